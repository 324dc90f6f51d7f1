using System;
using System.Globalization;
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
    /// The shipped dam break and oil-and-water scenes under DFSPH (issue #8). The dam break is loaded from a copy of the scene
    /// file with <c>settings.PressureSolver: 1</c> (the int Unity serialises the enum as), so the scene key is read as Unity
    /// writes it. Oil and water runs WCSPH at a support DFSPH refuses, so it is switched as <c>--solver dfsph</c> switches
    /// it (SolverChoice.FitSupport: the cubic spline at 2 spacings). The dam break must stay finite and lose nothing; the
    /// oil and water must layer as <see cref="SeparationTests"/> asks of WCSPH.
    /// </summary>
    public sealed class DivergenceFreeSceneTests
    {
        const float Frame = 1f / 60f;

        static FluidSceneDescription DivergenceFree(string name)
        {
            string path = RunnerPaths.EditedScene(name, "    PressureSolver: 0", "    PressureSolver: 1");
            var scene = SceneLoader.Load(path, RunnerPaths.Project).Description;
            Assert.That(scene.Settings.PressureSolver, Is.EqualTo(PressureSolver.Dfsph), "the scene key settings.PressureSolver: 1");
            return scene;
        }

        [Test]
        public void DamBreak_StaysFiniteAndLosesNothingForTwoSeconds()
        {
            var scene = DivergenceFree("DamBreak");
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            int spawned = sim.ParticleCount;
            double steps = 0;
            int frames = 0;
            while (sim.SimulatedTime < 2.0 - 1e-6)
            {
                sim.Step(Frame);
                steps += sim.LastStep.Substeps;
                frames++;
            }
            var report = sim.ReadDiagnostics();
            TestContext.Progress.WriteLine($"DFSPH dam break, N={spawned}: {steps / frames:F2} sub-steps per frame; {report}");
            Assert.That(report.NanCount, Is.EqualTo(0));
            Assert.That(report.OutsideCount, Is.EqualTo(0));
            Assert.That(report.ParticleCount, Is.EqualTo(spawned));
            Assert.That(report.TotalMass, Is.GreaterThan(0.0));
        }

        [Test, Ignore("Not met: measured layering 0.870 at 6 s and 21.9 % of the floor layer still oil, 0 clamp hits (simulate --solver " +
                      "dfsph --seconds 6; this test takes about 7 minutes on lavapipe); WCSPH reaches 0.95 at 4.0 s with 0 % oil on the floor. The oil rises but the interface freezes tilted, a " +
                      "wedge of oil on the floor at one end. Before the wall particles became unknowns of the solves: 0.842, 23.6 %, 63 clamp " +
                      "hits. Not the wall friction (21 % with slip walls at half the particles, 4 s), nor the viscosity (both phases' / 10: 28.9 % " +
                      "at half the particles), nor the spawn jitter (moved onto the constraint before t = 0: 26.4 % at 6 s), nor the solver's " +
                      "stiffness (27-29 % at half the particles for 1 % and 0.1 % tolerances). Particle shifting after each sub-step passes " +
                      "the bars (A = 2: 0.95 at 4 s, 1 % floor oil) only by stirring the fluid (kinetic energy 0.09 J at 6 s against 0.003 J); " +
                      "so did a wall model that dropped wall particles with fewer than 8 fluid neighbours (0.974, 0.3 %, but 0.13 J). " +
                      "Later probes, floor-layer oil at half the particles and 4 s (19.5 % as shipped, layering 0.79; WCSPH 0 %, 0.97): " +
                      "without Drift's wall contact 6.8 % (0.91), with it only for particles closer to the walls than a flat-wall particle " +
                      "at rest 10.6 % (0.89); at full scale and 6 s both leave 19 % and 18 % (0.90), 57 of the 68 floor-oil particles " +
                      "within one spacing of the front or back wall: the oil stays in the floor's edges along the thin container's front " +
                      "and back walls, 0.69 spacings from both walls (the floor's middle row: 0.60) at 1741 Pa against 1563 Pa. Stiffer " +
                      "is worse (0.01 % tolerance: 26.8 %; 1 %: 16 %); not the sub-step (1 ms: 24.5 %), the divergence-free solve " +
                      "(off: 18.1 %), the walls' sampling (half a spacing: 18.7 %) nor shifting at a fixed speed scale (21.6 %); " +
                      "Akinci's mirrored walls: 33.3 %. The papers' full Jacobi step overshoots the lattice's stiffest pressure waves " +
                      "(SolverRelaxation: lambda_max 2.82), and a compression-only solve never takes an overshoot back; relaxed to " +
                      "1 / lambda_max (SolverRelaxation 0.355) the floor oil falls to 15 % at 4.5 s (layering 0.88, still settling " +
                      "slowly), at 0.6 to 13 % and at 0.4 to 11 % at half the particles and 4 s, at 3.2 times the resting tank's " +
                      "constant-density iterations. Relaxed with a 1 % tolerance: 13 % at 6 s, layering 0.93, in 281 s of wall time, its " +
                      "interface frozen 49 mm tilted as WCSPH's was with the same kernel (50-52 mm): the cubic spline's lattice at " +
                      "DFSPH's 2 spacings. Wendland C2 at 2 spacings diverges in the first frame; at 2.85 see " +
                      "FluidSettings.MaxDivergenceFreeSupportRatio.")]
        public void DefaultOilAndWater_LayersFullyWithin6Seconds_AndNoOilStaysOnTheFloor()
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH OilAndWater");
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            double reached = double.NaN, next = 0.5;
            FluidMeasures? last = null;
            int water = Phase(sim, "Water"), oil = Phase(sim, "Oil");
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            var s = scene.Settings;
            while (sim.SimulatedTime < 6.0 - 1e-6)
            {
                sim.Step(Frame);
                if (sim.SimulatedTime < next - 1e-6) continue;
                next += 0.5;
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                last = FluidMeasures.Measure(sim.SimulatedTime, particles, densities, sim.PhaseRows, scene.Container, s.Gravity, s.ParticleSpacing, s.SmoothingRadius);
                TestContext.Progress.WriteLine(string.Format(CultureInfo.InvariantCulture, "t={0:F2} s layering {1:F3} oil floor {2:F1} %, {3}",
                    sim.SimulatedTime, last.LayeringIndex, 100 * last.Phases[oil].FloorShare, sim.LastStep));
                if (double.IsNaN(reached) && last.LayeringIndex >= 0.95) reached = sim.SimulatedTime;
            }
            var report = sim.ReadDiagnostics();
            Assert.That(last, Is.Not.Null, "measured every half second");
            TestContext.Progress.WriteLine($"DFSPH OilAndWater: layering 0.95 reached at {reached:F2} s; at 6 s {last.LayeringIndex:F3}, " +
                $"oil floor share {100 * last.Phases[oil].FloorShare:F2} %; {report}");
            Assert.That(reached, Is.LessThanOrEqualTo(6.0 + 1e-5), "layering index >= 0.95 within 6 simulated seconds");
            Assert.That(last.Phases[oil].FloorShare, Is.LessThan(0.02), "less than 2 % of the floor layer is oil");
            Assert.That(last.Phases[oil].MeanHeight, Is.GreaterThan(last.Phases[water].MeanHeight));
            Assert.That(report.OutsideCount, Is.EqualTo(0));
            Assert.That(report.NanCount, Is.EqualTo(0));
        }

        static int Phase(FluidSimulation sim, string name)
        {
            for (int k = 0; k < sim.Phases.Count; k++) if (sim.Phases[k].Name == name) return k;
            throw new ArgumentException(name);
        }
    }
}
