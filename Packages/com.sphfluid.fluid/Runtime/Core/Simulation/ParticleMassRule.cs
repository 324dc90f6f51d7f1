using System.Collections.Generic;

namespace SphFluid.Simulation
{
    /// <summary>
    /// An explicit particle mass sets the density the spawn lattice starts at: rho = m delta0. The Tait pressure
    /// grows with (rho / rho0)^gamma, so a mass far from the derived one m0 = rho0 / delta0 starts the fluid
    /// compressed (2.5 m0 gave a 69 966 % density error) or stretched into a gas that collapses (1e-9 kg).
    /// Allowed: 0 (derived) or m0 / F to m0 F with F = <see cref="SpeedOfSoundRule.SonicImpactDensityRatio"/>
    /// (1.24 at gamma = 7): the lattice then starts no more compressed, or stretched, than a Mach-1 impact would
    /// leave it, which the health check accepts.
    /// </summary>
    internal static class ParticleMassRule
    {
        /// <summary>m0, kg: the mass at which the spawn lattice sits at rest density (<see cref="DerivedParticleMass"/>).</summary>
        internal static double DerivedMass(FluidSceneDescription scene, PhaseDescription phase) =>
            DerivedParticleMass.Of(scene, phase);

        /// <summary>Needs valid settings and a valid rest density.</summary>
        internal static void Validate(FluidSceneDescription scene, PhaseDescription phase, string owner, string path, List<ValidationError> errors)
        {
            if (phase.ParticleMass == 0f) return;
            double derived = DerivedMass(scene, phase);
            double factor = SpeedOfSoundRule.SonicImpactDensityRatio(scene.Settings.Gamma);
            double min = derived / factor, max = derived * factor;
            if (phase.ParticleMass >= min && phase.ParticleMass <= max) return;
            errors.Add(new ValidationError(path + nameof(PhaseDescription.ParticleMass),
                owner, $"ParticleMass must be 0 (derived: {ValidationRules.Format(derived)} kg) or in [{ValidationRules.Format(min)}, {ValidationRules.Format(max)}] kg ({ValidationRules.Format(1.0 / factor)} to {ValidationRules.Format(factor)} times the derived mass for this spacing, support radius, rest density and Gamma) (was {ValidationRules.Format(phase.ParticleMass)})"));
        }
    }
}
