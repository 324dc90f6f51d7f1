using System;
using NUnit.Framework;
using SphFluid.Headless.Runs;
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

        /// <summary>lavapipe's adapter name is the same under Mesa releases that run the suite three times apart, so the
        /// runs name the driver's version beside it (a Vulkan 1.2 device reports one).</summary>
        [Test]
        public void TheRunsNameTheDriverBesideTheAdapter()
        {
            var device = GpuTestDevice.Shared;
            Assume.That(Version.Parse(device.ApiVersion), Is.GreaterThanOrEqualTo(new Version(1, 2)), "a Vulkan 1.1 device reports no driver version");
            Assert.That(device.Driver, Is.Not.Empty);
            Assert.That(DeviceFactory.Describe(device), Is.EqualTo($"{device.DeviceName}, driver {device.Driver}"));
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
