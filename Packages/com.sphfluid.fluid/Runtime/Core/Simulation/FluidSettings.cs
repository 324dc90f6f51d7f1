using System;
using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Solver settings of one fluid, each declared once: the field's initializer is its default and its
    /// <see cref="SettingAttribute"/> its range, unit, group and tooltip. Unity serializes the class inside the
    /// simulator component (the fields are public for that reason), the editor drawer shows the declarations as
    /// tooltips and ranges, the headless scene reader reads the same field names, and <see cref="Validate()"/> checks
    /// the declared ranges. Defaults suit a tank of about 0.5 m: spacing 2 cm, support 2 spacings, a speed of sound of
    /// about 20 m/s (ten times the speed of a 0.2 m dam break). Walls are boundary particles (BoundarySampling), so
    /// they need no settings here.
    /// </summary>
    [Serializable]
    public sealed class FluidSettings
    {
        public const float MinSupportRatio = 2f, MaxSupportRatio = 4f;

        /// <summary>The widest support, in spacings, the cubic spline is allowed: beyond it its particles pair up (Dehnen and
        /// Aly, "Improving convergence in SPH simulations without pairing instability") and the walls no longer hold them.
        /// Measured in a resting tank (0.4 x 0.3 x 0.2 m, s = 0.025 m, 3 s): the clamp caught 0 particles at 2 and 2.25
        /// spacings, 208 at 2.5 and 23 515 at 3; Wendland C2 caught 0 at 2.5 and 3.</summary>
        public const float MaxCubicSplineSupportRatio = 2.25f;

        /// <summary>The widest support, in spacings, DFSPH takes, with Wendland C2 only (the cubic spline: 2 spacings). Above 2
        /// spacings the solve also needs <see cref="SolverRelaxation"/> within <see cref="SphFluid.Simulation.SolverRelaxation.StableLimit"/>.
        /// Before the wall particles became unknowns of the solves, DFSPH let the fluid through the walls at any wider support
        /// (the resting tank, 0.1 % tolerance, 1 s: with the cubic spline 943 particles caught by the clamp at 2.25 spacings;
        /// with Wendland C2 583 at 2.5, 10 143 at 3 in 2 s and 2 766 at 4). After it, two things held Wendland C2 at 2.85
        /// spacings back: the full Jacobi step diverges within 0.05 s (the lattice's stiffest wave has lambda_max 5.4), and
        /// in the oil-and-water container the walls, weighed at the lattice's rest number density instead of the fluid's
        /// (SphBoundary.hlsl's WallWeight), asked for a density no motion of the fluid could give and the first solve lifted
        /// the whole fluid (0.70 m/s after one 4 ms sub-step). With the walls weighed at the fluid's rest and the step at
        /// 0.3, the oil-and-water scene runs with no clamp hit (Headless/docs/known-limits.md). 2.9 is the top of the
        /// band where Wendland C2's lattice is stable (<see cref="SmoothingKernel"/>). Until the wall particles weighed
        /// their lattice cells (BoundarySampling) a DFSPH tank at rest with Wendland C2 at 2 to 2.6 spacings lifted its
        /// fluid within 0.1 s; since, the resting tank holds at 2, 2.3 and 2.6 spacings (relaxed to 0.3), its lattice
        /// creeping where LatticeStability says it grows.</summary>
        public const float MaxDivergenceFreeSupportRatio = 2.9f;

        const string Particles = "Particles", Pressure = "Pressure", Forces = "Forces", Stepping = "Time stepping";

        [Setting(Particles, 0.001, 1, "m", "Lattice spacing s of spawned particles: the resolution. Halving it gives 8 times the particles.")]
        public float ParticleSpacing = 0.02f;

        // 2 spacings by default: the cubic spline then recovers a linear pressure gradient to 2 % on the lattice at the
        // lowest cost (SmoothingKernels.LatticeGradientReproduction).
        [Setting(Particles, 0.002, 4, "m", "Kernel support radius H (the neighbour grid's cells are H/2), 2 to 4 particle spacings (the cubic spline up to 2.25; DFSPH: the cubic spline at 2, Wendland C2 up to 2.9): wider is smoother and slower.")]
        public float SmoothingRadius = 0.04f;

        [Setting(Particles, 0, 1, "", "Kernel family of every SPH sum: 0 = CubicSpline (cheapest; support 2 to 2.25 spacings; a fluid at rest keeps creeping), 1 = WendlandC2 (no particle pairing; at 2.8 to 2.9 spacings its particle lattice is stable under pressure, so with DeltaSph a fluid at rest comes to rest, at about 3 times the neighbours).")]
        public KernelFamily SmoothingKernel = KernelFamily.CubicSpline;

        [Setting(Particles, 1, 16777216, "", "Most particles the spawn boxes may hold together.")]
        public int MaxParticles = 262144;

        [Setting(Pressure, 0, 1, "", "How pressure is computed: 0 = WCSPH (Tait equation of state, one pass, step bounded by the speed of sound), 1 = DFSPH (iterative incompressible solves to a tolerance, step bounded by the flow speed).")]
        public PressureSolver PressureSolver = PressureSolver.Wcsph;

        [Setting(Pressure, 0.001, 10, "%", "DFSPH: largest average density error of any phase that the constant-density solve accepts.")]
        public float DensityTolerance = 0.1f;

        [Setting(Pressure, 0.01, 1000, "%/s", "DFSPH: largest average rate of density change of any phase that the divergence-free solve accepts at sub-steps of 1/240 s and longer; a shorter sub-step accepts the density change a sub-step that this rate allows over 1/240 s (DivergenceSolveTolerance).")]
        public float DivergenceTolerance = 10f;

        [Setting(Pressure, 1, 1000, "", "DFSPH: most iterations of each solve per sub-step.")]
        public int MaxSolverIterations = 100;

        // Jacobi by default: every DFSPH figure of the shipped scenes was measured with it. Chebyshev took OilAndWater's
        // constant-density solve from 41 to 7 iterations a sub-step at 25 900 particles
        // (Headless/docs/known-limits.md).
        [Setting(Pressure, 0, 1, "", "DFSPH: how each solve iterates: 0 = Jacobi (Bender and Koschier's relaxed step, compression only; iterations grow with the square of the fluid's depth in particle spacings), 1 = Chebyshev (the same step accelerated over the operator's eigenvalue bounds, with pressure taken back where a step overshoots; iterations grow with the depth; the constant-density solve is accelerated only at tolerances below a sixtieth of a per cent per spacing of the fluid's depth, and takes Jacobi steps above).")]
        public SolverIteration SolverIteration = SolverIteration.Jacobi;

        // 1 by default, the papers' step and the cheapest. At 0.355 the resting tank's largest compression fell from 0.56 %
        // to 0.23 % and its divergence error from 5.6 to 0.55 %/s at 2.4 times the wall time (21.6 constant-density
        // iterations per sub-step against 6.6), and, before the walls counted at the fluid's rest number density, DFSPH's oil
        // and water with the cubic spline left 15 % of its floor layer oil at 4.5 s against 21.9 % at 6 s (SolverRelaxation
        // says why). Above 2 spacings validation keeps it within SolverRelaxation.StableLimit; OilAndWater runs 0.3.
        [Setting(Pressure, 0.05, 1, "", "DFSPH: fraction of each Jacobi step the fluid particles take. 1 = Bender and Koschier's full step, which overshoots the lattice's stiffest pressure waves; at or below 1 / lambda_max (0.355 for the cubic spline at 2 spacings, 0.384 for Wendland C2) none overshoots, at about 1 / value times the iterations. Above 2 spacings (Wendland C2) at most 2 / lambda_max (0.372 at 2.85), beyond which the stiffest wave grows.")]
        public float SolverRelaxation = 1f;

        // The scene narrows the stiffness: c must exceed the scene's fastest speed and stay within 100 times it
        // (SpeedOfSoundRule).
        [Setting(Pressure, 1, 1e9, "Pa", "WCSPH: Tait stiffness k; speed of sound c = sqrt(k gamma / rho0). Stiffer compresses less but takes shorter steps.")]
        public float Stiffness = 50000f;

        [Setting(Pressure, 1, 10, "", "WCSPH: Tait exponent gamma (7 for water).")]
        public float Gamma = 7f;

        [Setting(Pressure, 0, 1, "", "WCSPH: how each particle's density is found: 0 = Summation (the kernel sum over its neighbours, every sub-step), 1 = DeltaSph (carried by the particle, integrated with the continuity equation plus delta-SPH density diffusion, started hydrostatic).")]
        public WcsphDensity WcsphDensity = WcsphDensity.Summation;

        // A fall along the container's diagonal must also stay below the speed of sound (SpeedOfSoundRule).
        [Setting(Forces, 0, 1000, "m/s^2", "Gravitational acceleration, in world space.")]
        public SettingVector Gravity = new Vector3(0f, -9.81f, 0f);

        // Laplacian by default: every shipped scene and GPU figure was measured with it, and its phases' viscosities are too
        // low for the rotation it brakes to show. A spinning block at 10 Pa s keeps 0.17 of its angular momentum under it,
        // and all of it to within 4.5e-4 under the strain rate (SpinningBlockProbe).
        [Setting(Forces, 0, 1, "", "The physical viscosity's stress: 0 = Laplacian (mu times the Laplacian of the velocity, Morris et al. 1997: cheapest, but it brakes a rigidly spinning liquid), 1 = StrainRate (the Newtonian stress 2 mu D: a rigid rotation keeps its spin; one more pass each sub-step and half the explicit viscous step).")]
        public ViscousStress ViscousStress = ViscousStress.Laplacian;

        // Applied every sub-step, it pulls each particle towards its neighbours' mean velocity by epsilon per
        // sub-step: kept small (0.02) or it damps buoyancy-driven flow (oil rising through water) with the noise.
        [Setting(Forces, 0, 1, "", "XSPH velocity smoothing epsilon: the share of each particle's velocity difference from its neighbours' taken every sub-step, so shorter sub-steps damp the liquid more; 0 turns the pass off.")]
        public float XsphEpsilon = 0.02f;

        [Setting(Forces, 0, 1, "", "Monaghan's artificial viscosity alpha: damps the acoustic noise of approaching particle pairs; 0 turns it off.")]
        public float ArtificialViscosity = 0.02f;

        // Off by default: measured at A = 2 it did not settle a resting tank (65 mm/s between 1 and 2 s against 38 mm/s
        // without, and dp/dy 4.4 % off rho0 g against 2.3 %); in 3 s of the shipped scenes it took the dam break's clamp
        // hits from 154 to 0 (that scene turns it on) but raised oil-and-water's from 27 to 67 and the sphere wake's
        // from 146 to 197.
        [Setting(Forces, 0, 10, "", "Particle shifting coefficient A (Lind et al. 2012): each sub-step a particle moves by -A h |v| dt grad C towards a uniform distribution, along but not across free surfaces and phase interfaces; 0 turns the pass off.")]
        public float ParticleShifting;

        [Setting(Forces, 0, 1000, "1/s", "Global velocity damping; 0 = none.")]
        public float VelocityDamping;

        // The floors of CflNumber and MaxTimeStep keep a run moving: at 1e-30 either one left every frame a few 1e-29 s
        // further on, and a run of 0.02 simulated seconds had not ended after three minutes.
        [Setting(Stepping, 0.01, 1, "", "Courant number of the CFL condition: the fraction of a support radius a particle may travel per sub-step.")]
        public float CflNumber = 0.3f;

        [Setting(Stepping, 1, 1000, "", "Most sub-steps per frame; beyond it the simulation runs slower than real time.")]
        public int MaxSubsteps = 32;

        [Setting(Stepping, 1e-5, 0.1, "s", "Largest sub-step.")]
        public float MaxTimeStep = 0.005f;

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
            bool spacingOk = SettingRules.Validate(this, errors, owner, path, nameof(ParticleSpacing));
            foreach (var field in SettingRules.Declared(typeof(FluidSettings)))
                if (field.Field.Name != nameof(ParticleSpacing)) SettingRules.Validate(this, errors, owner, path, field.Field.Name);
            if (spacingOk && !errors.Exists(e => e.Field == path + nameof(SmoothingRadius)))
            {
                if (PressureSolver == PressureSolver.Dfsph)
                    ValidateDivergenceFreeSupport(errors, owner, path);
                else if (SmoothingKernel == KernelFamily.CubicSpline)
                    ValidationRules.InRange(errors, owner, path, nameof(SmoothingRadius), SmoothingRadius,
                        MinSupportRatio * ParticleSpacing, MaxCubicSplineSupportRatio * ParticleSpacing,
                        "m (2 to 2.25 particle spacings with the CubicSpline kernel; up to 4 with WendlandC2)");
                else
                    ValidationRules.InRange(errors, owner, path, nameof(SmoothingRadius), SmoothingRadius,
                        MinSupportRatio * ParticleSpacing, MaxSupportRatio * ParticleSpacing, "m (2 to 4 particle spacings)");
            }
        }

        /// <summary>DFSPH's support (<see cref="MaxDivergenceFreeSupportRatio"/>) and, above 2 spacings, its relaxation: at 2
        /// spacings the tests measure the papers' full step, whose overshoot of the stiffest wave (lambda_max 2.82 for the cubic
        /// spline) the compression-only solve cuts short; wider, lambda_max grows (5.4 for Wendland C2 at 2.85) and the full
        /// step diverges, so the step must keep omega lambda_max within 2, where every lattice wave's residual shrinks.</summary>
        void ValidateDivergenceFreeSupport(List<ValidationError> errors, string owner, string path)
        {
            bool cubic = SmoothingKernel == KernelFamily.CubicSpline;
            if (!ValidationRules.InRange(errors, owner, path, nameof(SmoothingRadius), SmoothingRadius,
                    MinSupportRatio * ParticleSpacing, (cubic ? MinSupportRatio : MaxDivergenceFreeSupportRatio) * ParticleSpacing,
                    cubic ? "m (2 particle spacings for the CubicSpline kernel with the Dfsph pressure solver; 2 to 2.9 with WendlandC2)"
                          : "m (2 to 2.9 particle spacings for the WendlandC2 kernel with the Dfsph pressure solver)"))
                return;
            if (SmoothingRadius <= MinSupportRatio * ParticleSpacing * (1f + 1e-4f) || errors.Exists(e => e.Field == path + nameof(SolverRelaxation)))
                return;
            float limit = (float)global::SphFluid.Simulation.SolverRelaxation.StableLimit(SmoothingKernel, ParticleSpacing, SmoothingRadius);
            ValidationRules.InRange(errors, owner, path, nameof(SolverRelaxation), SolverRelaxation, 0.05f, Math.Max(0.05f, limit),
                string.Format(System.Globalization.CultureInfo.InvariantCulture,
                    "(2 / lambda_max of the Dfsph solve's Jacobi step with {0} at {1:G3} particle spacings: beyond it the lattice's stiffest pressure wave grows)",
                    SmoothingKernel, SmoothingRadius / ParticleSpacing));
        }
    }
}
