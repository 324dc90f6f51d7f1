using System.Collections;
using System.Collections.Generic;
using System.Reflection;
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
    public sealed class FluidSimulatorPlayModeTests
    {
        const int Frames = 30;
        const float Spacing = 0.02f;
        static readonly Vector3 ContainerCentre = new Vector3(0f, 0.15f, 0f);
        static readonly Vector3 ContainerSize = new Vector3(0.3f, 0.3f, 0.3f);

        readonly List<GameObject> _objects = new List<GameObject>();

        [TearDown]
        public void DestroyObjects()
        {
            foreach (GameObject o in _objects)
                if (o != null) Object.DestroyImmediate(o);
            _objects.Clear();
        }

        static void RequireGpu()
        {
            Assume.That(SystemInfo.supportsComputeShaders, Is.True, "needs a graphics device with compute shaders (run without -nographics)");
#if !UNITY_EDITOR
            Assert.Ignore("loads the compute shaders through the editor's AssetDatabase");
#endif
        }

        static ComputeShader LoadShader(string name)
        {
#if UNITY_EDITOR
            var shader = UnityEditor.AssetDatabase.LoadAssetAtPath<ComputeShader>($"Assets/SphFluid/Shaders/{name}.compute");
            Assert.That(shader, Is.Not.Null, $"Assets/SphFluid/Shaders/{name}.compute");
            return shader;
#else
            return null;
#endif
        }

        static void Set(object component, string field, object value)
        {
            FieldInfo info = component.GetType().GetField(field, BindingFlags.Instance | BindingFlags.NonPublic);
            Assert.That(info, Is.Not.Null, $"{component.GetType().Name} has no serialized field '{field}'");
            info.SetValue(component, value);
        }

        GameObject Create(string objectName, Vector3 position, Vector3 scale)
        {
            var o = new GameObject(objectName);
            o.transform.position = position;
            o.transform.localScale = scale;
            _objects.Add(o);
            return o;
        }

        /// <summary>A 0.3 m tank with a 0.12 m cube of water (6 x 6 x 6 particles) and, optionally, a sphere.</summary>
        FluidSimulator CreateFluid(bool withSphere, out int expectedParticles)
        {
            FluidContainer container = Create("Tank", ContainerCentre, ContainerSize).AddComponent<FluidContainer>();
            Create("Water", new Vector3(0f, 0.1f, 0f), new Vector3(0.12f, 0.12f, 0.12f)).AddComponent<SpawnBox>();
            expectedParticles = 6 * 6 * 6;
            if (withSphere)
                Create("Ball", new Vector3(0.08f, 0.22f, 0f), new Vector3(0.08f, 0.08f, 0.08f)).AddComponent<SphereObstacle>();

            GameObject fluid = Create("Fluid", Vector3.zero, Vector3.one);
            fluid.SetActive(false); // wire it before OnEnable
            FluidSimulator simulator = fluid.AddComponent<FluidSimulator>();
            Set(simulator, "solverShader", LoadShader("FluidSolver"));
            Set(simulator, "diagnosticsShader", LoadShader("FluidDiagnostics"));
            Set(simulator, "sortShader", LoadShader("ParticleSort"));
            Set(simulator, "prefixSumShader", LoadShader("PrefixSum"));
            Set(simulator, "container", container);
            Set(simulator, "particleSpacing", Spacing);
            fluid.SetActive(true);
            return simulator;
        }

        [UnityTest]
        public IEnumerator RunsFramesOnTheGpuFiniteWithNoParticleLostOrOutside()
        {
            RequireGpu();
            FluidSimulator simulator = CreateFluid(true, out int expected);
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
            FluidSimulator simulator = CreateFluid(false, out _);
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
            FluidSimulator simulator = CreateFluid(false, out int expected);
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
                FluidSimulator simulator = CreateFluid(true, out _);
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

                FluidSimulator simulator = null;
                foreach (GameObject root in scene.GetRootGameObjects())
                {
                    simulator = root.GetComponentInChildren<FluidSimulator>();
                    if (simulator != null) break;
                }
                Assert.That(simulator, Is.Not.Null, $"{scene.path} has no FluidSimulator");
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
