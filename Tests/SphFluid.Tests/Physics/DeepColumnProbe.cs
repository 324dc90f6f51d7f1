using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// Issue #8's 1M case on a CPU: what decides DFSPH's iterations is the fluid's depth in spacings (the longest pressure
    /// wave, <see cref="SolverIterationScalingTests"/>), and the default oil-and-water scene at 1M particles is about 80
    /// spacings deep. A water column of that depth on a footprint of 6 by 6 spacings (and of 12 by 12, to see what the
    /// footprint changes; and under Chebyshev of 40 and 120 spacings, to see the growth with depth past
    /// <see cref="ChebyshevBounds.TunedDepth"/>), spawned at rest and run for 0.5 s at
    /// the scene's kernel settings (Wendland C2 at 2.85 spacings, relaxed to 0.3) and the target's (0.1 % density
    /// tolerance, at most 100 iterations a solve) under each iteration scheme, prints
    /// its constant-density iterations a sub-step, the share of solves the cap cut off, its compression and its health.
    /// A measurement run by name, `bash Headless/test.sh --filter FullyQualifiedName~DeepColumnProbe`, which CI does not run.
    /// </summary>
    [Explicit("a measurement, not a check: run it by name")]
    [TestFixture(SolverIteration.Jacobi, 6, 80)]
    [TestFixture(SolverIteration.Chebyshev, 6, 80)]
    [TestFixture(SolverIteration.Jacobi, 12, 80)]
    [TestFixture(SolverIteration.Chebyshev, 12, 40)]
    [TestFixture(SolverIteration.Chebyshev, 12, 80)]
    [TestFixture(SolverIteration.Chebyshev, 12, 120)]
    public sealed class DeepColumnProbe
    {
        const float Spacing = 0.025f;
        readonly SolverIteration _iteration;
        readonly int _footprint;
        readonly int _depth;

        public DeepColumnProbe(SolverIteration iteration, int footprint, int depth)
        {
            _iteration = iteration;
            _footprint = footprint;
            _depth = depth;
        }

        [Test]
        public void IterationsOfADeepColumn()
        {
            var settings = new FluidSettings
            {
                // OilAndWater's kernel, support and relaxed Jacobi step.
                ParticleSpacing = Spacing, SmoothingKernel = KernelFamily.WendlandC2, SmoothingRadius = 2.85f * Spacing, SolverRelaxation = 0.3f,
                MaxSubsteps = 200, PressureSolver = PressureSolver.Dfsph, DensityTolerance = 0.1f, SolverIteration = _iteration, MaxSolverIterations = 100,
            };
            var water = new Vector3(_footprint * Spacing, _depth * Spacing, _footprint * Spacing);
            var container = new Vector3(water.X, water.Y + 0.1f, water.Z);
            var scene = SolverScenes.Scene(settings, container,
                SolverScenes.Box("Water", SolverScenes.Water(viscosity: 0.001f), new Vector3(0f, -0.5f * container.Y + 0.5f * water.Y, 0f), water));
            var watch = System.Diagnostics.Stopwatch.StartNew();
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var health = new HealthCheck(scene, sim.ParticleCount);
            HealthProblem? problem = null;
            DiagnosticsReport report = sim.ReadDiagnostics();
            int frames = 0;
            var averages = new SolveAverages(0.15);
            while (sim.SimulatedTime < 0.5 - 1e-6 && problem == null)
            {
                sim.Step(1f / 60f);
                if (++frames % 6 != 0) continue;
                report = sim.ReadDiagnostics();
                problem = health.Check(report);
                averages.Add(_iteration.ToString(), sim.SimulatedTime, report);
            }
            TestContext.Progress.WriteLine($"{_iteration}, a column of {_depth} spacings on {_footprint} by {_footprint}, N = {sim.ParticleCount}: " +
                (problem == null ? "healthy for 0.5 s" : $"unhealthy: {problem}") + averages.Summary("0.2 to 0.5 s", report.Phases[0].Name) +
                $"; {watch.Elapsed.TotalSeconds:F1} s wall");
            Assert.That(report.ParticleCount, Is.EqualTo(sim.ParticleCount));
        }
    }
}
