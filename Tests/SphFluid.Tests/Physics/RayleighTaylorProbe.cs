using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// Whether water laid over oil overturns at the rate linear theory gives: the Rayleigh-Taylor instability of the
    /// OilAndWater liquids, a measurement run by name, `bash Headless/test.sh --filter FullyQualifiedName~RayleighTaylorProbe`,
    /// which CI does not run (each fixture simulates 2 s: half a minute to three minutes of lavapipe, twenty at twice the
    /// resolution).
    /// <para>
    /// The scene's tank holds <see cref="InternalSeicheProbe.LayerDepth"/> of water over as much oil, the interface displaced
    /// by the tank's fundamental mode by one or two spacings (<see cref="InternalSeicheProbe.TiltLayers"/>, a staircase of
    /// whole spacings), from rest; or flat and kicked, given the growing mode's own flow
    /// (<see cref="InternalSeiche.InterfaceModeVelocity"/>), which starts that mode alone. Linear theory lets the mode grow
    /// as A cosh(s t) + B sinh(s t), s from the two-layer relation the internal seiche obeys with the heavy layer on top
    /// (<see cref="InternalSeiche.GrowthRate"/>: 1.175/s, inviscid; the liquids' own viscosity takes under a percent off
    /// it at this wavelength): a0 cosh(s t) from the displaced start, <see cref="InternalSeicheProbe.KickAmplitude"/> sinh(s t) from the
    /// kicked one (twice that "kicked twice as hard", half "kicked half as hard"). The mode's amplitude
    /// (<see cref="FundamentalAmplitude"/>) is sampled every frame and printed every 0.1 s beside the theory's, and from a
    /// kicked start beside what the lattice as an elastic solid gives (<see cref="ElasticInterfaceMode.KickedInterface"/>);
    /// the probe prints its largest, how long it stays within
    /// <see cref="Following"/> of the theory's, and s fitted to it while it grows and stays below three spacings, and below
    /// two.
    /// </para>
    /// <para>
    /// A lattice of particles under pressure carries a shear stress (<see cref="LatticeShearStrength"/>) that holds a
    /// stable interface tilted by up to a bound (<see cref="InternalSeiche.HeldRise"/>); the same strength may resist the
    /// overturn, so each fixture prints that bound. Fixtures: the scene as shipped (WCSPH); DFSPH as <c>--solver dfsph</c>
    /// runs it; DFSPH with free-slip walls, which take the front and back walls' boundary layers out of it; with a tenth
    /// of the liquids' viscosity as well, the inviscid limit the theory describes, and with forty times it, at which waves
    /// four spacings long grow slower than the fundamental (so that none breaks on it); a start twice as large; oil at 500
    /// kg/m^3, five times the density step; twice the resolution (8 times the particles) with the start of the same
    /// size in metres; the cubic spline at 2 spacings, whose lattice is about three times as strong in shear; Wendland
    /// C2 at 3 and 3.5 spacings, six and thirty times weaker (under WCSPH: DFSPH takes Wendland C2 to 2.9 spacings); and
    /// WCSPH with particle shifting at A = 2, which DamBreak uses; and kicked starts spawned jittered by half a spacing
    /// (<see cref="FluidBlock.Jitter"/>), a disordered packing in place of the lattice.
    /// </para>
    /// </summary>
    [Explicit("a measurement, not a check: run it by name")]
    [TestFixture("shipped", "1 spacing")]
    [TestFixture("dfsph", "1 spacing")]
    [TestFixture("dfsph, free-slip walls", "1 spacing")]
    [TestFixture("dfsph, free-slip walls, viscosity / 10", "1 spacing")]
    [TestFixture("dfsph, free-slip walls", "2 spacings")]
    [TestFixture("dfsph, oil at 500 kg/m3", "1 spacing")]
    [TestFixture("dfsph, free-slip walls, viscosity x 40", "1 spacing")]
    [TestFixture("dfsph, twice as fine", "2 spacings")]
    [TestFixture("dfsph, cubic spline at 2 spacings", "1 spacing")]
    [TestFixture("shipped, Wendland C2 at 3 spacings", "1 spacing")]
    [TestFixture("shipped, Wendland C2 at 3.5 spacings", "1 spacing")]
    [TestFixture("shipped", "kicked")]
    [TestFixture("dfsph", "kicked")]
    [TestFixture("dfsph, free-slip walls", "kicked")]
    [TestFixture("dfsph, free-slip walls, viscosity x 40", "kicked")]
    [TestFixture("dfsph, free-slip walls", "kicked twice as hard")]
    [TestFixture("dfsph, free-slip walls", "kicked half as hard")]
    [TestFixture("shipped", "kicked half as hard")]
    [TestFixture("dfsph, cubic spline at 2 spacings", "kicked")]
    [TestFixture("shipped, Wendland C2 at 3 spacings", "kicked")]
    [TestFixture("shipped, Wendland C2 at 3.5 spacings", "kicked")]
    [TestFixture("dfsph, free-slip walls, twice as fine", "kicked")]
    [TestFixture("shipped, particle shifting 2", "1 spacing")]
    [TestFixture("shipped, particle shifting 2", "kicked")]
    [TestFixture("dfsph, jittered by 0.5", "kicked")]
    [TestFixture("shipped, jittered by 0.5", "kicked")]
    public sealed class RayleighTaylorProbe
    {
        const double Seconds = 2.0, Report = 0.1;

        /// <summary>How far (a fraction of the amplitude) the measured mode may stray from the theory's before it is said
        /// to have parted from it.</summary>
        const double Following = 0.02;

        /// <summary>The theory's amplitude (m) from which the measured one is compared with it: a kicked start begins flat, and
        /// its first millimetre is within the lattice's own ripple.</summary>
        const double Resolvable = 0.002;

        readonly string _configuration, _start;

        /// <summary>Two arguments, since NUnit cuts each to 40 characters in the test's name: the solver and its settings,
        /// and the start (displaced by one or two spacings, or kicked).</summary>
        public RayleighTaylorProbe(string configuration, string start) => (_configuration, _start) = (configuration, start);

        [Test]
        public void WaterOverOilOverturnsAtTheRayleighTaylorRate()
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            if (_configuration.Contains("twice as fine")) ParticleScaling.ScaleBy(scene, 8);
            if (_configuration.StartsWith("dfsph")) new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH OilAndWater");
            if (_configuration.Contains("free-slip walls")) scene.Container.Friction = WallFriction.Slip;
            if (_configuration.Contains("oil at 500 kg/m3"))
                scene.SpawnBoxes.First(b => b.Phase.Name == "Oil").Phase.RestDensity = 500f;
            if (_configuration.Contains("viscosity x 40"))
                foreach (var phase in scene.SpawnBoxes.Select(b => b.Phase).Distinct()) phase.Viscosity *= 40;
            if (_configuration.Contains("viscosity / 10"))
                foreach (var phase in scene.SpawnBoxes.Select(b => b.Phase).Distinct()) phase.Viscosity /= 10;
            bool kicked = _start.StartsWith("kicked");
            int tilt = kicked ? 0 : _start == "2 spacings" ? 2 : 1;
            InternalSeicheProbe.TiltLayers(scene, tilt, waterOnTop: true);
            var s = scene.Settings;
            if (_configuration.Contains("cubic spline at 2 spacings"))
            {
                s.SmoothingKernel = KernelFamily.CubicSpline;
                s.SmoothingRadius = 2f * s.ParticleSpacing;
            }
            var support = System.Text.RegularExpressions.Regex.Match(_configuration, @"Wendland C2 at ([\d.]+) spacings");
            if (support.Success) s.SmoothingRadius = float.Parse(support.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) * s.ParticleSpacing;
            var jitter = System.Text.RegularExpressions.Regex.Match(_configuration, @"jittered by ([\d.]+)");
            if (jitter.Success)
                foreach (var box in scene.SpawnBoxes) box.Jitter = float.Parse(jitter.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
            var shifting = System.Text.RegularExpressions.Regex.Match(_configuration, @"particle shifting ([\d.]+)");
            if (shifting.Success) s.ParticleShifting = float.Parse(shifting.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);

            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var phases = sim.PhaseRows;
            int water = phases[0].RestDensity > phases[1].RestDensity ? 0 : 1, oil = 1 - water;
            double layer = InternalSeicheProbe.LayerSpacings(s.ParticleSpacing) * s.ParticleSpacing;
            var tank = new InternalSeiche.Tank(scene.Container.Size.X, scene.Container.Size.Z, s.Gravity.Length(),
                layer, phases[water].RestDensity, phases[water].Viscosity, layer, phases[oil].RestDensity, phases[oil].Viscosity,
                scene.Container.Friction == WallFriction.NoSlip);
            double theory = InternalSeiche.GrowthRate(tank);
            var particles = new Particle[sim.ParticleCount];
            double kick = !kicked ? 0 : InternalSeicheProbe.KickAmplitude * (_start.EndsWith("twice as hard") ? 2 : _start.EndsWith("half as hard") ? 0.5 : 1);
            if (kicked) InternalSeicheProbe.Kick(sim, scene, tank, particles, kick);
            var (axis, diagonal) = ElasticInterfaceMode.ModulusRatios(s.SmoothingKernel, s.ParticleSpacing, s.SmoothingRadius);
            var lattice = axis > 0 ? ElasticInterfaceMode.Modes(tank, axis, diagonal) : null;
            var densities = new System.Numerics.Vector4[sim.ParticleCount];
            var times = new List<double>();
            var amplitudes = new List<double>();
            double nextReport = 0;
            while (true)
            {
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                times.Add(sim.SimulatedTime);
                amplitudes.Add(FundamentalAmplitude(scene, particles, densities, phases, oil));
                if (sim.SimulatedTime >= nextReport - 1e-6)
                {
                    double expected = Math.Abs(amplitudes[0]) * Math.Cosh(theory * times[^1]) + kick * Math.Sinh(theory * times[^1]);
                    string elastic = !kicked || lattice == null ? "" : $", the elastic lattice's {1000 * ElasticInterfaceMode.KickedInterface(lattice, tank, kick, times[^1]):F1} mm";
                    TestContext.Progress.WriteLine($"t={sim.SimulatedTime:F2} s amplitude {1000 * Math.Abs(amplitudes[^1]):F1} mm, the theory's {1000 * expected:F1} mm{elastic}");
                    nextReport += Report;
                }
                if (sim.SimulatedTime >= Seconds - 1e-6) break;
                sim.Step(1f / 60f);
            }
            var report = sim.ReadDiagnostics();
            double sign = kicked ? 1 : Math.Sign(amplitudes[0]); // positive while the start's mode grows
            for (int i = 0; i < amplitudes.Count; i++) amplitudes[i] *= sign;

            double strength = LatticeShearStrength.YieldRatio(s.SmoothingKernel, s.ParticleSpacing, s.SmoothingRadius);
            double held = InternalSeiche.HeldRise(tank, strength, sideWalls: false), heldWithWalls = InternalSeiche.HeldRise(tank, strength, sideWalls: true);

            string Fit(int spacings)
            {
                int n = GrowingSamples(amplitudes, spacings * s.ParticleSpacing);
                if (n < 8) return $"below {spacings} spacings: {n} samples, no fit";
                var (rate, residual) = FitGrowth(times.Take(n).ToList(), amplitudes.Take(n).ToList());
                return $"below {spacings} spacings (to {times[n - 1]:F2} s): s = {rate:F3}/s, {rate / theory:F2} of the theory's (RMS residual {1000 * residual:F1} mm)";
            }
            // How long the start follows the theory's mode, a0 cosh(s t) from rest plus a sinh(s t) from the kick, before it
            // parts from it, judged where the mode has grown past Resolvable.
            double Mode(int i) => amplitudes[0] * Math.Cosh(theory * times[i]) + kick * Math.Sinh(theory * times[i]);
            int parted = Enumerable.Range(0, amplitudes.Count).FirstOrDefault(i => Math.Abs(Mode(i)) >= Resolvable && Math.Abs(amplitudes[i] / Mode(i) - 1) > Following, -1);
            int last = parted < 0 ? amplitudes.Count - 1 : Math.Max(0, parted - 1);
            int largest = Enumerable.Range(0, amplitudes.Count).Aggregate((a, b) => amplitudes[b] > amplitudes[a] ? b : a);
            string following = $"largest {1000 * amplitudes[largest]:F1} mm at {times[largest]:F2} s; follows {(kicked ? "a0 cosh(s t) + a sinh(s t)" : "a0 cosh(s t)")} within {Following:P0} to {times[last]:F2} s " +
                $"({1000 * amplitudes[last]:F1} mm, the theory's {1000 * Mode(last):F1}); ";
            string solver = s.PressureSolver == PressureSolver.Dfsph ? "DFSPH" : $"WCSPH with {s.WcsphDensity} density";
            TestContext.Progress.WriteLine($"Rayleigh-Taylor ({_configuration}, {_start}): {solver}; theory s = {theory:F3}/s; " +
                $"fitted {Fit(3)}; {Fit(2)}; {following}amplitude at 0 s {1000 * amplitudes[0]:F1} mm, at {Seconds} s {1000 * amplitudes[^1]:F1} mm; " +
                $"the lattice's shear strength, {strength:E2} of the pressure, can hold a plane interface still at a tilt of up to " +
                $"{1000 * held:F1} mm on the interface and the floor, {1000 * heldWithWalls:F1} mm with the front and back walls; " +
                $"the lattice as an elastic solid, C44 = {axis:F5} p and C' = {diagonal:F5} p: " +
                (lattice == null ? "C44 below 0, no elastic prediction; " : $"its lowest mode lambda = {lattice[0].Lambda:F3}/s^2 (Lamb's {-theory * theory:F3}); ") +
                $"max speed at {Seconds} s {1000 * report.MaxSpeed:F1} mm/s; clamp hits {report.ClampHits}; " +
                $"the oil's depth at {Seconds} s in columns of 2 spacings along the tank, mm: {string.Join(" ", OilDepths(scene, particles, densities, phases, oil).Select(d => (1000 * d).ToString("F0")))}");
            Assert.That(amplitudes.All(double.IsFinite), Is.True);
        }

        /// <summary>The oil's volume over each column of the floor, two spacings along the tank and the tank's width across,
        /// over the column's area: the interface's height where the oil lies under the water in one layer.</summary>
        static double[] OilDepths(FluidSceneDescription scene, Particle[] particles, System.Numerics.Vector4[] densities,
            IReadOnlyList<PhaseProperties> phases, int oil)
        {
            var container = scene.Container;
            float width = 2 * scene.Settings.ParticleSpacing, left = container.Position.X - container.Size.X / 2;
            var depths = new double[(int)Math.Round(container.Size.X / width)];
            for (int i = 0; i < particles.Length; i++)
            {
                if (particles[i].Phase != oil) continue;
                int column = Math.Clamp((int)((particles[i].Position.X - left) / width), 0, depths.Length - 1);
                depths[column] += phases[oil].ParticleMass / densities[i].X / (width * container.Size.Z);
            }
            return depths;
        }

        /// <summary>
        /// The fundamental mode's amplitude a in the interface's height a cos(pi x / L) (x from the left wall) while the oil
        /// lies under the water: the oil's height h(x) is its volume over the floor, so a = (2 / L) integral h cos(pi x / L)
        /// dx = (2 / (L W)) sum_i V_i cos(pi x_i / L) over the oil's particles (V_i = m_i / rho_i), which the overtones do
        /// not enter and which moves with the particles rather than in whole particles across columns.
        /// </summary>
        static double FundamentalAmplitude(FluidSceneDescription scene, Particle[] particles, System.Numerics.Vector4[] densities,
            IReadOnlyList<PhaseProperties> phases, int oil)
        {
            var container = scene.Container;
            double length = container.Size.X, left = container.Position.X - length / 2, sum = 0;
            for (int i = 0; i < particles.Length; i++)
                if (particles[i].Phase == oil)
                    sum += phases[oil].ParticleMass / densities[i].X * Math.Cos(Math.PI * (particles[i].Position.X - left) / length);
            return 2 * sum / (length * container.Size.Z);
        }

        /// <summary>The samples from the start while the amplitude stays below <paramref name="cap"/> and has not fallen a
        /// millimetre below its largest yet, ending at that largest: past it the overturn no longer grows the mode (with
        /// oil at 500 kg/m^3 the amplitude then swings between about +-33 mm as the layers slosh).</summary>
        static int GrowingSamples(IReadOnlyList<double> amplitudes, double cap)
        {
            int largest = 0;
            for (int i = 0; i < amplitudes.Count; i++)
            {
                if (amplitudes[i] >= cap) return i;
                if (amplitudes[i] > amplitudes[largest]) largest = i;
                else if (amplitudes[i] < amplitudes[largest] - 0.001) return largest + 1;
            }
            return amplitudes.Count;
        }

        /// <summary>Least squares of r(t) = A cosh(s t) + B sinh(s t) (A and B linear for each s; s on a grid refined
        /// twice): the growth rate and the RMS residual.</summary>
        static (double Rate, double Residual) FitGrowth(IReadOnlyList<double> times, IReadOnlyList<double> values)
        {
            double low = 0, high = 10, step = 0.01, best = double.PositiveInfinity, bestRate = 0;
            for (int pass = 0; pass < 3; pass++)
            {
                for (double rate = low; rate <= high + 1e-12; rate += step)
                {
                    double r = Residual(times, values, rate);
                    if (r < best) (best, bestRate) = (r, rate);
                }
                (low, high) = (Math.Max(0, bestRate - 2 * step), bestRate + 2 * step);
                step /= 20;
            }
            return (bestRate, Math.Sqrt(best / times.Count));
        }

        static double Residual(IReadOnlyList<double> times, IReadOnlyList<double> values, double rate)
        {
            // At rate 0 the pair is 1 and t (the limit of sinh(s t) / s).
            double F(double t) => Math.Cosh(rate * t);
            double G(double t) => rate > 0 ? Math.Sinh(rate * t) / rate : t;
            double ff = 0, fg = 0, gg = 0, fv = 0, gv = 0;
            for (int i = 0; i < times.Count; i++)
            {
                double f = F(times[i]), g = G(times[i]);
                ff += f * f; fg += f * g; gg += g * g; fv += f * values[i]; gv += g * values[i];
            }
            double det = ff * gg - fg * fg;
            if (Math.Abs(det) < 1e-300) return double.PositiveInfinity;
            double a = (fv * gg - gv * fg) / det, b = (gv * ff - fv * fg) / det;
            double sum = 0;
            for (int i = 0; i < times.Count; i++)
            {
                double d = values[i] - (a * F(times[i]) + b * G(times[i]));
                sum += d * d;
            }
            return sum;
        }
    }
}
