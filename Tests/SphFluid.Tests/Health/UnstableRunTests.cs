using System;
using System.IO;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Health
{
    /// <summary>The health check can fail: configurations that really are unstable are caught, and the runner exits 4
    /// naming the first bad time, phase and figure.</summary>
    public sealed class UnstableRunTests
    {
        /// <summary>Sub-steps five times the CFL limit, forced past the adaptive controller: a pool at rest blows up.</summary>
        [Test]
        public void StepsFiveTimesTheCflLimit_AreCaughtByTheHealthCheck()
        {
            var settings = SolverScenes.Coarse(0.04f);
            var tank = new Vector3(0.48f, 0.4f, 0.16f);
            var scene = SolverScenes.Scene(settings, tank,
                SolverScenes.Box("Water", SolverScenes.Water(), new Vector3(0f, -0.12f, 0f), new Vector3(0.48f, 0.16f, 0.16f)));
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, scene))
            {
                var check = new HealthCheck(scene);
                var particles = new Particle[sim.ParticleCount];
                float dt = 5f * settings.CflNumber * settings.SmoothingRadius / sim.TimeStep.SpeedOfSound; // 15.6 ms
                HealthProblem? problem = null;
                for (int frame = 0; frame < 30 && problem == null; frame++)
                {
                    sim.StepFixed(1, dt);
                    sim.Particles.GetData(particles);
                    problem = check.Check(sim.ReadDiagnostics(), particles);
                }
                TestContext.Out.WriteLine(problem?.Message);
                Assert.That(problem, Is.Not.Null, "a step five times the CFL limit must not pass as healthy");
                Assert.That(problem.Time, Is.LessThan(0.5));
                Assert.That(problem.Message, Does.StartWith("unhealthy at t = "));
            }
        }

        /// <summary>
        /// The PlayModeTest scene on a device that runs every sub-step 8 times longer than planned (a broken step
        /// controller, <see cref="OversteppingDevice"/>): the particles fly, and the runner stops with exit 4 at the first
        /// frame the time step's speed read-back exceeds the bound, between the 0.25 s diagnostics lines.
        /// </summary>
        [Test]
        public void SimulateExitsFourOnTheFirstUnhealthyState()
        {
            string scene = RunnerPaths.Scene("PlayModeTest");
            string outDir = RunnerPaths.ScratchFolder("unhealthy");
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            var run = new SimulateRun(SimulateOptions.Parse(new[] { scene, "--seconds", "0.5", "--frames-every", "1", "--out", outDir }), stdout, stderr)
            {
                Device = new OversteppingDevice(GpuTestDevice.Shared, 8f), InteractiveProgress = false,
            };

            int code = run.Execute();

            TestContext.Out.WriteLine(stderr.ToString());
            Assert.That(code, Is.EqualTo(ExitCodes.SimulationFailed), stdout.ToString());
            Assert.That(stderr.ToString(), Does.Contain("simulate: unhealthy at t = ").And.Contains("phase '").And.Contains("exceeds the bound"));
            Assert.That(run.Summary.OrFail("the run's summary").SimulatedSeconds, Is.LessThan(0.1),
                "the run stops at the first unhealthy frame, long before the next 0.25 s diagnostics line");
            Assert.That(File.ReadAllText(Path.Combine(outDir, "summary.txt")), Does.Contain("result: FAILED: unhealthy at t = "));
        }

        /// <summary>An explicit mass 1.2 times the derived one, scaled to twice the particles: still 1.2 times the
        /// (smaller) derived mass, so the scene stays valid (unscaled, it started at 2.4 times: 702 m/s in one sub-step).</summary>
        [Test]
        public void ParticlesScale_KeepsAnExplicitMassAtItsRatioToTheDerivedOne()
        {
            var scene = SolverScenes.Scene(SolverScenes.Coarse(0.04f), new Vector3(0.48f, 0.4f, 0.16f),
                SolverScenes.Box("Water", SolverScenes.Water(), new Vector3(0f, -0.12f, 0f), new Vector3(0.48f, 0.16f, 0.16f)));
            float derived = scene.BuildPhaseTable()[0].ParticleMass;
            scene.SpawnBoxes[0].Phase.ParticleMass = 1.2f * derived;

            ParticleScaling.ScaleBy(scene, 2.0);

            var errors = scene.Validate().Select(e => e.Message).ToArray();
            Assert.That(errors, Is.Empty);
            float derivedScaled = (float)(1000.0 / scene.RestNumberDensity());
            Assert.That(derivedScaled, Is.EqualTo(derived / 2f).Within(derived * 1e-3f));
            // The derived mass follows the volume each particle stands for (the box's cell, 2.4 % off s^3 here).
            float derivedOfTheCell = (float)DerivedParticleMass.Of(scene, scene.SpawnBoxes[0].Phase);
            Assert.That(scene.SpawnBoxes[0].Phase.ParticleMass / derivedOfTheCell, Is.EqualTo(1.2f).Within(1e-4f));
        }
    }
}
