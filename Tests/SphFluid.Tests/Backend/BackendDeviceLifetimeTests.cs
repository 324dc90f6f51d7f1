using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>A device of its own: the staging-copy path a discrete GPU takes, and a clean teardown.</summary>
    public sealed class BackendDeviceLifetimeTests
    {
        [Test]
        public void StagingCopiesWorkAndDisposeLeavesNothingBehind()
        {
            GpuTestDevice.Shared.ToString(); // ignored, with the reason, where there is no Vulkan at all
            bool validation = VulkanComputeDevice.IsValidationLayerAvailable();
            var device = new VulkanComputeDevice(new VulkanComputeOptions
            {
                ShaderDirectories = GpuTestDevice.ShaderDirectories,
                Validation = validation,
                MapDeviceBuffers = false,
            });
            try
            {
                var program = device.LoadProgram("BackendBuffers");
                int kernel = program.FindKernel("AddOne");
                var counter = device.CreateBuffer("Counter", 300, sizeof(uint));
                var zeros = new uint[300];
                counter.GetData(zeros);
                Assert.That(zeros, Is.All.EqualTo(0u), "new buffers start zeroed through the staging path too");
                var start = new uint[300];
                for (int i = 0; i < start.Length; i++) start[i] = (uint)(7 * i);
                counter.SetData(start);
                device.SetBuffer(program, kernel, device.PropertyId("_Counter"), counter);
                device.SetInt(program, device.PropertyId("_ItemCount"), 300);
                device.DispatchThreads(program, kernel, 300);
                device.DispatchThreads(program, kernel, 300);
                var result = new uint[300];
                counter.GetData(result);
                for (int i = 0; i < result.Length; i++) Assert.That(result[i], Is.EqualTo((uint)(7 * i + 2)), "element " + i);
                device.CreateBuffer("NeverDisposed", 4, 4); // the device releases what its owner forgot
            }
            finally
            {
                device.Dispose();
            }
            Assert.That(() => device.Dispose(), Throws.Nothing);
            Assert.That(device.ValidationMessages, Is.Empty, string.Join("\n", device.ValidationMessages));
            Assert.That(() => device.LoadProgram("BackendBuffers"), Throws.TypeOf<System.ObjectDisposedException>());
        }
    }
}
