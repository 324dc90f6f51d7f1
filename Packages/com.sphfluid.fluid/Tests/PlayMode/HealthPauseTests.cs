using System.Collections;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SphFluid.Runtime;
using SphFluid.Simulation;
using UnityEngine;
using UnityEngine.TestTools;

namespace SphFluid.Tests.PlayMode
{
    /// <summary>
    /// A fluid whose diagnostics turn unhealthy pauses on the first problem and says so once in the Console; a reset
    /// clears it. A valid scene does not blow up on demand, so the bad report is made up and fed through the
    /// simulator's own check, as an arriving read-back would be.
    /// </summary>
    public sealed class HealthPauseTests
    {
        readonly TestTank _tank = new TestTank();

        [TearDown]
        public void DestroyObjects() => _tank.Destroy();

        [UnityTest]
        public IEnumerator FirstProblem_PausesAndLogsOnce_AndResetClearsIt()
        {
            TestTank.RequireGpu();
            Fluid simulator = _tank.CreateFluid(false);
            for (int i = 0; i < 10; i++) yield return null;
            Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);
            Assert.That(simulator.HealthProblem, Is.Null, "a tank of water at rest is healthy");
            Assert.That(simulator.IsPaused, Is.False);

            var phases = new[] { new PhaseDiagnostics("Water", simulator.ParticleCount, 0f, 0f) };
            var blownUp = new DiagnosticsReport(1.0, 1.0, 0.5f, 7, 0, phases, 0.123);
            LogAssert.Expect(LogType.Error, new Regex(
                @"^Fluid 'Fluid': unhealthy at t = 0\.123 s, phase 'all phases': non-finite particle count 7 exceeds the bound 0 .*; paused"));
            simulator.CheckHealth(blownUp);
            simulator.CheckHealth(blownUp); // a second report of the same trouble is not logged again
            double pausedAt = simulator.SimulatedTime;
            for (int i = 0; i < 5; i++) yield return null;

            Assert.That(simulator.IsPaused, Is.True, "the first problem pauses the simulation");
            Assert.That(simulator.HealthProblem, Is.Not.Null);
            Assert.That(simulator.HealthProblem.Figure, Is.EqualTo("non-finite particle count"));
            Assert.That(simulator.HealthProblem.Value, Is.EqualTo(7.0));
            Assert.That(simulator.SimulatedTime, Is.EqualTo(pausedAt), "paused: no time is simulated");
            LogAssert.NoUnexpectedReceived();

            simulator.ResetSimulation();
            for (int i = 0; i < 5; i++) yield return null;
            Assert.That(simulator.HealthProblem, Is.Null, "a reset clears the problem");
            Assert.That(simulator.IsPaused, Is.False, "and lifts the pause the check made");
            Assert.That(simulator.SimulatedTime, Is.GreaterThan(0.0), "the respawned fluid runs");
        }
    }
}
