using System.Collections;
using NUnit.Framework;
using SphFluid.Runtime;
using UnityEngine;
using UnityEngine.TestTools;

namespace SphFluid.Tests.PlayMode
{
    /// <summary>
    /// A <see cref="SphereDriver"/> and a <see cref="ContainerSpinner"/> keep the fluid's simulated time, not the
    /// player's: after frames of running each stands where its law puts it at the fluid's time, a paused fluid holds
    /// them still, and a single step moves them by one <see cref="Fluid.SingleStepSeconds"/>. On the player's clock a
    /// sphere kept moving through a paused fluid, and ran ahead of one that a hitch or the sub-step cap slowed.
    /// </summary>
    public sealed class DriverClockTests
    {
        readonly TestTank _tank = new TestTank();

        [TearDown]
        public void DestroyObjects() => _tank.Destroy();

        [UnityTest]
        public IEnumerator DriversKeepTheFluidsTime_ThroughPauseAndSingleStep()
        {
            TestTank.RequireGpu();
            Fluid simulator = _tank.CreateDrivenFluid();
            Transform ball = GameObject.Find("Ball").transform;
            Transform tank = GameObject.Find("Tank").transform;
            Vector3 ballStart = ball.position; // the driver's start: its OnEnable ran as it was added
            Quaternion tankRest = tank.rotation;
            SphereDriver driver = ball.GetComponent<SphereDriver>();
            ContainerSpinner spinner = tank.GetComponent<ContainerSpinner>();

            for (int i = 0; i < 20; i++) yield return null;
            Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);
            Assert.That(simulator.LastStep.Capped, Is.False, "the tank is small enough that the sub-step cap never binds");
            AssertOnTheFluidsTime("after 20 frames");

            simulator.Pause();
            yield return null;
            Vector3 pausedAt = ball.position;
            Quaternion pausedTurn = tank.rotation;
            double pausedTime = simulator.SimulatedTime;
            for (int i = 0; i < 10; i++) yield return null;
            Assert.That(simulator.SimulatedTime, Is.EqualTo(pausedTime), "paused: no time is simulated");
            Assert.That(ball.position, Is.EqualTo(pausedAt), "the sphere stands still while the fluid is paused");
            Assert.That(tank.rotation, Is.EqualTo(pausedTurn), "so does the container");

            simulator.StepOnce();
            yield return null;
            Assert.That(simulator.SimulatedTime - pausedTime, Is.EqualTo(Fluid.SingleStepSeconds).Within(1e-6));
            AssertOnTheFluidsTime("after a single step");

            void AssertOnTheFluidsTime(string when)
            {
                double t = simulator.SimulatedTime;
                Vector3 expected = ballStart + driver.Drive.Offset(t).ToUnity();
                Assert.That(Vector3.Distance(ball.position, expected), Is.LessThan(1e-4f),
                    $"{when}: the sphere stands where its law puts it at the fluid's t = {t:0.####} s");
                Quaternion turned = spinner.Spin.Turn(t).ToUnity() * tankRest;
                Assert.That(Quaternion.Angle(tank.rotation, turned), Is.LessThan(0.01f),
                    $"{when}: the container is turned as its law turns it at the fluid's t = {t:0.####} s");
            }
        }
    }
}
