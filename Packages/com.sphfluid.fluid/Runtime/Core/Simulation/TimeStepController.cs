using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Adaptive time stepping, engine-free. The stable step is
    /// dt = min(cfl h / (c + vmax), 0.25 sqrt(h / amax), dt_capillary, MaxTimeStep)
    /// (CFL with the Tait speed of sound c = sqrt(k gamma / rho0_min); acceleration condition; capillary condition
    /// dt_capillary = sqrt(rho0_min s^3 / (2 pi sigma_max)) of Brackbill, Kothe &amp; Zemach 1992, "A continuum
    /// method for modeling surface tension", with the particle spacing s as the grid size). The explicit viscous force's
    /// limit dt_viscous = 1 / (nu_max Lambda_max) of its stiffest lattice wave (<see cref="ViscousStepLimit"/>) bounds the
    /// step only where the implicit solve a longer sub-step would need costs more than the explicit sub-steps it stands
    /// for (<see cref="ImplicitViscosity.PaysOff"/>: never under DFSPH; under WCSPH at OilAndWater's 2.9 limits, not at a
    /// pool's 7.6). nu_max is taken over
    /// every pair of phases, 2 min(mu_i, mu_j) / rho0_i bounding the shader's harmonic mixing, because a light
    /// phase next to a viscous one feels more than its own nu. vmax and amax come from the GPU's max-reduction,
    /// read back asynchronously and possibly a frame stale, so the controller uses the larger of the last two
    /// reports. With DFSPH (<see cref="PressureSolver.Dfsph"/>) the solves keep the density, so no speed of sound enters:
    /// dt = min(cfl h / max(vmax, u_walls, sqrt(g H)), dt_capillary, MaxTimeStep) (the velocity CFL of
    /// Bender &amp; Koschier 2017, sec. 6; the capillary limit stays because the tension is still explicit, the
    /// acceleration limit goes because the pressure acceleration is no longer explicit). u_walls is the
    /// fastest wall or obstacle (<see cref="BoundarySpeed"/>): a sphere started at 6.26 m/s through fluid at rest crossed
    /// 0.78 spacings a 5 ms sub-step, and the pool went unhealthy at 0.05 s (HardCaseTests' driven sphere under DFSPH).
    /// sqrt(g H) is <see cref="GravityWaveSpeed"/>, the speed of the longest gravity wave over the fluid's height H: a fluid
    /// at rest reports no speed, but each sub-step its solve rebuilds part of the hydrostatic pressure (the warm start
    /// carries half), whose imbalance over the step compresses the fluid by about g H dt^2 / s^2, a CFL number of the
    /// gravity wave squared. Measured on OilAndWater's slice at 1M particles' spacing (LockExchangeSliceProbe, 83
    /// spacings deep), calm at dt sqrt(g H) / h of 0.28 and 0.48 (1.39 and 2.38 ms), unhealthy within 0.05 s at 0.68 and
    /// 0.85 (3.33 and 4.17 ms); at half the depth calm at 0.48 (3.33 ms) and ringing at 0.60 (4.17 ms); the 250k slice
    /// calm at 0.53 (4.17 ms). The scenes' CFL number of 0.3 keeps a margin of 1.8 below that. WCSPH's CFL adds
    /// the speed of sound, which dominates any subsonic wall's speed. A frame of length T is covered by n = ceil(T / dt)
    /// sub-steps of T / n, capped at MaxSubsteps
    /// (then each sub-step is dt and the simulation runs slower than real time).
    /// </summary>
    public sealed class TimeStepController
    {
        readonly FluidSettings _settings;
        readonly double _viscousRowSum; // ImplicitViscosity.LatticeRowSum of the scene's lattice, 1/m^2
        float _reportedSpeed, _previousSpeed, _reportedAcceleration, _previousAcceleration;

        /// <summary>Speed of sound c = sqrt(k gamma / rho0_min), m/s.</summary>
        public float SpeedOfSound { get; }

        /// <summary>Largest kinematic viscosity nu = mu / rho0 over the phases, m^2/s.</summary>
        public float MaxKinematicViscosity { get; }

        /// <summary>The kinematic viscosity the discrete viscous operator acts with, m^2/s: <see cref="MaxKinematicViscosity"/>,
        /// twice it for the strain-rate stress, whose velocity part is Morris's pair term twice over (<see cref="ViscousStress"/>).
        /// It sets the explicit step limit and the implicit solve's conditioning.</summary>
        public double OperatorViscosity { get; }

        /// <summary>The viscous step limit, s (<see cref="ViscousStepLimit"/> at <see cref="OperatorViscosity"/>; infinite
        /// without viscosity).</summary>
        public double ViscousTimeStep { get; }

        /// <summary>The capillary step limit of surface tension, s (infinite without tension).</summary>
        public float CapillaryTimeStep { get; }

        /// <summary>The speed the next frame plans with (max of the last two reports), m/s.</summary>
        public float MaxSpeed => Math.Max(_reportedSpeed, _previousSpeed);

        /// <summary>The fastest point of any wall or obstacle now, m/s (the simulation sets it before each frame).</summary>
        public float BoundarySpeed { get; set; }

        /// <summary>sqrt(|g| H) for the fluid's height H (<see cref="SpawnLayout.Depth"/>), m/s: DFSPH's CFL plans with at
        /// least this speed (the simulation sets it from the spawn; 0 leaves the velocity CFL alone).</summary>
        public float GravityWaveSpeed { get; set; }

        /// <summary>The acceleration the next frame plans with (max of the last two reports), m/s^2.</summary>
        public float MaxAcceleration => Math.Max(_reportedAcceleration, _previousAcceleration);

        public TimeStepController(FluidSettings settings, float minRestDensity, float maxKinematicViscosity,
            float capillaryTimeStep = float.PositiveInfinity)
        {
            _settings = settings ?? throw new ArgumentNullException(nameof(settings));
            SpeedOfSound = SpeedOfSoundRule.SpeedOfSound(settings, minRestDensity);
            MaxKinematicViscosity = Math.Max(0f, maxKinematicViscosity);
            OperatorViscosity = (settings.ViscousStress == ViscousStress.StrainRate ? 2.0 : 1.0) * MaxKinematicViscosity;
            ViscousTimeStep = MaxKinematicViscosity > 0f && settings.ParticleSpacing > 0f && settings.SmoothingRadius > 0f
                ? ViscousStepLimit.For(settings.SmoothingKernel, settings.ParticleSpacing, settings.SmoothingRadius, OperatorViscosity)
                : double.PositiveInfinity;
            CapillaryTimeStep = capillaryTimeStep > 0f ? capillaryTimeStep : float.PositiveInfinity;
            _viscousRowSum = settings.ParticleSpacing > 0f && settings.SmoothingRadius > 0f
                ? ImplicitViscosity.LatticeRowSum(settings.SmoothingKernel, settings.ParticleSpacing, settings.SmoothingRadius)
                : 0.0;
            Reset();
        }

        public static TimeStepController ForScene(FluidSceneDescription scene)
        {
            float minRho = float.MaxValue, maxNu = 0f, maxTension = 0f;
            var phases = scene.Phases();
            foreach (var phase in phases)
            {
                minRho = Math.Min(minRho, phase.RestDensity);
                maxTension = Math.Max(maxTension, phase.SurfaceTension);
                maxNu = Math.Max(maxNu, phase.Viscosity / phase.RestDensity);
                // Across phases the shader's harmonic mean is at most twice the smaller viscosity.
                foreach (var other in phases)
                    if (other.Name != phase.Name)
                        maxNu = Math.Max(maxNu, 2f * Math.Min(phase.Viscosity, other.Viscosity) / phase.RestDensity);
            }
            if (minRho == float.MaxValue) minRho = 1000f;
            double s = scene.Settings.ParticleSpacing;
            float capillary = maxTension > 0f
                ? (float)Math.Sqrt(minRho * s * s * s / (2.0 * Math.PI * maxTension))
                : float.PositiveInfinity;
            var controller = new TimeStepController(scene.Settings, minRho, maxNu, capillary);
            float speed = 0f;
            foreach (var box in scene.SpawnBoxes) speed = Math.Max(speed, box.InitialVelocity.Length());
            controller.ReportMotion(speed, scene.Settings.Gravity.Length());
            return controller;
        }

        /// <summary>Forgets measured motion: plans as for fluid at rest under gravity.</summary>
        public void Reset()
        {
            float g = _settings.Gravity.Length();
            _reportedSpeed = _previousSpeed = 0f;
            _reportedAcceleration = _previousAcceleration = g;
        }

        /// <summary>Feeds the GPU's max speed (m/s) and max acceleration (m/s^2) of a recent step.
        /// Non-finite values (a broken simulation) are ignored rather than collapsing dt to zero.</summary>
        public void ReportMotion(float maxSpeed, float maxAcceleration)
        {
            if (!ValidationRules.IsFinite(maxSpeed) || !ValidationRules.IsFinite(maxAcceleration)) return;
            _previousSpeed = _reportedSpeed;
            _previousAcceleration = _reportedAcceleration;
            _reportedSpeed = Math.Max(0f, maxSpeed);
            _reportedAcceleration = Math.Max(0f, maxAcceleration);
        }

        /// <summary>The largest stable sub-step for the motion last reported, s, and the condition that set it.</summary>
        public float StableTimeStep(out string limit)
        {
            double h = _settings.SmoothingRadius;
            double dt = _settings.MaxTimeStep;
            limit = "max";
            bool divergenceFree = _settings.PressureSolver == PressureSolver.Dfsph;
            float moving = Math.Max(MaxSpeed, BoundarySpeed);
            float speed = divergenceFree ? Math.Max(moving, GravityWaveSpeed) : SpeedOfSound + MaxSpeed;
            double cfl = speed > 0f ? _settings.CflNumber * h / speed : double.PositiveInfinity;
            if (cfl < dt) { dt = cfl; limit = divergenceFree && GravityWaveSpeed > moving ? "gravity wave" : "cfl"; }
            if (MaxAcceleration > 0f && !divergenceFree)
            {
                double acc = 0.25 * Math.Sqrt(h / MaxAcceleration);
                if (acc < dt) { dt = acc; limit = "acceleration"; }
            }
            if (ViscousTimeStep < dt && !ImplicitViscosity.PaysOff(_settings.PressureSolver, dt, ViscousTimeStep, _viscousRowSum, OperatorViscosity))
            {
                dt = ViscousTimeStep;
                limit = "viscous";
            }
            if (CapillaryTimeStep < dt) { dt = CapillaryTimeStep; limit = "capillary"; }
            return (float)dt;
        }

        public float StableTimeStep() => StableTimeStep(out _);

        /// <summary>Sub-steps covering a frame of <paramref name="frameSeconds"/>.</summary>
        public StepReport PlanFrame(float frameSeconds)
        {
            float dt = StableTimeStep(out string limit);
            var solver = _settings.PressureSolver;
            if (!(frameSeconds > 0f) || float.IsInfinity(frameSeconds)) return new StepReport(0, 0f, 0f, false, dt, limit, solver);
            double needed = Math.Ceiling(frameSeconds / (double)dt - 1e-6);
            int n = (int)Math.Max(1.0, Math.Min(needed, int.MaxValue));
            if (n > _settings.MaxSubsteps)
            {
                n = _settings.MaxSubsteps;
                return new StepReport(n, dt, n * dt, true, dt, limit, solver);
            }
            float step = frameSeconds / n;
            return new StepReport(n, step, frameSeconds, false, dt, limit, solver);
        }
    }
}
