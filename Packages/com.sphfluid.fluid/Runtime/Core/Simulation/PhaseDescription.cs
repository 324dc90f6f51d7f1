using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// What one liquid is, as the scene describes it. Spawn boxes that name the same phase share one
    /// row of the GPU phase table (<see cref="PhaseProperties"/>).
    /// </summary>
    public sealed class PhaseDescription
    {
        public const float MinRestDensity = 1f, MaxRestDensity = 100000f;
        public const float MaxViscosity = 1000f;
        public const float MaxSurfaceTension = 10f;
        public const float MaxAbsorption = 10000f;

        /// <summary>Phase name; boxes with the same name share one phase.</summary>
        public string Name { get; set; } = "Water";

        /// <summary>Rest density rho0, kg/m^3, in [1, 100000].</summary>
        public float RestDensity { get; set; } = 1000f;

        /// <summary>Dynamic viscosity mu, Pa·s, in [0, 1000].</summary>
        public float Viscosity { get; set; } = 0.001f;

        /// <summary>Mass of one particle, kg; 0 = derived so that the spawn lattice sits exactly at rest density.
        /// Otherwise within a factor (1 + gamma / 2)^(1 / gamma) of the derived mass (<see cref="ParticleMassRule"/>).</summary>
        public float ParticleMass { get; set; }

        /// <summary>Surface tension coefficient gamma, N/m, in [0, 10]; 0 = none.</summary>
        public float SurfaceTension { get; set; }

        /// <summary>Linear RGBA tint for rendering and snapshots.</summary>
        public Vector4 Color { get; set; } = new Vector4(0.2f, 0.45f, 0.9f, 0.8f);

        /// <summary>Schlick reflectance at normal incidence, in [0, 1].</summary>
        public float FresnelF0 { get; set; } = 0.02f;

        /// <summary>Beer-Lambert absorption coefficient, 1/m, in [0, 10000].</summary>
        public float Absorption { get; set; } = 2f;

        public PhaseDescription() { }

        public PhaseDescription(string name, float restDensity, float viscosity)
        {
            Name = name;
            RestDensity = restDensity;
            Viscosity = viscosity;
        }

        public PhaseDescription Clone() => (PhaseDescription)MemberwiseClone();

        /// <summary>Same physical and optical definition (used to detect conflicting boxes of one phase).</summary>
        public bool SameDefinition(PhaseDescription other)
        {
            return other != null && Name == other.Name && RestDensity == other.RestDensity
                && Viscosity == other.Viscosity && ParticleMass == other.ParticleMass
                && SurfaceTension == other.SurfaceTension && Color == other.Color
                && FresnelF0 == other.FresnelF0 && Absorption == other.Absorption;
        }

        public override string ToString() =>
            $"{Name} (rho0 {RestDensity} kg/m^3, mu {Viscosity} Pa s, gamma {SurfaceTension} N/m)";
    }
}
