using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The shipped OilAndWater scene is a lock exchange (<see cref="LockExchange"/>): 0.2 m of water and of oil side by
    /// side in a 0.6 m tank, released at once. Its two fronts, sampled every frame from the release to 1.4 s, and their
    /// speeds fitted where each lies 5 to 22 cm from the lock (after the start, before the end wall), against Benjamin's
    /// energy-conserving gravity current. As shipped the water's front along the floor runs at 0.63 of his speed and the
    /// oil's along the free surface at 0.75 (Froude numbers 0.316 and 0.377 against his 1/2): at this resolution the
    /// current's head spans about two supports, and WCSPH's artificial viscosity and delta-SPH diffusion, both in
    /// proportion to the speed of sound, slow it further. In the limit his theory describes (DFSPH, a tenth of each
    /// liquid's viscosity, slip walls) both currents run at 0.74 to 0.84 of his speed by <see cref="LockExchange.Heads"/>,
    /// which does not change with the spacing, while the oil's front here counts a film running ahead along the surface
    /// as the support shrinks, reading 1.02 to 1.08 of his speed at 1.26 to 2 times finer (<see cref="LockExchangeProbe"/>;
    /// Headless/docs/physics.md, "The lock exchange, against Benjamin's gravity current").
    /// </summary>
    public sealed class LockExchangeTests
    {
        Exchange _run = null!;

        [OneTimeSetUp]
        public void ReleaseTheLock() => _run = Run(LockExchangeProbe.Configure("wcsph", out double seconds), "OilAndWater.unity as shipped", seconds);

        /// <summary>No front outruns the current that loses no energy (5 % for the fit): a faster one would take energy
        /// the release does not give.</summary>
        [Test]
        public void NeitherFrontOutrunsTheEnergyConservingCurrent()
        {
            Assert.That(_run.WaterSpeed, Is.LessThanOrEqualTo(1.05 * _run.WaterTheory));
            Assert.That(_run.OilSpeed, Is.LessThanOrEqualTo(1.05 * _run.OilTheory));
        }

        /// <summary>A floor under the speeds measured as shipped (0.63 and 0.75 of Benjamin's), not agreement with him: an
        /// exchange held back further, as one whose density step is too small for the lattice to give way is held
        /// (Headless/docs/physics.md, "From a tilted start"), fails it.</summary>
        [Test]
        public void BothFrontsRunAtLeastHalfBenjaminsSpeed()
        {
            Assert.That(_run.WaterSpeed, Is.GreaterThanOrEqualTo(0.5 * _run.WaterTheory));
            Assert.That(_run.OilSpeed, Is.GreaterThanOrEqualTo(0.5 * _run.OilTheory));
        }

        /// <summary>The same two bounds on the heads (<see cref="LockExchange.Heads"/>: where each liquid fills a quarter of
        /// the depth), which no film running ahead along the surface or the floor can set: as shipped 0.61 and 0.58 of
        /// Benjamin's speed.</summary>
        [Test]
        public void BothHeadsRunBetweenHalfAndBenjaminsSpeed()
        {
            Assert.That(_run.WaterHeadSpeed, Is.InRange(0.5 * _run.WaterTheory, 1.05 * _run.WaterTheory));
            Assert.That(_run.OilHeadSpeed, Is.InRange(0.5 * _run.OilTheory, 1.05 * _run.OilTheory));
        }

        [Test]
        public void NothingLeavesAndTheLastResortClampStaysIdle()
        {
            Assert.That(_run.Report.OutsideCount, Is.EqualTo(0));
            Assert.That(_run.Report.ClampHits, Is.EqualTo(0));
            Assert.That(_run.Report.NanCount, Is.EqualTo(0));
        }

        /// <summary>The probe's configurations, which CI does not run, all make valid scenes: a word misspelt or a value
        /// out of range is caught here, not minutes into a measurement.</summary>
        [Test]
        public void EveryProbeConfigurationMakesAValidScene()
        {
            var configurations = typeof(LockExchangeProbe).GetCustomAttributes(typeof(TestFixtureAttribute), false)
                .Select(a => (string)((TestFixtureAttribute)a).Arguments[0]!).ToList();
            Assert.That(configurations, Is.Not.Empty);
            foreach (string configuration in configurations)
                Assert.That(() => LockExchangeProbe.Configure(configuration, out _), Throws.Nothing, configuration);
        }

        internal sealed record Exchange(double Depth, double WaterSpeed, double OilSpeed, double WaterTheory, double OilTheory, DiagnosticsReport Report)
        {
            /// <summary>The fronts' speeds measured by their heads (<see cref="LockExchange.Heads"/>), m/s.</summary>
            public double WaterHeadSpeed { get; init; }

            public double OilHeadSpeed { get; init; }
        }

        /// <summary>Runs the exchange for <paramref name="seconds"/>, sampling both fronts every frame, and prints their
        /// fitted speeds beside Benjamin's for the liquids' measured depth.</summary>
        internal static Exchange Run(FluidSceneDescription scene, string name, double seconds)
        {
            var s = scene.Settings;
            var container = scene.Container;
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var rows = sim.PhaseRows;
            uint water = (uint)Enumerable.Range(0, rows.Count).OrderByDescending(k => rows[k].RestDensity).First();
            uint oil = (uint)Enumerable.Range(0, rows.Count).OrderBy(k => rows[k].RestDensity).First();
            var particles = new Particle[sim.ParticleCount];
            var times = new List<double>();
            var waterFront = new List<double>();
            var oilFront = new List<double>();
            var waterHead = new List<double>();
            var oilHead = new List<double>();
            void Sample()
            {
                sim.Particles.GetData(particles);
                var fronts = LockExchange.Fronts(particles, container.Position, water, oil, s.SmoothingRadius);
                var heads = LockExchange.Heads(particles, container.Position, water, oil);
                times.Add(sim.SimulatedTime);
                waterFront.Add(fronts.Heavy);
                oilFront.Add(-fronts.Light);
                waterHead.Add(heads.Heavy);
                oilHead.Add(-heads.Light);
            }
            Sample();
            var start = Energies(sim, particles);
            var line = start;
            (double Kinetic, double Potential)? windowStart = null, windowEnd = null;
            int frames = 0, substeps = 0;
            while (sim.SimulatedTime < seconds - 1e-6)
            {
                substeps += sim.Step(1f / 60f).Substeps;
                frames++;
                Sample();
                int k = times.Count - 1;
                if (k % 12 == 0)
                {
                    var now = Energies(sim, particles);
                    TestContext.Progress.WriteLine($"{name}: t={times[k]:F2} s, water front {1000 * waterFront[k]:F1} mm and oil front {1000 * oilFront[k]:F1} mm from the lock " +
                        $"(heads {1000 * waterHead[k]:F1} and {1000 * oilHead[k]:F1} mm)" +
                        (s.PressureSolver == PressureSolver.Dfsph ? Budget(start, line, now) + Solves(sim, particles, container) : ""));
                    line = now;
                }
                if (Math.Abs(times[k] - BudgetWindow.Start) < 1e-3) windowStart = Energies(sim, particles);
                if (Math.Abs(times[k] - BudgetWindow.End) < 1e-3) windowEnd = Energies(sim, particles);
            }
            var report = sim.ReadDiagnostics();

            var densities = new Vector4[sim.ParticleCount];
            sim.Densities.GetData(densities);
            double volume = 0;
            for (int i = 0; i < particles.Length; i++) volume += rows[(int)particles[i].Phase].ParticleMass / densities[i].X;
            double depth = volume / (container.Size.X * container.Size.Z), g = s.Gravity.Length();
            double rw = rows[(int)water].RestDensity, ro = rows[(int)oil].RestDensity;
            double uw = LockExchange.FrontSpeed(g, depth, rw, ro, ro), uo = LockExchange.FrontSpeed(g, depth, rw, ro, rw);
            var w = LockExchange.Speed(times, waterFront, 0.05, 0.22);
            var o = LockExchange.Speed(times, oilFront, 0.05, 0.22);
            // The heads read a steady front about half a column ahead of its nose: the same window, moved by that.
            double ahead = LockExchange.HeadColumn / 2;
            var wh = LockExchange.Speed(times, waterHead, 0.05 + ahead, 0.22 + ahead);
            var oh = LockExchange.Speed(times, oilHead, 0.05 + ahead, 0.22 + ahead);
            TestContext.Progress.WriteLine(
                $"lock exchange ({name}: {s.PressureSolver}, {s.SmoothingKernel} at {s.SmoothingRadius / s.ParticleSpacing:F2} spacings, " +
                $"spacing {1000 * s.ParticleSpacing:F2} mm, {container.Friction} walls), N={sim.ParticleCount}, depth {1000 * depth:F1} mm: " +
                $"water front {w.Speed:F4} m/s over {w.Samples} frames (Benjamin's {uw:F4}: Froude {w.Speed / (2 * uw):F3}), " +
                $"oil front {o.Speed:F4} m/s over {o.Samples} frames (Benjamin's {uo:F4}: Froude {o.Speed / (2 * uo):F3}); " +
                $"clamp hits {report.ClampHits}, outside {report.OutsideCount}; by the heads ({LockExchange.HeadShare:P0} of the depth over " +
                $"{1000 * LockExchange.HeadColumn:F0} mm): water {wh.Speed:F4} m/s (Froude {wh.Speed / (2 * uw):F3}), oil {oh.Speed:F4} m/s (Froude {oh.Speed / (2 * uo):F3})" +
                (s.PressureSolver == PressureSolver.Dfsph && windowStart is { } a && windowEnd is { } b
                    ? $"; kinetic share of the potential energy released from {BudgetWindow.Start} to {BudgetWindow.End} s: {(b.Kinetic - a.Kinetic) / (a.Potential - b.Potential):P1}, at {(double)substeps / frames:F2} sub-steps a frame"
                    : ""));
            return new Exchange(depth, w.Speed, o.Speed, uw, uo, report) { WaterHeadSpeed = wh.Speed, OilHeadSpeed = oh.Speed };
        }

        /// <summary>When the energy budget is taken, s: both fronts cross the fit's window, after the start's settling and
        /// before either nears an end wall.</summary>
        static readonly (double Start, double End) BudgetWindow = (0.4, 1.2);

        /// <summary>The particles' kinetic energy and their potential energy above the origin, J.</summary>
        static (double Kinetic, double Potential) Energies(FluidSimulation sim, Particle[] particles)
        {
            double kinetic = 0, potential = 0;
            Vector3 g = sim.Scene.Settings.Gravity;
            foreach (Particle p in particles)
            {
                double m = sim.PhaseRows[(int)p.Phase].ParticleMass;
                kinetic += 0.5 * m * p.Velocity.LengthSquared();
                potential -= m * Vector3.Dot(g, p.Position);
            }
            return (kinetic, potential);
        }

        /// <summary>
        /// Where the potential energy the exchange releases goes. Benjamin's current that loses no energy turns all of it
        /// into the two layers' motion, so in an inviscid run the kinetic share of what was released since the line before
        /// is what the scheme kept. Under DFSPH only: WCSPH's compression stores energy this budget does not count, and the
        /// start's settling releases some at every solver, so the first lines read high or low.
        /// </summary>
        static string Budget((double Kinetic, double Potential) start, (double Kinetic, double Potential) before, (double Kinetic, double Potential) now)
        {
            double released = start.Potential - now.Potential, releasedSince = before.Potential - now.Potential;
            return $"; energy released {1000 * released:F2} mJ, kinetic {1000 * now.Kinetic:F2} mJ, since the line before " +
                $"{(now.Kinetic - before.Kinetic) / releasedSince:P0} of the release kept";
        }

        /// <summary>DFSPH's solves since the last call and the pressure on the floor beside what the liquids weigh: a solve
        /// that cannot reach its tolerance runs out of iterations while its warm-started pressure climbs.</summary>
        static string Solves(FluidSimulation sim, Particle[] particles, ContainerDescription container)
        {
            var report = sim.ReadDiagnostics();
            var densities = new Vector4[sim.ParticleCount];
            sim.Densities.GetData(densities);
            double floor = container.Position.Y - container.Size.Y / 2, spacing = sim.Scene.Settings.ParticleSpacing, mass = 0, pressure = 0;
            int bottom = 0;
            for (int i = 0; i < particles.Length; i++)
            {
                mass += sim.PhaseRows[(int)particles[i].Phase].ParticleMass;
                if (particles[i].Position.Y - floor >= spacing) continue;
                pressure += densities[i].Y;
                bottom++;
            }
            double weight = mass * sim.Scene.Settings.Gravity.Length() / (container.Size.X * container.Size.Z);
            return $"; solves: density {report.DensitySolveIterations:F1} iterations ({report.DensitySolvesCutOff:P0} cut off), " +
                $"divergence {report.DivergenceSolveIterations:F1} ({report.DivergenceSolvesCutOff:P0}); bottom row's pressure " +
                $"{pressure / Math.Max(1, bottom):F0} Pa, the liquids' weight over the floor {weight:F0} Pa";
        }
    }
}
