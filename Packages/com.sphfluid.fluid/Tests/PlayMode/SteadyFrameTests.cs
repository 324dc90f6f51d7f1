using System.Collections;
using System.Globalization;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Runtime;
using SphFluid.Simulation;
using Unity.Profiling;
using UnityEngine;
using UnityEngine.Profiling;
using UnityEngine.TestTools;
using NVector4 = System.Numerics.Vector4;

namespace SphFluid.Tests.PlayMode
{
    /// <summary>
    /// What a running fluid costs each frame beyond the GPU work: no managed garbage once warmed up, GPU pass
    /// times read from the very recorder that was enabled, and read-backs that reuse their request.
    /// The scene is <see cref="TestTank"/>: no readout (IMGUI allocates in OnGUI by itself) and no controls,
    /// so a frame holds the fluid's own work only.
    /// </summary>
    public sealed class SteadyFrameTests
    {
        /// <summary>Frames before measuring: read-back requests, dictionaries and JIT-compiled paths all exist by then.</summary>
        const int WarmUpFrames = 30;

        const int MeasuredFrames = 20;

        readonly TestTank _tank = new TestTank();

        [TearDown]
        public void DestroyObjects() => _tank.Destroy();

        [UnityTest]
        public IEnumerator SteadyFramesAllocateNoGarbage()
        {
            TestTank.RequireGpu();
            return FramesAllocateNoGarbage(_tank.CreateFluid(true), null);
        }

        /// <summary>A turning container and a driven sphere change the scene every frame: still no garbage.</summary>
        [UnityTest]
        public IEnumerator DrivenFramesAllocateNoGarbage()
        {
            TestTank.RequireGpu();
            Fluid simulator = _tank.CreateDrivenFluid();
            Vector3 ballStart = GameObject.Find("Ball").transform.position;
            return FramesAllocateNoGarbage(simulator, running =>
            {
                Assert.That(running.Plan.UploadContainerTransform, Is.True, "the container was still turning");
                Assert.That(running.Simulation.Scene.Obstacles[0].Center.X, Is.Not.EqualTo(ballStart.x), "the sphere was driven");
                Assert.That(running.HealthProblem, Is.Null, running.HealthProblem?.Message);
            });
        }

        /// <param name="whileRunning">Checks of the running fluid, after the measured frames (null: none).</param>
        IEnumerator FramesAllocateNoGarbage(Fluid simulator, System.Action<Fluid> whileRunning)
        {
            for (int i = 0; i < WarmUpFrames; i++) yield return null;
            Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);

            var fluid = new long[MeasuredFrames];
            var idle = new long[MeasuredFrames];
            using (ProfilerRecorder allocated = ProfilerRecorder.StartNew(ProfilerCategory.Memory, "GC Allocated In Frame"))
            {
                Assume.That(allocated.Valid, Is.True, "the 'GC Allocated In Frame' counter is not available here");
                yield return null; // the frame the recorder started in was counted only in part
                for (int i = 0; i < MeasuredFrames; i++)
                {
                    yield return null;
                    fluid[i] = allocated.LastValue; // the frame that just ended, its fluid step included
                }
                whileRunning?.Invoke(simulator);

                // The same frames without the fluid: what the editor and the test runner allocate by themselves.
                simulator.enabled = false;
                yield return null; // the frame that released the GPU resources
                for (int i = 0; i < MeasuredFrames; i++)
                {
                    yield return null;
                    idle[i] = allocated.LastValue;
                }
            }
            Assume.That(idle, Is.All.EqualTo(0L),
                "frames without the fluid already allocate (editor windows? run in batch mode), bytes: " + Join(idle));
            Assert.That(fluid, Is.All.EqualTo(0L), "bytes allocated in each frame of a running fluid: " + Join(fluid));
        }

        static string Join(long[] values)
        {
            var parts = new string[values.Length];
            for (int i = 0; i < values.Length; i++) parts[i] = values[i].ToString(CultureInfo.InvariantCulture);
            return string.Join(" ", parts);
        }

        [UnityTest]
        public IEnumerator GpuPassTimesAreReadFromTheRecorderThatWasEnabled()
        {
            TestTank.RequireGpu();
            Fluid simulator = _tank.CreateFluid(false);
            for (int i = 0; i < WarmUpFrames; i++) yield return null;
            Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);

            GpuPassTimer forces = simulator.Device.RecordedTimer(PassNames.Forces);
            Assert.That(forces, Is.Not.Null, "the Forces pass records a range every sub-step");
            Assert.That(forces.ProfilerName, Is.EqualTo("SphFluid.Forces"));
            Assert.That(GpuPassTimer.Of(PassNames.Forces), Is.SameAs(forces), "one timer per pass name");
            Assume.That(SystemInfo.supportsGpuRecorder, Is.True, "this graphics API cannot time GPU ranges");
            Assert.That(forces.Recorder, Is.Not.Null, "a GPU-timed sampler has its recorder");
            Assert.That(forces.Recorder.enabled, Is.True);
            Assert.That(forces.TryGetMilliseconds(out double forcesMs), Is.True, "the enabled recorder reports the Forces pass");
            Assert.That(forcesMs, Is.GreaterThan(0.0));
            Assert.That(simulator.TryGetGpuMilliseconds(out double frameMs), Is.True);
            Assert.That(frameMs, Is.GreaterThanOrEqualTo(forcesMs), "a frame's GPU time sums every pass, Forces among them");

            // A reset makes a new device; it times its passes with the same recorder, which keeps counting.
            Recorder recorder = forces.Recorder;
            simulator.ResetSimulation();
            for (int i = 0; i < 10; i++) yield return null;
            Assert.That(simulator.Device.RecordedTimer(PassNames.Forces), Is.SameAs(forces));
            Assert.That(forces.Recorder, Is.SameAs(recorder));
            Assert.That(simulator.TryGetGpuMilliseconds(out double afterResetMs), Is.True);
            Assert.That(afterResetMs, Is.GreaterThan(0.0));
        }

        [UnityTest]
        public IEnumerator ARequestIsRestartedOnceReadAndLeftAloneWhileAwaited()
        {
            TestTank.RequireGpu();
            var device = new UnityComputeDevice(new ComputeShader[0]);
            try
            {
                IComputeBuffer buffer = device.CreateBuffer("SteadyFrameTests.Readback", 2, 16);
                var first = new[] { new NVector4(1f, 2f, 3f, 4f), new NVector4(-5f, 6.5f, 0f, 1e6f) };
                var second = new[] { new NVector4(7f, 8f, 9f, 10f), new NVector4(0.25f, -1f, 2f, -3f) };
                buffer.SetData(first);

                var request = (UnityReadbackRequest)device.RequestReadback(buffer);
                for (int i = 0; i < 60 && !request.IsDone; i++) yield return null;
                Assert.That(request.IsDone, Is.True, "the read-back did not finish within 60 frames");
                Assert.That(request.HasError, Is.False);
                var read = new NVector4[2];
                request.GetData(read);
                Assert.That(read, Is.EqualTo(first));

                buffer.SetData(second);
                IReadbackRequest again = device.RequestReadback(buffer);
                Assert.That(again, Is.SameAs(request), "a spent request (done and read) is restarted, not remade");
                Assert.That(request.Starts, Is.EqualTo(2));
                Assert.That(again.IsDone, Is.False, "a restarted request waits for its new data");

                IReadbackRequest other = device.RequestReadback(buffer);
                Assert.That(other, Is.Not.SameAs(again), "a request still awaited is never restarted under its caller");

                for (int i = 0; i < 60 && !(again.IsDone && other.IsDone); i++) yield return null;
                Assert.That(again.IsDone && other.IsDone, Is.True, "the read-backs did not finish within 60 frames");
                again.GetData(read);
                Assert.That(read, Is.EqualTo(second));
                other.GetData(read);
                Assert.That(read, Is.EqualTo(second));
            }
            finally
            {
                device.Dispose();
            }
        }
    }
}
