using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Output;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// Whether the OilAndWater interface settles as a liquid's would: a measurement run by name,
    /// `bash Headless/test.sh --filter FullyQualifiedName~InternalSeicheProbe`, which CI does not run (each fixture
    /// simulates 12 s: 12 to 16 minutes of lavapipe).
    /// <para>
    /// Once the lock exchange has laid the oil over the water, the interface is left tilted and should rock as the
    /// tank's fundamental internal seiche, at the period and with the laminar viscous decay of <see cref="InternalSeiche"/>
    /// for the layers' measured depths (their volumes over the floor). The interface's signed rise along the tank
    /// (<see cref="InterfaceTilt.Rises"/>) is sampled every 50 ms from 2 s on; a damped oscillation fitted to it gives the
    /// measured period and decay, and its zero crossings and the extremes between them are printed too.
    /// </para>
    /// <para>
    /// Fixtures: the scene as shipped (WCSPH: delta-SPH, Wendland C2 at 2.85 spacings); its previous configuration
    /// (summation, the cubic spline at 2 spacings), whose interface froze tilted; and DFSPH (the scene's own DFSPH
    /// settings, as <c>--solver dfsph</c> runs it) as it is, with a tenth of each liquid's viscosity and with free-slip
    /// walls, which tell the liquids' viscous damping and the walls' from the method's own, and with a tenth of the
    /// viscosity at a tenfold looser density tolerance, 1 %, which tells the constant-density solve's part (it takes a
    /// quarter of the energy the lock exchange releases, <see cref="LockExchangeTests"/>). The "layers tilted" fixtures
    /// start from rest with the layers already in place and the interface displaced by the seiche's own mode
    /// (<see cref="TiltLayers"/>), sampled from the first frame: no lock exchange or bore comes before the seiche, and the
    /// swing starts small. One of them sets the oil's rest density to 500 kg/m^3 instead of 900, which multiplies the buoyancy that
    /// drives the seiche by five; one tightens DFSPH's density tolerance tenfold, to 0.01 %; one takes the cubic spline
    /// at 2 spacings, whose lattice is about three times as strong in shear (<see cref="LatticeShearStrength"/>). Each
    /// fixture also prints the largest plane tilt its lattice can hold still (<see cref="InternalSeiche.HeldRise"/>). The
    /// "kicked" fixture starts from flat layers given the seiche's own flow (<see cref="Kick"/>), an interface of
    /// <see cref="KickAmplitude"/> sin(omega t) with nothing else moving: the seiche at a small amplitude, whose period
    /// tells whether the lattice adds a stiffness of its own to the buoyancy's.
    /// </para>
    /// </summary>
    [Explicit("a measurement, not a check: run it by name")]
    [TestFixture("shipped")]
    [TestFixture("cubic spline")]
    [TestFixture("dfsph")]
    [TestFixture("dfsph, viscosity / 10")]
    [TestFixture("dfsph at 1 %, viscosity / 10")]
    [TestFixture("dfsph, free-slip walls")]
    [TestFixture("shipped, layers tilted by 1 spacing")]
    [TestFixture("dfsph, layers tilted by 1 spacing")]
    [TestFixture("dfsph, layers tilted by 2 spacings")]
    [TestFixture("dfsph, oil at 500 kg/m3, layers tilted by 1 spacing")]
    [TestFixture("dfsph at 0.01 %, layers tilted by 1 spacing")]
    [TestFixture("dfsph, cubic spline at 2 spacings, layers tilted by 1 spacing")]
    [TestFixture("dfsph, free-slip walls, kicked")]
    public sealed class InternalSeicheProbe
    {
        const double Seconds = 12.0, Sample = 0.05;
        readonly string _configuration;
        readonly int _tilt;

        public InternalSeicheProbe(string configuration)
        {
            _configuration = configuration;
            var tilted = System.Text.RegularExpressions.Regex.Match(configuration, @"layers tilted by (\d) spacings?$");
            _tilt = tilted.Success ? int.Parse(tilted.Groups[1].Value) : 0;
        }

        /// <summary>The kicked starts' interface amplitude a, m (the scene's spacing, at any resolution): a sinh(s t) for
        /// the Rayleigh-Taylor mode, a sin(omega t) for the seiche.</summary>
        internal const double KickAmplitude = 0.015;

        /// <summary>Each layer's depth as <see cref="TiltLayers"/> lays it, m.</summary>
        internal const double LayerDepth = 0.105;

        /// <summary>Whole spacings nearest <see cref="LayerDepth"/>.</summary>
        internal static int LayerSpacings(float spacing) => (int)Math.Round(LayerDepth / spacing);

        /// <summary>
        /// The layers already in place, each <see cref="LayerDepth"/> deep (seven of the scene's spacings; whole spacings at
        /// any spacing, so every box's lattice is cubic and both phases keep one particle mass), with the interface
        /// displaced by the fundamental seiche mode, -s round(n cos(pi x / L)) for x from the left wall, in columns two
        /// spacings wide: a staircase n spacings up at one end and down at the other. The free surface starts flat, so the
        /// start excites the internal mode and hardly the surface's, and no lock exchange or bore precedes the seiche. With <paramref name="waterOnTop"/> the
        /// water lies over the oil instead (<see cref="RayleighTaylorProbe"/>).
        /// </summary>
        internal static void TiltLayers(FluidSceneDescription scene, int spacings, bool waterOnTop = false)
        {
            int layer = LayerSpacings(scene.Settings.ParticleSpacing);
            var boxes = scene.SpawnBoxes;
            var oil = boxes.First(b => b.Phase.RestDensity < boxes.Max(o => o.Phase.RestDensity));
            var water = boxes.First(b => b.Phase.RestDensity == boxes.Max(o => o.Phase.RestDensity));
            var container = scene.Container;
            float s = scene.Settings.ParticleSpacing, width = 2 * s, floor = container.Position.Y - container.Size.Y / 2;
            int columns = (int)Math.Round(container.Size.X / width);
            var (lower, upper) = waterOnTop ? (oil, water) : (water, oil);
            var tilted = new List<FluidBlock>();
            for (int c = 0; c < columns; c++)
            {
                int rise = -(int)Math.Round(spacings * Math.Cos(Math.PI * (c + 0.5) / columns));
                float x = container.Position.X - container.Size.X / 2 + (c + 0.5f) * width;
                float lowerDepth = (layer + rise) * s, upperDepth = (layer - rise) * s;
                tilted.Add(Column(lower, x, floor + lowerDepth / 2, lowerDepth));
                tilted.Add(Column(upper, x, floor + lowerDepth + upperDepth / 2, upperDepth));
            }
            scene.SpawnBoxes = tilted;

            FluidBlock Column(FluidBlock like, float x, float y, float height)
            {
                var box = like.Clone();
                box.Phase = like.Phase;
                box.Center = new Vector3(x, y, container.Position.Z);
                box.Size = new Vector3(width, height, container.Size.Z);
                return box;
            }
        }

        /// <summary>Gives the flat layers at rest the fundamental interface mode's flow
        /// (<see cref="InternalSeiche.InterfaceModeVelocity"/>) for an interface of <paramref name="amplitude"/> sinh(s t),
        /// or <paramref name="amplitude"/> sin(omega t) with the light layer on top, rising first at the left wall; the
        /// positions are left as they are.</summary>
        internal static void Kick(FluidSimulation sim, FluidSceneDescription scene, InternalSeiche.Tank tank, Particle[] particles, double amplitude)
        {
            var container = scene.Container;
            float left = container.Position.X - container.Size.X / 2, floor = container.Position.Y - container.Size.Y / 2;
            sim.Particles.GetData(particles);
            for (int i = 0; i < particles.Length; i++)
            {
                var (along, up) = InternalSeiche.InterfaceModeVelocity(tank, amplitude, particles[i].Position.X - left, particles[i].Position.Y - floor);
                particles[i].Velocity = new Vector3((float)along, (float)up, 0);
            }
            sim.SetParticles(particles);
        }

        [Test]
        public void TheInterfaceRocksAtTheSeichePeriod()
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            if (_configuration.StartsWith("dfsph")) new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH OilAndWater");
            if (_configuration.Contains("viscosity / 10"))
                foreach (var phase in scene.SpawnBoxes.Select(b => b.Phase).Distinct()) phase.Viscosity /= 10;
            if (_configuration.Contains("free-slip walls")) scene.Container.Friction = WallFriction.Slip;
            if (_configuration.Contains("oil at 500 kg/m3"))
                scene.SpawnBoxes.First(b => b.Phase.Name == "Oil").Phase.RestDensity = 500f;
            bool kicked = _configuration.EndsWith("kicked");
            if (_tilt > 0 || kicked) TiltLayers(scene, _tilt);
            if (_configuration.Contains("at 0.01 %")) scene.Settings.DensityTolerance = 0.01f;
            if (_configuration.Contains("at 1 %")) scene.Settings.DensityTolerance = 1f;
            double settled = _tilt > 0 || kicked ? 0.0 : 2.0;
            var s = scene.Settings;
            if (_configuration == "cubic spline" || _configuration.Contains("cubic spline at 2 spacings"))
            {
                s.SmoothingKernel = KernelFamily.CubicSpline;
                s.SmoothingRadius = 2f * s.ParticleSpacing;
                s.WcsphDensity = WcsphDensity.Summation;
            }
            string solver = s.PressureSolver == PressureSolver.Dfsph ? "DFSPH" : $"WCSPH with {s.WcsphDensity} density";
            string name = $"OilAndWater ({_configuration}): {solver}, {s.SmoothingKernel} at {s.SmoothingRadius / s.ParticleSpacing:F2} spacings";

            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            Func<double, double>? elasticRise = null, lambRise = null;
            if (kicked)
            {
                var rows = sim.PhaseRows;
                int heavy = rows[0].RestDensity > rows[1].RestDensity ? 0 : 1, light = 1 - heavy;
                double layer = LayerSpacings(s.ParticleSpacing) * s.ParticleSpacing;
                var laid = new InternalSeiche.Tank(scene.Container.Size.X, scene.Container.Size.Z, s.Gravity.Length(),
                    layer, rows[light].RestDensity, rows[light].Viscosity, layer, rows[heavy].RestDensity, rows[heavy].Viscosity,
                    scene.Container.Friction == WallFriction.NoSlip);
                Kick(sim, scene, laid, particles, KickAmplitude);
                // The lattice as an elastic solid (ElasticInterfaceMode), its interface a cos(pi x / L) read as the rise of
                // its least-squares plane across the tank, -24 a / pi^2 (up at the left wall, so falling along the tank).
                var (axis, diagonal) = ElasticInterfaceMode.ModulusRatios(s.SmoothingKernel, s.ParticleSpacing, s.SmoothingRadius);
                var lamb = ElasticInterfaceMode.Modes(laid, 0, 0);
                lambRise = time => -24 / (Math.PI * Math.PI) * ElasticInterfaceMode.KickedInterface(lamb, laid, KickAmplitude, time);
                if (axis > 0)
                {
                    var modes = ElasticInterfaceMode.Modes(laid, axis, diagonal);
                    elasticRise = time => -24 / (Math.PI * Math.PI) * ElasticInterfaceMode.KickedInterface(modes, laid, KickAmplitude, time);
                }
            }
            var densities = new Vector4[sim.ParticleCount];
            var times = new List<double>();
            var rises = new List<double>();
            FluidMeasures? last = null;
            double next = settled;
            while (sim.SimulatedTime < Seconds - 1e-6)
            {
                sim.Step(1f / 60f);
                if (sim.SimulatedTime < next - 1e-6) continue;
                next += Sample;
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                last = FluidMeasures.Measure(sim.SimulatedTime, particles, densities, sim.PhaseRows, scene.Container, s.Gravity, s.ParticleSpacing, s.SmoothingRadius);
                times.Add(sim.SimulatedTime);
                rises.Add(last.InterfaceRises[0].AlongU);
                if (times.Count % 10 == 1)
                    TestContext.Progress.WriteLine($"t={sim.SimulatedTime:F2} s rise {1000 * rises[^1]:F1} mm" +
                        (lambRise == null ? "" : $", Lamb's {1000 * lambRise(sim.SimulatedTime):F1} mm") +
                        (elasticRise == null ? "" : $", the elastic lattice's {1000 * elasticRise(sim.SimulatedTime):F1} mm"));
            }
            Assert.That(last, Is.Not.Null);
            var report = sim.ReadDiagnostics();

            // Layer depths from the measured volumes, and the seiche the two-layer theory gives them.
            var phases = sim.PhaseRows;
            double floorArea = scene.Container.Size.X * scene.Container.Size.Z;
            var depth = new double[phases.Count];
            for (int i = 0; i < particles.Length; i++)
                depth[particles[i].Phase] += phases[(int)particles[i].Phase].ParticleMass / densities[i].X / floorArea;
            int water = phases[0].RestDensity > phases[1].RestDensity ? 0 : 1, oil = 1 - water;
            var tank = new InternalSeiche.Tank(scene.Container.Size.X, scene.Container.Size.Z, s.Gravity.Length(),
                depth[oil], phases[oil].RestDensity, phases[oil].Viscosity, depth[water], phases[water].RestDensity, phases[water].Viscosity,
                scene.Container.Friction == WallFriction.NoSlip);
            double omega = InternalSeiche.AngularFrequency(tank), decay = InternalSeiche.DecayRate(tank);
            var fit = InternalSeiche.FitDampedOscillation(times, rises);
            double strength = LatticeShearStrength.YieldRatio(s.SmoothingKernel, s.ParticleSpacing, s.SmoothingRadius);
            double held = InternalSeiche.HeldRise(tank, strength, sideWalls: false), heldWithWalls = InternalSeiche.HeldRise(tank, strength, sideWalls: true);

            var crossings = InternalSeiche.ZeroCrossings(times, rises);
            var extremes = new List<double>();
            for (int c = 0; c + 1 < crossings.Count; c++)
                extremes.Add(Enumerable.Range(0, rises.Count).Where(i => times[i] > crossings[c] && times[i] < crossings[c + 1]).Max(i => Math.Abs(rises[i])));

            string measured = crossings.Count >= 2
                ? $"crossings at {string.Join(", ", crossings.Select(t => t.ToString("F2")))} s; " +
                  $"swings {string.Join(", ", extremes.Select(a => (1000 * a).ToString("F1")))} mm"
                : $"{crossings.Count} crossing(s) after {settled} s: no swing back";
            TestContext.Progress.WriteLine($"internal seiche ({name}): layers {1000 * depth[oil]:F1} mm oil over {1000 * depth[water]:F1} mm water; " +
                $"theory: period {2 * Math.PI / omega:F2} s, laminar decay {decay:F3}/s; fitted from {settled} s: period {2 * Math.PI / fit.Omega:F2} s, " +
                $"decay {fit.Gamma:F3}/s (RMS residual {1000 * fit.Residual:F1} mm); {measured}; rise along the tank at {settled} s {1000 * rises[0]:F1} mm, at {Seconds} s {1000 * rises[^1]:F1} mm; " +
                $"max speed at {Seconds} s {1000 * report.MaxSpeed:F1} mm/s; clamp hits {report.ClampHits}; " +
                $"the lattice's shear strength, {strength:E2} of the pressure, can hold a plane interface still at a tilt of up to {1000 * held:F1} mm " +
                $"on the interface and the floor, {1000 * heldWithWalls:F1} mm with the front and back walls");
        }
    }
}
