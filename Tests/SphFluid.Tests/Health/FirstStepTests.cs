using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Health
{
    /// <summary>The first frame is planned with the acceleration the first force pass computed, read back once at
    /// spawn, not with gravity alone.</summary>
    public sealed class FirstStepTests
    {
        [Test]
        public void ACompressedSpawn_PlansTheFirstFrameWithItsPressureAcceleration()
        {
            var scene = SolverScenes.Scene(SolverScenes.Coarse(0.04f), new Vector3(0.48f, 0.4f, 0.16f),
                SolverScenes.Box("Water", SolverScenes.Water(), new Vector3(0f, -0.12f, 0f), new Vector3(0.48f, 0.16f, 0.16f)));
            scene.SpawnBoxes[0].Phase.ParticleMass = 1.2f * scene.BuildPhaseTable()[0].ParticleMass; // starts 20 % compressed
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, scene))
            {
                sim.ReadMotion(out float speed, out float acceleration);
                TestContext.Out.WriteLine($"first force pass: max |a| = {acceleration:G4} m/s^2; planned dt {sim.TimeStep.StableTimeStep(out string limit) * 1000:G4} ms ({limit})");
                Assert.That(acceleration, Is.GreaterThan(10f * 9.81f), "the compressed lattice pushes far harder than gravity");
                Assert.That(sim.TimeStep.MaxAcceleration, Is.EqualTo(acceleration), "the controller plans with the read-back figure");
                Assert.That(sim.TimeStep.StableTimeStep(), Is.EqualTo(Math.Min(
                    scene.Settings.CflNumber * 0.08 / sim.TimeStep.SpeedOfSound, 0.25 * Math.Sqrt(0.08 / acceleration))).Within(1e-6));
            }
        }
    }
}
