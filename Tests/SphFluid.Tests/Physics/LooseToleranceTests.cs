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
    /// DFSPH held only loosely incompressible, with the Chebyshev-accelerated solve: OilAndWater at a 1 % density
    /// tolerance, the loosest the study runs. Nothing drives the closed tank, so its mechanical energy may at no frame rise
    /// above the spawn's, and a looser tolerance must not cost more iterations than a tighter one.
    /// <para>With both solves accelerated at every tolerance it failed both. At the scene's own 4 160 particles (13.4
    /// spacings deep) 1 % took 2 + 10 iterations a sub-step against 0.1 %'s 4 + 2, and the fluid bounced, its potential
    /// energy 0.06 J above the spawn's at 0.1 s; at 25 900 (24.4 spacings) 1 % took 2 + 25. A loose constant-density solve
    /// stops partway through the polynomial, and its overshoots stay in the velocities (ChebyshevBounds.DensityCrossover).
    /// Now the constant-density solve takes the Jacobi steps at a tolerance that loose for the depth, and 1 % takes 2 + 2
    /// at 4 160 and about 5 + 3 at 25 900.</para>
    /// <para>At 25 900 the run must also stay healthy with no clamp hit. While the accelerated solve's interval ended at
    /// the lattice's stiffest wave with a 5 % margin, the accelerated constant-density solve amplified a loosely held
    /// fluid's stiffer waves: unhealthy at 0.033 s here (42 % largest compression), and on an H200 at 100k and 250k
    /// particles at 0.037 s (62 and 69 m/s; Headless/figures/gpu-h200-study.txt); the top is now at least the relaxed
    /// Jacobi step's bound (ChebyshevBounds.JacobiLimit). These runs no longer take accelerated constant-density steps at
    /// 1 %, which a fluid does only past 60 spacings deep, beyond what CI runs; with that bound removed (a hand edit) this
    /// case and 25 900 at 0.35 and 0.2 %, accelerated, stayed healthy for 0.1 s, so ChebyshevBoundsTests alone hold it.
    /// The H200's 100k and 250k rows at 1 % ran healthy for 1 s at 8e65ea2 (Headless/figures/gpu-h200-half-support-cells.txt).</para>
    /// <para>Each liquid's compression, averaged over the frames from 0.033 s, must be within the tolerance. The solve
    /// stops at 0.9 of it on a first-order prediction (FluidSimulation.DensityPredictionMargin); with the accelerated
    /// constant-density solve at 25 900 particles the second-order part it misses was more than that tenth (0.950 % for
    /// the water, 1.012 % for the oil), with the Jacobi steps it is not (0.847 and 0.883 %).</para>
    /// </summary>
    [Category(TestProcesses.LongRuns)]
    public sealed class LooseToleranceTests
    {
        const float Loose = 1f, Tight = 0.1f;

        sealed class Run
        {
            public int Particles;
            public double DepthInSpacings, EnergyRise = double.MinValue, Largest, Iterations;
            public bool Accelerated;
            public HealthProblem? Problem;
            public int ClampHits, Lost;
            public string[] Names = Array.Empty<string>();
            public double[] Compression = Array.Empty<double>();
            public string Last = "";
        }

        static readonly Dictionary<(float, float), Run> Runs = new Dictionary<(float, float), Run>();

        /// <summary>OilAndWater at <paramref name="tolerance"/> % and <paramref name="scale"/> times its particles for
        /// <paramref name="frames"/> 60 Hz frames; iterations (both solves, per sub-step) and compression averaged over the
        /// frames from the second on.</summary>
        static Run Simulate(float tolerance, float scale, int frames)
        {
            if (Runs.TryGetValue((tolerance, scale), out var cached)) return cached;
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            var choice = new SolverChoice { Solver = PressureSolver.Dfsph, Iteration = SolverIteration.Chebyshev, DensityTolerance = tolerance };
            Assert.That(choice.ApplyTo(scene, $"DFSPH OilAndWater at {tolerance} %"), Is.Null, "the scene's own DFSPH settings");
            if (scale != 1f) ParticleScaling.ScaleBy(scene, scale);
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var run = new Run
            {
                Particles = sim.ParticleCount, Accelerated = sim.AcceleratesDensitySolve,
                DepthInSpacings = SpawnLayout.Depth(SpawnLayout.Generate(scene), scene.Settings.Gravity, scene.Settings.ParticleSpacing) / scene.Settings.ParticleSpacing,
            };
            var health = new HealthCheck(scene, sim.ParticleCount);
            var gravity = (System.Numerics.Vector3)scene.Settings.Gravity;
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            double spawnEnergy = FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity);
            var report = sim.ReadDiagnostics();
            run.Compression = new double[report.Phases.Count];
            int samples = 0;
            for (int frame = 1; frame <= frames && run.Problem == null; frame++)
            {
                sim.Step(1f / 60f);
                report = sim.ReadDiagnostics();
                run.Problem = health.Check(report);
                sim.Particles.GetData(particles);
                run.EnergyRise = Math.Max(run.EnergyRise, FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity) - spawnEnergy);
                if (frame < 2) continue;
                samples++;
                run.Iterations += report.DensitySolveIterations + report.DivergenceSolveIterations;
                for (int k = 0; k < run.Compression.Length; k++) run.Compression[k] += report.Phases[k].AverageDensityError;
                run.Largest = Math.Max(run.Largest, report.Phases.Max(p => (double)p.MaxDensityError));
            }
            samples = Math.Max(samples, 1);
            run.Iterations /= samples;
            for (int k = 0; k < run.Compression.Length; k++) run.Compression[k] /= samples;
            run.Names = report.Phases.Select(p => p.Name).ToArray();
            run.ClampHits = report.ClampHits;
            run.Lost = sim.ParticleCount - report.ParticleCount;
            run.Last = report.ToString();
            TestContext.Progress.WriteLine($"DFSPH (Chebyshev) OilAndWater at {tolerance} %, N={run.Particles}, {run.DepthInSpacings:F1} spacings deep, " +
                $"constant-density solve {(run.Accelerated ? "accelerated" : "Jacobi")}: " +
                (run.Problem == null ? $"healthy for {frames} frames" : $"unhealthy: {run.Problem}") +
                $"; iterations a sub-step from the second frame {run.Iterations:F2}; average compression: " +
                string.Join(", ", run.Names.Select((n, k) => $"{n} {100 * run.Compression[k]:F3} %")) +
                $", largest {100 * run.Largest:F1} %; mechanical energy {spawnEnergy:F4} J at spawn, largest rise {run.EnergyRise:F4} J; {run.Last}");
            Runs[(tolerance, scale)] = run;
            return run;
        }

        /// <summary>At six times the scene's particles (25 900; the spawn settles and the lock exchange starts in the
        /// first 0.1 s).</summary>
        [Test]
        public void OnePercentAtSixTimesTheScene_StaysHealthy_GainsNoEnergy_AndHoldsTheTolerance()
        {
            var run = Simulate(Loose, 6f, 6);
            Assert.That(run.Problem, Is.Null, "the health check");
            Assert.That(run.ClampHits, Is.EqualTo(0));
            Assert.That(run.Lost, Is.EqualTo(0));
            Assert.That(run.EnergyRise, Is.LessThanOrEqualTo(0.0), "no work is done on the closed tank");
            AssertWithinTheTolerance(run);
        }

        static void AssertWithinTheTolerance(Run run)
        {
            for (int k = 0; k < run.Compression.Length; k++)
                Assert.That(run.Compression[k], Is.LessThanOrEqualTo(0.01 * Loose), $"{run.Names[k]}'s average compression");
        }

        /// <summary>At the scene's own size for 0.3 s: 1 % gains no energy (0.06 J above the spawn with the accelerated
        /// constant-density solve).</summary>
        [Test]
        public void OnePercentAtTheScenesSize_GainsNoEnergy_AndHoldsTheTolerance()
        {
            var run = Simulate(Loose, 1f, 18);
            Assert.That(run.Accelerated, Is.False, "1 % at 13.4 spacings is past the crossover");
            Assert.That(run.Problem, Is.Null, "the health check");
            Assert.That(run.EnergyRise, Is.LessThanOrEqualTo(0.0), "no work is done on the closed tank");
            AssertWithinTheTolerance(run);
        }

        /// <summary>At the scene's own size for 0.3 s: 1 % takes fewer iterations a sub-step than 0.1 % (2 + 10 against
        /// 4 + 2 with the accelerated constant-density solve at both).</summary>
        [Test]
        public void OnePercentAtTheScenesSize_TakesFewerIterationsThanATenth()
        {
            var loose = Simulate(Loose, 1f, 18);
            var tight = Simulate(Tight, 1f, 18);
            Assert.That(tight.Accelerated, Is.True, "0.1 % at 13.4 spacings is within the crossover");
            Assert.That(loose.Iterations, Is.LessThan(tight.Iterations), "iterations a sub-step, both solves");
        }
    }
}
