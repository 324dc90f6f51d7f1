using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// A tank of water at rest (the physics issue's case: a 0.4 x 0.3 x 0.2 m water box filling the footprint of its
    /// container) must stay at rest: its column keeps its height, the pressure grows with depth as rho0 g, and the walls
    /// hold it without the last-resort clamp. With penalty walls and the Spiky density it lost 14 % of its height and its
    /// pressure gradient was 32 % too steep. One 2-second run, several measures, for
    /// <list type="bullet">
    /// <item>the shipped RestingTank scene (Assets/FluidDemo/Scenes/RestingTank.unity): delta-SPH's carried density
    /// (SphDensityDiffusion.hlsl) with Wendland C2 at 2.85 spacings, the middle of the supports at which the particle
    /// lattice is stable under pressure (<see cref="LatticeStability"/>), spawned on the plain lattice;</item>
    /// <item>the same tank at the default cubic spline at 2 spacings, for each WCSPH density (summation and delta-SPH),
    /// spawned with the spawn box's default jitter. Its lattice is unstable under the hydrostatic load, so the 5 mm/s
    /// test reports its measured speed as ignored.</item>
    /// </list>
    /// </summary>
    [TestFixture("RestingTank")]
    [TestFixture(WcsphDensity.Summation)]
    [TestFixture(WcsphDensity.DeltaSph)]
    public sealed class RestingTankTests
    {
        readonly Func<FluidSceneDescription> _scene;
        readonly string _name;

        /// <summary>A shipped scene of the tank.</summary>
        public RestingTankTests(string shippedScene)
        {
            _scene = () => SceneLoader.Load(RunnerPaths.Scene(shippedScene), RunnerPaths.Project).Description;
            _name = shippedScene + ".unity";
        }

        /// <summary>The tank at the default cubic spline at 2 spacings and the spawn box's default jitter.</summary>
        public RestingTankTests(WcsphDensity density)
        {
            _scene = () => Tank(0.025f, density);
            _name = $"cubic spline at 2 spacings, {density}";
        }

        const float BoxHeight = 0.3f;
        public const double RestDensity = 1000.0;
        const double RhoG = RestDensity * 9.81;
        double _spawned, _height, _gradient, _maxSpeedLastSecond;
        DiagnosticsReport _report;
        KernelFamily _kernel;

        public static FluidSceneDescription Tank(float spacing, WcsphDensity density = WcsphDensity.Summation,
            KernelFamily kernel = KernelFamily.CubicSpline, float supportRatio = 2f)
        {
            var settings = new FluidSettings
            {
                ParticleSpacing = spacing, SmoothingRadius = supportRatio * spacing, SmoothingKernel = kernel, MaxSubsteps = 200, WcsphDensity = density,
            };
            var container = new Vector3(0.4f, 0.4f, 0.2f);
            var water = new Vector3(0.4f, 0.3f, 0.2f);
            var box = SolverScenes.Box("Water", SolverScenes.Water(viscosity: 0.001f), new Vector3(0f, -0.5f * container.Y + 0.5f * water.Y, 0f), water);
            return SolverScenes.Scene(settings, container, box);
        }

        [OneTimeSetUp]
        public void RunTwoSeconds()
        {
            var scene = _scene();
            var settings = scene.Settings;
            _kernel = settings.SmoothingKernel;
            float floor = scene.Container.Position.Y - 0.5f * scene.Container.Size.Y;
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            sim.Particles.GetData(particles);
            _spawned = TankMeasures.ColumnHeight(particles, floor);
            while (sim.SimulatedTime < 2.0 - 1e-6)
            {
                sim.Step(1f / 60f);
                if (sim.SimulatedTime <= 1.0) continue;
                sim.Particles.GetData(particles);
                _maxSpeedLastSecond = Math.Max(_maxSpeedLastSecond, TankMeasures.MaxSpeed(particles));
            }
            sim.Particles.GetData(particles);
            sim.Densities.GetData(densities);
            _report = sim.ReadDiagnostics();
            _height = TankMeasures.ColumnHeight(particles, floor);
            double surface = floor + _height;
            // Fitted away from the floor and the free surface by the same fractions of the support H (1.5 and 2.5 spacings
            // at H = 2 spacings), where neither the wall's nor the surface's truncated kernel sums reach.
            double support = settings.SmoothingRadius;
            _gradient = TankMeasures.PressureGradient(particles, densities, floor + 0.75 * support, surface - 1.25 * support);
            TestContext.Progress.WriteLine($"resting tank ({_name}: {settings.WcsphDensity}, {_kernel} at {settings.SmoothingRadius / settings.ParticleSpacing:F2} spacings, jitter {scene.SpawnBoxes[0].Jitter}), N={sim.ParticleCount}, {sim.BoundaryCount} boundary particles: column {_height:F4} m at 2 s, " +
                $"{_spawned:F4} m spawned ({100 * (_height / _spawned - 1):F2} %; spawn vs box {100 * (_spawned / BoxHeight - 1):F2} %), " +
                $"dp/dy {_gradient:F0} Pa/m (rho0 g {RhoG:F0}: {100 * (-_gradient / RhoG - 1):F2} %), max speed 1-2 s {1000 * _maxSpeedLastSecond:F1} mm/s; {_report}");
        }

        [Test]
        public void TheHydrostaticSpawnCompressesTheBoxByLessThanOnePercent() =>
            Assert.That(_spawned, Is.EqualTo(BoxHeight).Within(0.01 * BoxHeight));

        [Test]
        public void TheColumnKeepsItsSpawnedHeightWithinOnePercentAfterTwoSeconds() =>
            Assert.That(_height, Is.EqualTo(_spawned).Within(0.01 * _spawned));

        [Test]
        public void ThePressureGrowsWithDepthAsRho0GWithinThreePercent() =>
            Assert.That(-_gradient, Is.EqualTo(RhoG).Within(0.03 * RhoG));

        [Test]
        public void TheWallsHoldTheFluidWithoutTheLastResortClamp()
        {
            Assert.That(_report.ClampHits, Is.EqualTo(0));
            Assert.That(_report.OutsideCount, Is.EqualTo(0));
        }

        /// <summary>Met by the shipped RestingTank scene. The cubic spline at 2 spacings keeps moving: released from a damped
        /// equilibrium its lattice's motion grows at about 17/s whatever the time step and at four times the stiffness, but
        /// hardly at a quarter of g (TankEquilibriumProbe): the lattice is unstable under the hydrostatic pressure, as the
        /// linear analysis of <see cref="LatticeStability"/> predicts (about 25/s at the tank's mid-depth pressure).
        /// Reported as ignored, with this run's figure, for those fixtures.</summary>
        [Test]
        public void TheFluidComesToRestBelowFiveMillimetresPerSecond()
        {
            if (_kernel == KernelFamily.CubicSpline)
                Assert.Ignore($"Not met by the cubic spline at 2 spacings: {1000 * _maxSpeedLastSecond:F1} mm/s between 1 and 2 s " +
                              "(its lattice is unstable under the hydrostatic load: LatticeStability, TankEquilibriumProbe). Met by the RestingTank scene: DeltaSph, WendlandC2 at 2.85 spacings.");
            Assert.That(_maxSpeedLastSecond, Is.LessThan(0.005));
        }
    }
}
