using System;
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
    /// DFSPH held only loosely incompressible: OilAndWater at a 1 % density tolerance, the loosest the study runs, with the
    /// Chebyshev-accelerated solve, at six times the scene's particles (25 900; the spawn settles and the lock exchange
    /// starts in the first 0.1 s). Loosely held, the fluid is disordered, and its stiffest neighbourhoods carry pressure
    /// waves above the ordered lattice's. While the accelerated solve's interval ended at the lattice's stiffest wave with
    /// a 5 % margin, it amplified them: unhealthy at 0.033 s here (42 % largest compression), and on an H200 at 100k and
    /// 250k particles at 0.037 s (62 and 69 m/s; Headless/figures/gpu-h200-study.txt), while the Jacobi solve ran clean.
    /// Its top is now at least the relaxed Jacobi step's own stability bound (ChebyshevBounds.JacobiLimit). The run must
    /// stay healthy with no clamp hit, and since nothing drives the closed tank, its mechanical energy may at no frame
    /// rise above the spawn's (before the fix: 0.6 J of kinetic energy gained by 0.033 s).
    /// <para>Each liquid's compression, averaged over the frames from 0.033 s, is printed, not asserted: 0.950 % for the
    /// water and 1.012 % for the oil against the 1 % asked for. The solve stops at 0.9 of the tolerance on a first-order
    /// prediction (FluidSimulation.DensityPredictionMargin), and at this tolerance the second-order part it misses is
    /// more than the tenth that margin allows.</para>
    /// </summary>
    public sealed class LooseToleranceTests
    {
        const float Tolerance = 1f;

        [Test]
        public void ChebyshevAtOnePercent_StaysHealthy_AndGainsNoEnergy()
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            var choice = new SolverChoice { Solver = PressureSolver.Dfsph, Iteration = SolverIteration.Chebyshev, DensityTolerance = Tolerance };
            Assert.That(choice.ApplyTo(scene, "DFSPH OilAndWater at 1 %"), Is.Null, "the scene's own DFSPH settings");
            ParticleScaling.ScaleBy(scene, 6);
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            var health = new HealthCheck(scene, sim.ParticleCount);
            HealthProblem? problem = null;
            var gravity = (System.Numerics.Vector3)scene.Settings.Gravity;
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            double spawnEnergy = FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity), energyRise = double.MinValue;
            var report = sim.ReadDiagnostics();
            var compression = new double[report.Phases.Count];
            double largest = 0;
            int samples = 0;
            for (int frame = 1; frame <= 6 && problem == null; frame++)
            {
                sim.Step(1f / 60f);
                report = sim.ReadDiagnostics();
                problem = health.Check(report);
                sim.Particles.GetData(particles);
                energyRise = Math.Max(energyRise, FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity) - spawnEnergy);
                if (frame < 2) continue;
                samples++;
                for (int k = 0; k < compression.Length; k++) compression[k] += report.Phases[k].AverageDensityError;
                largest = Math.Max(largest, report.Phases.Max(p => (double)p.MaxDensityError));
            }
            var names = report.Phases.Select(p => p.Name).ToArray();
            TestContext.Progress.WriteLine($"DFSPH (Chebyshev) OilAndWater at 1 %, N={sim.ParticleCount}: " +
                (problem == null ? "healthy for 0.1 s" : $"unhealthy: {problem}") + "; average compression from 0.033 s: " +
                string.Join(", ", names.Select((n, k) => $"{n} {100 * compression[k] / Math.Max(samples, 1):F3} %")) +
                $", largest {100 * largest:F1} %; mechanical energy {spawnEnergy:F4} J at spawn, largest rise {energyRise:F4} J; {report}");
            Assert.That(problem, Is.Null, "the health check");
            Assert.That(report.ClampHits, Is.EqualTo(0));
            Assert.That(report.ParticleCount, Is.EqualTo(sim.ParticleCount));
            Assert.That(energyRise, Is.LessThanOrEqualTo(0.0), "no work is done on the closed tank");
        }
    }
}
