using NUnit.Framework;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>The Khronos validation layer watches the GPU tests wherever it is installed.</summary>
    public sealed class BackendValidationTests
    {
        [Test]
        public void ValidationIsOnWhereverTheLayerIsInstalled()
        {
            Assert.That(GpuTestDevice.Shared.ValidationEnabled, Is.EqualTo(VulkanComputeDevice.IsValidationLayerAvailable()));
        }

        [Test]
        public void DeviceIsNamedAndTyped()
        {
            var device = GpuTestDevice.Shared;
            Assert.That(device.DeviceName, Is.Not.Empty);
            Assert.That(device.DeviceType, Is.Not.Empty);
        }

        [Test]
        public void NoValidationMessagesSoFar()
        {
            GpuTestDevice.AssertNoValidationMessages();
        }
    }
}
