using System;
using System.Collections.Generic;
using System.Globalization;

namespace SphFluid.Simulation
{
    /// <summary>
    /// What one liquid is, as the scene describes it. Spawn boxes that name the same phase share one row of the GPU phase
    /// table (<see cref="PhaseProperties"/>). Each value is declared once, like <see cref="FluidSettings"/>: the field's
    /// initializer is its default and its <see cref="SettingAttribute"/> its range, unit, group and tooltip. Unity
    /// serializes the class inside the SpawnBox component (through <see cref="FluidBlock.Phase"/>); the editor
    /// drawer, the validation, the headless scene reader and the README's table read the declarations.
    /// </summary>
    [Serializable]
    public sealed class PhaseDescription
    {
        const string Liquid = "Phase", Look = "Look";

        [Setting(Liquid, 1, 256, "", "Phase name; boxes with the same name are one liquid and must agree on every phase value. Names must differ by more than letter case.")]
        public string Name = "Water";

        [Setting(Liquid, 1, 100000, "kg/m^3", "Rest density rho0 (water 1000, oil 900).")]
        public float RestDensity = 1000f;

        [Setting(Liquid, 0, 1000, "Pa s", "Dynamic viscosity mu (water 0.001; the simulation needs more, e.g. 0.05).")]
        public float Viscosity = 0.001f;

        // The scene narrows an explicit mass further (ParticleMassRule).
        [Setting(Liquid, 0, 1e6, "kg", "Mass of one particle; 0 = derived so that the spawn lattice sits exactly at rest density. An explicit mass must lie within a factor (1 + gamma/2)^(1/gamma) of the derived one.")]
        public float ParticleMass;

        [Setting(Liquid, 0, 10, "N/m", "Surface tension sigma against air (water 0.072, oil about 0.03); an interface between two liquids carries both. 0 = off.")]
        public float SurfaceTension;

        // Linear, as the phase table and the shaders use it. Unity's inspector shows and picks sRGB, as for any colour,
        // and converts at its edge (the package's SettingColor drawer applies Color.linear / Color.gamma).
        [Setting(Look, 0, 1, "", "Tint and opacity, stored as linear RGBA (the inspector shows and picks it as sRGB).")]
        public SettingColor Color = new SettingColor(0.2f, 0.45f, 0.9f, 0.8f);

        [Setting(Look, 0, 1, "", "Schlick reflectance at normal incidence, ((n - 1) / (n + 1))^2: water 0.02, oil 0.035.")]
        public float FresnelF0 = 0.02f;

        [Setting(Look, 0, 10000, "1/m", "Beer-Lambert absorption coefficient of the tint.")]
        public float Absorption = 2f;

        public PhaseDescription() { }

        public PhaseDescription(string name, float restDensity, float viscosity)
        {
            Name = name;
            RestDensity = restDensity;
            Viscosity = viscosity;
        }

        public PhaseDescription Clone() => (PhaseDescription)MemberwiseClone();

        /// <summary>Same physical and optical definition, every declared value equal (used to detect conflicting boxes
        /// of one phase).</summary>
        public bool SameDefinition(PhaseDescription other) => other != null && DifferencesFrom(other).Count == 0;

        /// <summary>Each declared value in which <paramref name="other"/> differs, in declaration order, worded with this
        /// phase's value first: "RestDensity (1000 against 998 kg/m^3)". A value printed alone says nothing of which of
        /// the others differs (Color, Absorption), so a refusal of two boxes lists these.</summary>
        public List<string> DifferencesFrom(PhaseDescription other)
        {
            var differences = new List<string>();
            foreach (var declared in SettingRules.Declared(typeof(PhaseDescription)))
            {
                object mine = declared.Field.GetValue(this), theirs = declared.Field.GetValue(other);
                if (Equals(mine, theirs)) continue;
                differences.Add($"{declared.Field.Name} ({Shown(mine)} against {Shown(theirs)}{ValidationRules.Unit(declared.Declaration.Unit)})");
            }
            return differences;
        }

        static string Shown(object value) => value is float f ? ValidationRules.Format(f) : Convert.ToString(value, CultureInfo.InvariantCulture);

        public override string ToString() =>
            $"{Name} (rho0 {RestDensity} kg/m^3, mu {Viscosity} Pa s, sigma {SurfaceTension} N/m)";
    }
}
