using System;
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
            Assert.That(device.RobustBufferAccess, Is.True, "out-of-range reads return zero, as in D3D/Unity");
        }

        [Test]
        public void DeviceChosenByNameSubstringOrRefusedNamingTheChoices()
        {
            var shared = GpuTestDevice.Shared;
            string part = shared.DeviceName.Substring(0, Math.Min(6, shared.DeviceName.Length)).ToUpperInvariant();
            using (var chosen = new VulkanComputeDevice(new VulkanComputeOptions { DeviceName = part }))
                Assert.That(chosen.DeviceName, Is.EqualTo(shared.DeviceName));
            Assert.That(() => new VulkanComputeDevice(new VulkanComputeOptions { DeviceName = "NoSuchGpuAnywhere" }),
                Throws.TypeOf<VulkanUnavailableException>().With.Message.Contains("NoSuchGpuAnywhere").And.Message.Contains(shared.DeviceName));
        }

        [Test]
        public void NoValidationMessagesSoFar()
        {
            GpuTestDevice.AssertNoValidationMessages();
        }
    }
}
