using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// DiagnosticsReport.DensitySolvesCutOff and DivergenceSolvesCutOff: the share of each kind of DFSPH solve since the
    /// previous report that ran out of its recorded rounds before its tolerance. Without it a tolerance the iteration cap cannot reach looks met, at the capped cost.
    /// A small resting block (192 particles, 4 cm spacing) settles for half a second, then the share of the next 10 frames is
    /// read (the report before them restarts the counts).
    /// </summary>
    public sealed class SolvesCutOffTests
    {
        const float Frame = 1f / 60f;
        const int SettleFrames = 30, MeasuredFrames = 10;

        static FluidSceneDescription RestingBlock(PressureSolver solver)
        {
            var settings = SolverScenes.Coarse(0.04f);
            settings.PressureSolver = solver;
            var container = new Vector3(0.32f, 0.32f, 0.16f);
            var water = new Vector3(0.32f, 0.24f, 0.16f);
            return SolverScenes.Scene(settings, container,
                SolverScenes.Box("Water", SolverScenes.Water(), new Vector3(0f, -0.5f * container.Y + 0.5f * water.Y, 0f), water));
        }

        static DiagnosticsReport SettleThenMeasure(FluidSceneDescription scene, string name) => SettleThenMeasure(scene, name, out _);

        /// <param name="noStepSince">A report read right after, with no sub-step between: no solve since.</param>
        static DiagnosticsReport SettleThenMeasure(FluidSceneDescription scene, string name, out float noStepSince)
        {
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            for (int f = 0; f < SettleFrames; f++) sim.Step(Frame);
            sim.ReadDiagnostics();
            int substeps = 0;
            for (int f = 0; f < MeasuredFrames; f++) substeps += sim.Step(Frame).Substeps;
            var report = sim.ReadDiagnostics();
            TestContext.Progress.WriteLine($"{name}, N={sim.ParticleCount}: {substeps} sub-steps measured, rounds recorded " +
                $"{string.Join("/", sim.SolveRounds)}; {report}");
            Assert.That(report.NanCount, Is.EqualTo(0));
            var next = sim.ReadDiagnostics();
            noStepSince = next.DensitySolvesCutOff + next.DivergenceSolvesCutOff;
            return report;
        }

        /// <summary>The fold that ends each round (FoldSolveErrors) declares convergence only once a solve has made two
        /// corrections, and with two rounds the second is the last: every solve of both kinds is cut off, whatever the
        /// error.</summary>
        [Test]
        public void AtTwoIterationsEverySolveIsCutOff()
        {
            var scene = RestingBlock(PressureSolver.Dfsph);
            scene.Settings.MaxSolverIterations = 2;
            var report = SettleThenMeasure(scene, "DFSPH at most 2 iterations", out float noStepSince);
            Assert.That(report.DensitySolvesCutOff, Is.EqualTo(1f));
            Assert.That(report.DivergenceSolvesCutOff, Is.EqualTo(1f));
            Assert.That(report.ToString(), Does.Contain("(100 % cut off)"));
            Assert.That(noStepSince, Is.EqualTo(0f), "each report restarts the counts, and no solve since reads 0");
        }

        /// <summary>0.01 % is out of reach of three Jacobi steps while a loose divergence tolerance is met in two: the
        /// density solves are cut off and the divergence-free ones are not, each share reported on its own.</summary>
        [Test]
        public void ATinyDensityToleranceAtThreeIterationsCutsOffTheDensitySolvesOnly()
        {
            var scene = RestingBlock(PressureSolver.Dfsph);
            scene.Settings.MaxSolverIterations = 3;
            scene.Settings.DensityTolerance = 0.01f;
            scene.Settings.DivergenceTolerance = 100f;
            var report = SettleThenMeasure(scene, "DFSPH 0.01 %, 100 %/s, at most 3 iterations");
            Assert.That(report.DensitySolvesCutOff, Is.GreaterThan(0.9f));
            Assert.That(report.DivergenceSolvesCutOff, Is.EqualTo(0f));
        }

        /// <summary>A loose tolerance under the default cap: the block at rest converges within the rounds its budget
        /// (SolveBudget.Next) records, so no solve is cut off (measured: 2 iterations of each solve, 8 rounds
        /// recorded).</summary>
        [Test]
        public void ALooseToleranceCutsOffNoSolveOfABlockAtRest()
        {
            var scene = RestingBlock(PressureSolver.Dfsph);
            scene.Settings.DensityTolerance = 1f;
            Assert.That(scene.Settings.MaxSolverIterations, Is.EqualTo(100));
            var report = SettleThenMeasure(scene, "DFSPH 1 % at most 100 iterations");
            Assert.That(report.DensitySolveIterations, Is.GreaterThan(0f), "the solves ran");
            Assert.That(report.DensitySolvesCutOff, Is.EqualTo(0f));
            Assert.That(report.DivergenceSolvesCutOff, Is.EqualTo(0f));
            Assert.That(report.ToString(), Does.Contain("(0 % cut off)"));
        }

        [Test]
        public void WcsphReportsNoSolveCutOff()
        {
            var report = SettleThenMeasure(RestingBlock(PressureSolver.Wcsph), "WCSPH");
            Assert.That(report.DensitySolvesCutOff + report.DivergenceSolvesCutOff, Is.EqualTo(0f));
            Assert.That(report.ToString(), Does.Not.Contain("cut off"));
        }
    }
}
