using System.IO;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;

namespace SphFluid.Tests.Runner
{
    /// <summary>
    /// A count of particles the device cannot hold ends in a message naming the argument that asked for it, the counts and
    /// the device's limit (exit 2), before the output folder is touched: lavapipe ran DamBreak at --particles-scale 4096
    /// into "unexpected failure: Compute buffer 'FluidSimulation.Particles' (5898240 x 32 = 188743680 bytes) exceeds this
    /// device's storage buffer range" (exit 1). The device here says it binds smaller buffers than it does, so that the
    /// runs stay small.
    /// </summary>
    public sealed class DeviceLimitTests
    {
        sealed class SmallBuffersDevice : ForwardingDevice
        {
            readonly long _limit;

            public SmallBuffersDevice(IComputeDevice inner, long limit) : base(inner) { _limit = limit; }

            public override long MaxBufferBytes => _limit;
        }

        /// <summary>A device that holds the PlayModeTest scene as it is, and no more fluid or walls than that.</summary>
        static IComputeDevice HoldingTheSceneOnly(out int fluid, out long most)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("PlayModeTest")).Description;
            fluid = SpawnLayout.TotalCount(scene);
            long walls = BoundarySampling.Sample(scene).Length;
            most = System.Math.Max(fluid, walls);
            return new SmallBuffersDevice(GpuTestDevice.Shared, DeviceCapacity.ParticleBytes * most);
        }

        [Test]
        public void AParticleScaleTheDeviceCannotHoldIsABadArgument_AndNoOutputIsWritten()
        {
            var device = HoldingTheSceneOnly(out _, out long most);
            string outDir = Path.Combine(RunnerPaths.ScratchFolder("device-limit"), "out");
            var run = new SimulateRun(SimulateOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--particles-scale", "8", "--seconds", "0.02",
                "--out", outDir, "--quiet" }), new StringWriter(), new StringWriter()) { Device = device, InteractiveProgress = false };

            var e = Assert.Throws<UsageException>(() => run.Execute());

            TestContext.Out.WriteLine(e!.Message);
            Assert.That(e.Message, Does.StartWith("simulate: --particles-scale 8 is too large for this device: ")
                .And.Contain(" particles need a buffer of ")
                .And.Contain($"it holds at most {most} fluid"));
            Assert.That(Directory.Exists(outDir), Is.False, "refused before the output folder was claimed");
        }

        [Test]
        public void TheSceneItselfTooLargeForTheDeviceIsASceneError()
        {
            var small = new SmallBuffersDevice(GpuTestDevice.Shared, 1024);
            string scene = RunnerPaths.Scene("PlayModeTest");
            var run = new SimulateRun(SimulateOptions.Parse(new[] { scene, "--seconds", "0.02", "--out", RunnerPaths.ScratchFolder("device-limit-scene"), "--quiet" }),
                new StringWriter(), new StringWriter()) { Device = small, InteractiveProgress = false };

            var e = Assert.Throws<SceneException>(() => run.Execute());

            Assert.That(e!.Message, Does.StartWith(scene + ": too large for this device: ").And.Contain("it holds at most 32 fluid and 32 wall particles"));
        }

        [Test]
        public void ABenchRowTheDeviceCannotHoldIsABadArgumentNamingIt()
        {
            var device = HoldingTheSceneOnly(out int fluid, out _);
            var bench = new BenchRun(BenchOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--steps", "1", "--warmup", "0", "--warmup-seconds", "0",
                "--particles", "100", (4 * fluid).ToString(), "--skip-savings", "--out", RunnerPaths.ScratchFolder("device-limit-bench") }),
                new StringWriter(), new StringWriter()) { Device = device };

            var e = Assert.Throws<UsageException>(() => bench.Execute());

            Assert.That(e!.Message, Does.StartWith($"bench: --particles {4 * fluid} is too large for this device: "));
            Assert.That(bench.Rows, Is.Empty, "refused before the first row was measured");
        }
    }
}
