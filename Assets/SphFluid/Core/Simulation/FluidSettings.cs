using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Solver settings of one fluid (the SPH component's inspector). Defaults suit a tank of about
    /// 0.5 m: spacing 2 cm, support 2 spacings, a speed of sound of about 20 m/s (ten times the speed
    /// of a 0.2 m dam break). Walls are boundary particles (BoundarySampling), so they need no settings here.
    /// </summary>
    public sealed class FluidSettings
    {
        public const float MinSupportRatio = 2f, MaxSupportRatio = 4f;

        /// <summary>Lattice spacing s of spawned particles, m, in [0.001, 1].</summary>
        public float ParticleSpacing { get; set; } = 0.02f;

        /// <summary>Kernel support radius H (= grid cell size), m; H / s must be in [2, 4]. 2 spacings by default:
        /// the cubic spline then recovers a linear pressure gradient to 2 % on the lattice at the lowest cost
        /// (SmoothingKernels.LatticeGradientReproduction).</summary>
        public float SmoothingRadius { get; set; } = 0.04f;

        /// <summary>How pressure is computed: Tait equation of state (WCSPH) or iterative incompressible solves (DFSPH).</summary>
        public PressureSolver PressureSolver { get; set; } = PressureSolver.Wcsph;

        /// <summary>DFSPH: largest average density error the constant-density solve accepts, %, in [0.001, 10].</summary>
        public float DensityTolerance { get; set; } = 0.1f;

        /// <summary>DFSPH: largest average rate of density change the divergence-free solve accepts, %/s, in [0.01, 1000].</summary>
        public float DivergenceTolerance { get; set; } = 10f;

        /// <summary>DFSPH: most iterations of each solve per sub-step, in [1, 1000].</summary>
        public int MaxSolverIterations { get; set; } = 100;

        /// <summary>Tait stiffness k, Pa, in [1, 1e9]; speed of sound c = sqrt(k gamma / rho0). The scene narrows it:
        /// c must exceed the scene's fastest speed and stay within 100 times it (<see cref="SpeedOfSoundRule"/>).</summary>
        public float Stiffness { get; set; } = 50000f;

        /// <summary>Tait exponent gamma, in [1, 10].</summary>
        public float Gamma { get; set; } = 7f;

        /// <summary>Gravitational acceleration, m/s^2 (|g| up to 1000, and a fall along the container's diagonal
        /// must stay below the speed of sound: <see cref="SpeedOfSoundRule"/>).</summary>
        public Vector3 Gravity { get; set; } = new Vector3(0f, -9.81f, 0f);

        /// <summary>XSPH velocity smoothing epsilon, in [0, 1]; 0 turns the pass off. Applied to the velocity every
        /// sub-step, it pulls each particle towards its neighbours' mean velocity by epsilon per sub-step: keep it
        /// small (0.02) or it damps buoyancy-driven flow (oil rising through water) along with the noise.</summary>
        public float XsphEpsilon { get; set; } = 0.02f;

        /// <summary>Monaghan's artificial viscosity alpha, in [0, 1]: damps the acoustic noise of the weakly
        /// compressible fluid on approaching particle pairs (SphViscosity.hlsl). 0 turns it off.</summary>
        public float ArtificialViscosity { get; set; } = 0.02f;

        /// <summary>Particle shifting coefficient A, in [0, 10]; 0 turns the pass off. Each sub-step a particle moves by
        /// -A h |v| dt gradC down its concentration gradient (Lind et al. 2012; ParticleShifting.hlsl): it spreads
        /// particles back towards a uniform distribution, along (not across) free surfaces and phase interfaces.
        /// Off by default: measured at A = 2, it did not settle a resting tank (65 mm/s between 1 and 2 s against 38 mm/s
        /// without, and dp/dy 4.4 % off rho0 g against 2.3 %); in 3 s of the shipped scenes it took the dam break's clamp
        /// hits from 154 to 0 (its scene turns it on) but raised oil-and-water's from 27 to 67 and the sphere wake's from 146 to 197.</summary>
        public float ParticleShifting { get; set; } = DefaultParticleShifting;

        /// <summary>Default <see cref="ParticleShifting"/>.</summary>
        public const float DefaultParticleShifting = 0f;

        /// <summary>Global velocity damping, 1/s, in [0, 1000]; 0 = none.</summary>
        public float VelocityDamping { get; set; }

        /// <summary>Courant number of the CFL condition, in (0, 1].</summary>
        public float CflNumber { get; set; } = 0.3f;

        /// <summary>Most sub-steps per frame, in [1, 1000]; beyond it the simulation runs slower than real time.</summary>
        public int MaxSubsteps { get; set; } = 32;

        /// <summary>Largest sub-step, s, in (0, 0.1].</summary>
        public float MaxTimeStep { get; set; } = 0.005f;

        /// <summary>Most particles the scene may spawn, in [1, 16777216].</summary>
        public int MaxParticles { get; set; } = 262144;

        public FluidSettings Clone() => (FluidSettings)MemberwiseClone();

        public IReadOnlyList<ValidationError> Validate()
        {
            var errors = new List<ValidationError>();
            Validate(errors, "Settings.");
            return errors;
        }

        internal void Validate(List<ValidationError> errors, string path)
        {
            const string owner = "FluidSettings";
            bool spacingOk = ValidationRules.InRange(errors, owner, path, nameof(ParticleSpacing), ParticleSpacing, 0.001f, 1f, "m");
            if (spacingOk)
            {
                ValidationRules.InRange(errors, owner, path, nameof(SmoothingRadius), SmoothingRadius,
                    MinSupportRatio * ParticleSpacing, MaxSupportRatio * ParticleSpacing, "m (2 to 4 particle spacings)");
            }
            ValidationRules.InRange(errors, owner, path, nameof(Stiffness), Stiffness, 1f, 1e9f, "Pa");
            ValidationRules.InRange(errors, owner, path, nameof(DensityTolerance), DensityTolerance, 0.001f, 10f, "%");
            ValidationRules.InRange(errors, owner, path, nameof(DivergenceTolerance), DivergenceTolerance, 0.01f, 1000f, "%/s");
            ValidationRules.InRange(errors, owner, path, nameof(MaxSolverIterations), MaxSolverIterations, 1, 1000, "");
            ValidationRules.InRange(errors, owner, path, nameof(Gamma), Gamma, 1f, 10f, "");
            ValidationRules.Finite(errors, owner, path, nameof(Gravity), Gravity, 1000f, "m/s^2");
            ValidationRules.InRange(errors, owner, path, nameof(XsphEpsilon), XsphEpsilon, 0f, 1f, "");
            ValidationRules.InRange(errors, owner, path, nameof(ArtificialViscosity), ArtificialViscosity, 0f, 1f, "");
            ValidationRules.InRange(errors, owner, path, nameof(ParticleShifting), ParticleShifting, 0f, 10f, "");
            ValidationRules.InRange(errors, owner, path, nameof(VelocityDamping), VelocityDamping, 0f, 1000f, "1/s");
            ValidationRules.Positive(errors, owner, path, nameof(CflNumber), CflNumber, 1f, "");
            ValidationRules.InRange(errors, owner, path, nameof(MaxSubsteps), MaxSubsteps, 1, 1000, "");
            ValidationRules.Positive(errors, owner, path, nameof(MaxTimeStep), MaxTimeStep, 0.1f, "s");
            ValidationRules.InRange(errors, owner, path, nameof(MaxParticles), MaxParticles, 1, 16777216, "");
        }
    }
}
