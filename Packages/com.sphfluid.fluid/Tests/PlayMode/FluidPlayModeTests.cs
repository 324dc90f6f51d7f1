using System.Collections;
using System.Collections.Generic;
using NUnit.Framework;
using SphFluid.Runtime;
using SphFluid.Simulation;
using UnityEngine;
using UnityEngine.SceneManagement;
using UnityEngine.TestTools;
using Particle = SphFluid.Simulation.Particle;

namespace SphFluid.Tests.PlayMode
{
    /// <summary>
    /// The real pipeline on the real GPU: a small tank of water built in code runs for some frames, stays finite
    /// and loses nothing; disabling, destroying and unloading release every ComputeBuffer.
    /// Skipped (inconclusive) where there are no compute shaders, e.g. under -nographics.
    /// </summary>
    public sealed class FluidPlayModeTests
    {
        const int Frames = 30;
        static readonly Vector3 ContainerCentre = TestTank.ContainerCentre;
        static readonly Vector3 ContainerSize = TestTank.ContainerSize;

        readonly TestTank _tank = new TestTank();

        [TearDown]
        public void DestroyObjects() => _tank.Destroy();

        static void RequireGpu() => TestTank.RequireGpu();

        Fluid CreateFluid(bool withSphere, out int expectedParticles)
        {
            expectedParticles = TestTank.ExpectedParticles;
            return _tank.CreateFluid(withSphere);
        }

        [UnityTest]
        public IEnumerator RunsFramesOnTheGpuFiniteWithNoParticleLostOrOutside()
        {
            RequireGpu();
            Fluid simulator = CreateFluid(true, out int expected);
            Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);
            Assert.That(simulator.ParticleCount, Is.EqualTo(expected));

            for (int i = 0; i < Frames; i++) yield return null;

            Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);
            Assert.That(simulator.SimulatedTime, Is.GreaterThan(0.0));
            Assert.That(simulator.Plan.Obstacles, Is.True, "a scene with a sphere runs the obstacle pass");
            Assert.That(simulator.Plan.Multiphase, Is.False, "one phase runs no multi-phase variant");

            DiagnosticsReport report = simulator.Simulation.ReadDiagnostics();
            Assert.That(report.NanCount, Is.EqualTo(0), report.ToString());
            Assert.That(report.OutsideCount, Is.EqualTo(0), report.ToString());
            Assert.That(report.ParticleCount, Is.EqualTo(expected), report.ToString());

            // Independently of the GPU reductions: read every particle back and check it.
            var particles = new Particle[simulator.ParticleCount];
            simulator.Simulation.Particles.GetData(particles);
            Vector3 half = ContainerSize * 0.5f + new Vector3(1e-4f, 1e-4f, 1e-4f);
            var ids = new HashSet<uint>();
            foreach (Particle p in particles)
            {
                Vector3 position = p.Position.ToUnity();
                Vector3 velocity = p.Velocity.ToUnity();
                Assert.That(IsFinite(position) && IsFinite(velocity), Is.True, $"particle {p.Id} at {position} moving {velocity}");
                Vector3 local = position - ContainerCentre;
                Assert.That(Mathf.Abs(local.x) <= half.x && Mathf.Abs(local.y) <= half.y && Mathf.Abs(local.z) <= half.z,
                    Is.True, $"particle {p.Id} at {position} is outside the container");
                ids.Add(p.Id);
            }
            Assert.That(ids.Count, Is.EqualTo(expected), "every particle id appears exactly once");
        }

        static bool IsFinite(Vector3 v) =>
            !float.IsNaN(v.x) && !float.IsNaN(v.y) && !float.IsNaN(v.z)
            && !float.IsInfinity(v.x) && !float.IsInfinity(v.y) && !float.IsInfinity(v.z);

        [UnityTest]
        public IEnumerator DisablingReleasesEveryComputeBuffer()
        {
            RequireGpu();
            int before = UnityComputeDevice.LiveBufferTotal;
            Fluid simulator = CreateFluid(false, out _);
            yield return null;
            yield return null;
            Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);

            UnityComputeDevice device = simulator.Device;
            Assert.That(device.LiveBufferCount, Is.GreaterThan(0));
            // The solver must release its own buffers; the device's sweep is only the safety net.
            simulator.Simulation.Dispose();
            Assert.That(device.LiveBufferCount, Is.EqualTo(0), "buffers the FluidSimulation did not release itself");
            simulator.enabled = false;
            Assert.That(device.IsDisposed, Is.True);
            Assert.That(simulator.IsRunning, Is.False);
            Assert.That(UnityComputeDevice.LiveBufferTotal, Is.EqualTo(before));

            simulator.enabled = true; // and it starts again from the components
            yield return null;
            Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);
            Assert.That(UnityComputeDevice.LiveBufferTotal, Is.GreaterThan(before));
            Object.Destroy(simulator.gameObject);
            yield return null;
            Assert.That(UnityComputeDevice.LiveBufferTotal, Is.EqualTo(before), "destroying the simulator leaks");
        }

        [UnityTest]
        public IEnumerator ResetRespawnsWithoutLeaking()
        {
            RequireGpu();
            Fluid simulator = CreateFluid(false, out int expected);
            for (int i = 0; i < 5; i++) yield return null;
            int live = UnityComputeDevice.LiveBufferTotal;
            simulator.ResetSimulation();
            Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);
            Assert.That(simulator.SimulatedTime, Is.EqualTo(0.0));
            Assert.That(simulator.ParticleCount, Is.EqualTo(expected));
            Assert.That(UnityComputeDevice.LiveBufferTotal, Is.EqualTo(live), "a reset keeps the same number of buffers");
            yield return null;
        }

        [UnityTest]
        public IEnumerator SceneReloadDoesNotLeak()
        {
            RequireGpu();
            int before = UnityComputeDevice.LiveBufferTotal;
            Scene original = SceneManager.GetActiveScene();
            for (int round = 0; round < 2; round++)
            {
                Scene scene = SceneManager.CreateScene("SphFluidLeakTest" + round);
                SceneManager.SetActiveScene(scene); // new GameObjects go into the active scene
                Fluid simulator = CreateFluid(true, out _);
                for (int i = 0; i < 5; i++) yield return null;
                Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);
                Assert.That(UnityComputeDevice.LiveBufferTotal, Is.GreaterThan(before));

                SceneManager.SetActiveScene(original);
                yield return SceneManager.UnloadSceneAsync(scene);
                Assert.That(UnityComputeDevice.LiveBufferTotal, Is.EqualTo(before), $"round {round}: unloading the scene leaks");
            }
        }

        /// <summary>The shipped scenes (once the build lists them) load, run and unload cleanly.</summary>
        [UnityTest]
        public IEnumerator BuildScenesRunAndUnloadWithoutLeaks()
        {
            RequireGpu();
            int count = SceneManager.sceneCountInBuildSettings;
            Assume.That(count, Is.GreaterThan(0), "no scene in the build settings yet");
            int before = UnityComputeDevice.LiveBufferTotal;
            for (int index = 0; index < count; index++)
            {
                yield return SceneManager.LoadSceneAsync(index, LoadSceneMode.Additive);
                Scene scene = SceneManager.GetSceneByBuildIndex(index);
                for (int i = 0; i < 10; i++) yield return null;

                Fluid simulator = null;
                foreach (GameObject root in scene.GetRootGameObjects())
                {
                    simulator = root.GetComponentInChildren<Fluid>();
                    if (simulator != null) break;
                }
                Assert.That(simulator, Is.Not.Null, $"{scene.path} has no Fluid");
                Assert.That(simulator.IsRunning, Is.True, $"{scene.path}: {simulator.FailureReason}");
                DiagnosticsReport report = simulator.Simulation.ReadDiagnostics();
                Assert.That(report.NanCount, Is.EqualTo(0), $"{scene.path}: {report}");
                Assert.That(report.OutsideCount, Is.EqualTo(0), $"{scene.path}: {report}");
                Assert.That(report.ParticleCount, Is.EqualTo(simulator.ParticleCount), $"{scene.path}: {report}");

                yield return SceneManager.UnloadSceneAsync(scene);
                Assert.That(UnityComputeDevice.LiveBufferTotal, Is.EqualTo(before), $"{scene.path}: unloading leaks");
            }
        }
    }
}
