using System;
using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Decides whether a simulated state is still a liquid the scene could have produced, from bounds derived
    /// from the scene itself. Engine-free: the headless runner and the Unity simulator ask the same questions and
    /// print the same message. A state is unhealthy, in this order, when
    /// <list type="number">
    /// <item>a particle is NaN or infinite, one is outside the container, or the count changed;</item>
    /// <item>a particle is faster than the speed bound
    ///   V = <see cref="SpeedMargin"/> (sqrt(2 |g| D) + v_spawn + 2 v_wall + 2 v_obstacle + v_capillary + c e0) + <see cref="AcousticFraction"/> c,
    ///   where D is the container's diagonal (the longest fall in any orientation), v_spawn the fastest initial
    ///   velocity, v_wall the fastest wall point of the moving container (|V| + |w| D / 2) and v_obstacle the
    ///   fastest sphere, both the largest seen so far (a wall can at most double the speed of what it hits),
    ///   v_capillary the fastest a surface can pull its liquid (<see cref="CapillarySpeed"/>), c the highest
    ///   speed of sound of the phases and e0 the largest compression of the first state checked (c e0, the
    ///   <see cref="ReleaseSpeed"/>, is what that compression sets moving when released), and the last term the
    ///   acoustic noise of a weakly compressible liquid with a 1 % density error (validation keeps c / 100 below the
    ///   scene's own speeds);</item>
    /// <item>a phase's mean compression max(0, rho / rho0 - 1) exceeds <see cref="MeanCompressionBound"/>, what a
    ///   Mach-1 impact leaves ((1 + gamma / 2)^(1 / gamma) - 1, 24 % at gamma = 7: validation keeps every scene
    ///   subsonic), or one particle's exceeds twice that or the first state's own, <see cref="MaxCompressionBound"/>;</item>
    /// <item>with no moving wall or obstacle seen, the mechanical energy (kinetic plus gravitational,
    ///   <see cref="FluidEnergy"/>) grew above its first value by more than M (<see cref="EnergyAllowance"/> |g| D
    ///   + (c e0)^2 / 2) + E_surface: nothing else can feed it but the elastic energy the first state stores, which
    ///   the second term bounds from above (the linearised Tait energy c^2 e^2 / 2 per kilogram), and the surface energy of the spawn
    ///   (<see cref="SurfaceEnergy"/>); the first term absorbs integration error. With a driver, the speed bound caps
    ///   the energy instead.</item>
    /// </list>
    /// </summary>
    public sealed class HealthCheck
    {
        /// <summary>Factor on the fastest physical speed of the scene.</summary>
        public const float SpeedMargin = 2f;

        /// <summary>Allowed acoustic speed as a fraction of the speed of sound.</summary>
        public const float AcousticFraction = 0.01f;

        /// <summary>Energy growth allowed for integration error, as a fraction of the potential energy M |g| D.</summary>
        public const double EnergyAllowance = 0.05;

        readonly IReadOnlyList<PhaseProperties> _phases;
        readonly IReadOnlyList<PhaseDescription> _phaseNames;
        readonly Vector3 _gravity;
        readonly int _spawned;
        readonly double _totalMass;
        double _firstEnergy = double.NaN;
        bool _checkedFirst;

        /// <summary>Bounds for <paramref name="scene"/> (validated), whose particles the simulation spawned:
        /// <paramref name="spawnedCount"/> of them (FluidSimulation.ParticleCount: lattice points inside obstacles are not
        /// spawned), or by default the count its boxes spawn.</summary>
        public HealthCheck(FluidSceneDescription scene, int spawnedCount = -1)
        {
            if (scene == null) throw new ArgumentNullException(nameof(scene));
            _phaseNames = scene.Phases();
            _phases = scene.BuildPhaseTable();
            _gravity = scene.Settings.Gravity;
            _spawned = spawnedCount >= 0 ? spawnedCount : SpawnLayout.TotalCount(scene);
            for (int k = 0; k < _phaseNames.Count; k++)
            {
                long count = 0;
                foreach (var box in scene.SpawnBoxes)
                    if (box.Phase.Name == _phaseNames[k].Name) count += SpawnLayout.SpawnedCount(scene, box);
                _totalMass += count * (double)_phases[k].ParticleMass;
            }

            ContainerDiagonal = scene.Container.Size.Length();
            FreeFallSpeed = (float)Math.Sqrt(2.0 * scene.Settings.Gravity.Length() * ContainerDiagonal);
            foreach (var box in scene.SpawnBoxes) SpawnSpeed = Math.Max(SpawnSpeed, box.InitialVelocity.Length());
            foreach (var phase in _phaseNames)
            {
                SpeedOfSound = Math.Max(SpeedOfSound, SpeedOfSoundRule.SpeedOfSound(scene.Settings, phase.RestDensity));
                if (phase.SurfaceTension > 0f)
                    CapillarySpeed = Math.Max(CapillarySpeed,
                        (float)Math.Sqrt(2.0 * phase.SurfaceTension / (phase.RestDensity * (double)scene.Settings.ParticleSpacing)));
            }
            foreach (var box in scene.SpawnBoxes)
            {
                var size = box.Size;
                SurfaceEnergy += box.Phase.SurfaceTension * 2.0 * ((double)size.X * size.Y + (double)size.Y * size.Z + (double)size.Z * size.X);
            }
            MeanCompressionBound = (float)(SpeedOfSoundRule.SonicImpactDensityRatio(scene.Settings.Gamma) - 1.0);
            ObserveDrivers(scene.Container, scene.Obstacles);
        }

        /// <summary>Mean compression allowed in any phase: that of a Mach-1 impact.</summary>
        public float MeanCompressionBound { get; }

        /// <summary>Compression allowed for any one particle: twice the mean bound, or the first checked state's largest
        /// if that is more. A summation-density spawn jittered by 0.3 spacings or more crowds single particles past twice the
        /// mean bound (Splash at 0.3 spacings: 51 % against 47.9 %) with nothing having struck them, and was stopped
        /// as unhealthy at t = 0.</summary>
        public float MaxCompressionBound => Math.Max(2f * MeanCompressionBound, FirstCompression);

        /// <summary>sqrt(2 |g| D): the speed of a fall along the container's diagonal D, m/s.</summary>
        public float FreeFallSpeed { get; }

        /// <summary>The container's diagonal D, m.</summary>
        public float ContainerDiagonal { get; }

        /// <summary>Fastest initial velocity of the spawn boxes, m/s.</summary>
        public float SpawnSpeed { get; }

        /// <summary>Fastest container wall point seen so far, m/s.</summary>
        public float WallSpeed { get; private set; }

        /// <summary>Fastest sphere obstacle seen so far, m/s.</summary>
        public float ObstacleSpeed { get; private set; }

        /// <summary>Highest speed of sound over the phases (the lightest phase's), m/s.</summary>
        public float SpeedOfSound { get; }

        /// <summary>The fastest a surface can pull its liquid, m/s: the Taylor-Culick speed sqrt(2 sigma / (rho0 s)) at which
        /// the rim of a sheet one particle spacing s thick retracts (Culick 1960, "Comments on a ruptured soap film"),
        /// the thinnest liquid the particles resolve; the highest over the phases with a surface tension, 0 without.
        /// In zero gravity nothing else bounds a droplet's motion: a cube of water at its own 0.072 N/m rounding up
        /// reached 0.14 m/s at 5 mm spacings, against a bound of 1 % of its speed of sound, 0.037 m/s.</summary>
        public float CapillarySpeed { get; }

        /// <summary>The surface energy of the spawn boxes, J: each box's surface tension times its faces' area. Motion can
        /// release at most this (a surface's area cannot fall below zero, and the particles' force makes its sigma within
        /// 26 % at the spacings measured), and in zero gravity nothing else lets a droplet's mechanical energy grow.</summary>
        public double SurfaceEnergy { get; }

        /// <summary>c e0, m/s: the speed at which the first checked state's largest compression e0 sets its liquid moving
        /// when released (a sound wave that relieves a compression e moves the liquid at c e), 0 before the first check.
        /// Under gravity the free fall's term dwarfs it, but in zero gravity nothing else bounds it: DamBreak's spawn,
        /// jittered by a twentieth of a spacing, which compresses single particles by up to 5.5 %, moved at 0.34 m/s
        /// within two frames, past the 0.19 m/s that the other terms allowed.</summary>
        public float ReleaseSpeed => SpeedOfSound * FirstCompression;

        /// <summary>e0: the largest compression max(0, rho / rho0 - 1) of any particle in the first state checked, 0 before it.</summary>
        public float FirstCompression { get; private set; }

        /// <summary>The speed no particle may exceed, m/s (grows when faster drivers are observed).</summary>
        public float SpeedBound => SpeedMargin * (FreeFallSpeed + SpawnSpeed + 2f * WallSpeed + 2f * ObstacleSpeed + CapillarySpeed + ReleaseSpeed)
            + AcousticFraction * SpeedOfSound;

        /// <summary>A container wall or sphere has moved: energy may come in from outside.</summary>
        public bool Driven => WallSpeed > 0f || ObstacleSpeed > 0f;

        /// <summary>Mechanical energy of the last state checked with particles minus that of the first, J (0 until two were checked).</summary>
        public double EnergyGrowth { get; private set; }

        /// <summary>Energy growth allowed over the first state checked with particles, J.</summary>
        public double EnergyBound
        {
            get
            {
                double elastic = ReleaseSpeed;
                return _totalMass * (EnergyAllowance * _gravity.Length() * ContainerDiagonal + 0.5 * elastic * elastic) + SurfaceEnergy;
            }
        }

        /// <summary>Takes in the container and spheres as they move now (call before each frame or check):
        /// the speed bound follows the fastest driver seen so far.</summary>
        public void ObserveDrivers(ContainerDescription container, IReadOnlyList<RigidSphere> obstacles)
        {
            if (container != null)
            {
                float wall = container.FastestWallSpeed;
                if (ValidationRules.IsFinite(wall)) WallSpeed = Math.Max(WallSpeed, wall);
            }
            if (obstacles != null)
            {
                for (int i = 0; i < obstacles.Count; i++) // not foreach: Unity calls this every frame, and an interface's enumerator is garbage
                {
                    var o = obstacles[i];
                    if (o == null) continue;
                    float speed = o.Velocity.Length();
                    if (ValidationRules.IsFinite(speed)) ObstacleSpeed = Math.Max(ObstacleSpeed, speed);
                }
            }
        }

        /// <summary>
        /// The first problem of the state, or null when it is healthy. <paramref name="particles"/> (a read-back
        /// of <see cref="FluidSimulation.Particles"/> at the report's time) adds the phase of the fastest particle
        /// and the energy test; without it the speed is the report's maximum over all phases.
        /// </summary>
        public HealthProblem Check(DiagnosticsReport report, IReadOnlyList<Particle> particles = null)
        {
            if (report == null) throw new ArgumentNullException(nameof(report));
            double t = report.SimulatedTime;
            const string all = "all phases";
            if (report.NanCount > 0)
                return new HealthProblem(t, all, "non-finite particle count", report.NanCount, 0, "", "the simulation went non-finite: a position or velocity is NaN or infinite");
            if (report.OutsideCount > 0)
                return new HealthProblem(t, all, "count of particles outside the container", report.OutsideCount, 0, "", "the walls must hold every particle");
            if (report.ParticleCount != _spawned)
                return new HealthProblem(t, all, "particle count change", Math.Abs(report.ParticleCount - _spawned), 0, "", $"{report.ParticleCount} counted, {_spawned} spawned");

            if (!_checkedFirst)
            {
                _checkedFirst = true;
                float compression = 0f;
                foreach (var phase in report.Phases)
                    if (ValidationRules.IsFinite(phase.MaxDensityError)) compression = Math.Max(compression, phase.MaxDensityError);
                FirstCompression = compression;
            }

            var speed = SpeedProblem(report, particles);
            if (speed != null) return speed;

            for (int k = 0; k < report.Phases.Count; k++)
            {
                var phase = report.Phases[k];
                if (!(phase.AverageDensityError <= MeanCompressionBound))
                    return new HealthProblem(t, phase.Name, "mean compression", phase.AverageDensityError, MeanCompressionBound, "", "no subsonic impact compresses a Tait liquid this much");
                if (!(phase.MaxDensityError <= MaxCompressionBound))
                    return new HealthProblem(t, phase.Name, "max compression", phase.MaxDensityError, MaxCompressionBound, "", "twice what a subsonic impact leaves, or the first state's own if more");
            }

            if (particles != null && !Driven)
            {
                double energy = FluidEnergy.Mechanical(particles, _phases, _gravity);
                if (double.IsNaN(_firstEnergy)) _firstEnergy = energy;
                else EnergyGrowth = energy - _firstEnergy;
                if (!(EnergyGrowth <= EnergyBound))
                    return new HealthProblem(t, all, "mechanical energy growth", energy - _firstEnergy, EnergyBound, "J",
                        "nothing in the scene feeds energy in: no moving wall or sphere");
            }
            return null;
        }

        HealthProblem SpeedProblem(DiagnosticsReport report, IReadOnlyList<Particle> particles)
        {
            float bound = SpeedBound;
            if (particles == null)
            {
                return report.MaxSpeed > bound
                    ? new HealthProblem(report.SimulatedTime, "all phases", "speed", report.MaxSpeed, bound, "m/s", SpeedReason())
                    : null;
            }
            float fastest = 0f;
            int phase = -1;
            for (int i = 0; i < particles.Count; i++)
            {
                float v = particles[i].Velocity.Length();
                if (v > fastest || float.IsNaN(v)) { fastest = v; phase = (int)particles[i].Phase; }
                if (float.IsNaN(v)) break;
            }
            if (!(fastest <= bound))
            {
                string name = phase >= 0 && phase < _phaseNames.Count ? _phaseNames[phase].Name : "all phases";
                return new HealthProblem(report.SimulatedTime, name, "speed", fastest, bound, "m/s", SpeedReason());
            }
            return null;
        }

        /// <summary>How the speed bound is made up; composed only for a problem, so that a healthy check makes no garbage.</summary>
        string SpeedReason() => string.Format(System.Globalization.CultureInfo.InvariantCulture,
            "{0} x (free fall over the container {1:G3} + spawn {2:G3} + 2 x wall {3:G3} + 2 x obstacle {4:G3} + capillary {7:G3} + the first state's compression released {8:G3} m/s) + {5} x speed of sound {6:G3} m/s",
            SpeedMargin, FreeFallSpeed, SpawnSpeed, WallSpeed, ObstacleSpeed, AcousticFraction, SpeedOfSound, CapillarySpeed, ReleaseSpeed);
    }
}
