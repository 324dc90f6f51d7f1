using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The shipped dam break and oil-and-water scenes under DFSPH (issue #8). The dam break is loaded from a copy of the scene
    /// file with <c>settings.PressureSolver: 1</c> (the int Unity serialises the enum as), so the scene key is read as Unity
    /// writes it. Oil and water runs WCSPH and is switched as <c>--solver dfsph</c> switches it (SolverChoice.FitSupport: its
    /// DFSPH settings, Wendland C2 at 2.85 spacings relaxed to 0.3, fit, so it keeps them). The dam break must stay finite and
    /// lose nothing; the oil and water must layer and clear the floor as <see cref="SeparationTests"/> asks of WCSPH (not its
    /// flatness bar, which DFSPH misses: see the test).
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

        /// <summary>Issue #8's bar for DFSPH, #5's layering: index at least 0.95 and under 2 % of the floor layer oil within 6 s,
        /// with no clamp hit (measured: both at 3.0 s, 0.958 and 1.33 %, with the walls weighed by their lattice cells; 2.5 s
        /// before; WCSPH takes 5.0 s). It stood ignored at 21.9 % floor
        /// oil (0.870 at 6 s) while the walls were weighed at the lattice's rest number density instead of the fluid's
        /// (SphBoundary.hlsl's WallWeight) and DFSPH was held to the cubic spline at 2 spacings; with that fixed, that
        /// configuration leaves 8.7 % (0.907) and the scene's own, Wendland C2 at 2.85 spacings relaxed to 0.3, passes. It
        /// then took 22 minutes of lavapipe for 6 s and ran only by hand; with the neighbour lists (SphNeighbourhood.hlsl) a
        /// sub-step costs a third, and the run stops at the first measure that meets both bars, as SeparationTests' does.
        /// #5's third bar, the interface within a spacing of flat, DFSPH misses by half a second: after the lock exchange's
        /// one swing (64 mm of tilt at 3.5 s) its interface creeps back without rocking, 17.2 mm at 6 s and 11.2 mm at 6.5 s,
        /// where WCSPH's crosses flat near 5.4 s (6.9 mm at 5 s; 8.7 mm with the walls' new weights, the 6 s run not repeated). Both are far more damped than the liquids' viscosity damps
        /// the tank's internal seiche (<see cref="InternalSeicheProbe"/>); the test prints the tilt it stopped at and does
        /// not assert it.
        /// <para>With the Chebyshev-accelerated solve (<see cref="SolverIteration"/>, as <c>--solver-iteration chebyshev</c> sets it)
        /// the same bars hold: measured at 2.5 s (layering 0.96, no floor oil, no clamp hit in 6 s; 3.5 constant-density
        /// iterations a sub-step against Jacobi's 11.8).</para></summary>
        [TestCase(SolverIteration.Jacobi, TestName = "DefaultOilAndWater_LayersWithin6Seconds_AndNoOilStaysOnTheFloor")]
        [TestCase(SolverIteration.Chebyshev, TestName = "DefaultOilAndWater_LayersWithin6Seconds_AndNoOilStaysOnTheFloor_Chebyshev")]
        public void DefaultOilAndWater_LayersWithin6Seconds_AndNoOilStaysOnTheFloor(SolverIteration iteration)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph, Iteration = iteration }.ApplyTo(scene, "DFSPH OilAndWater"), Is.Null,
                "the scene's own DFSPH settings");
            Assert.That(scene.Settings.SolverIteration, Is.EqualTo(iteration));
            int water = SeparationTests.Phase(scene, "Water"), oil = SeparationTests.Phase(scene, "Oil");
            var (doneAt, last, report) = SeparationTests.RunUntil(scene, 6.0,
                m => m.LayeringIndex >= 0.95 && m.Phases[oil].FloorShare < 0.02);
            TestContext.Progress.WriteLine($"DFSPH ({iteration}) OilAndWater: layering >= 0.95 and floor oil < 2 % at {doneAt:F2} s: layering {last.LayeringIndex:F3}, " +
                $"oil floor share {100 * last.Phases[oil].FloorShare:F2} %, interface tilt {1000 * last.InterfaceTilt:F1} mm; {report}");
            Assert.That(doneAt, Is.LessThanOrEqualTo(6.0 + 1e-5),
                $"within 6 simulated seconds: layering index >= 0.95 (at 6 s {last.LayeringIndex:F3}) and less than 2 % of the floor layer oil " +
                $"({100 * last.Phases[oil].FloorShare:F2} %)");
            Assert.That(last.Phases[oil].MeanHeight, Is.GreaterThan(last.Phases[water].MeanHeight));
            Assert.That(report.OutsideCount, Is.EqualTo(0));
            Assert.That(report.NanCount, Is.EqualTo(0));
            Assert.That(report.ClampHits, Is.EqualTo(0));
        }
    }
}
