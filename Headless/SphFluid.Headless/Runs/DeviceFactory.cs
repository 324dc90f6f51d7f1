using System.IO;
using SphFluid.Vulkan;

namespace SphFluid.Headless.Runs;

/// <summary>Opens the headless Vulkan device on the project's shaders (Assets/SphFluid/Shaders).</summary>
public static class DeviceFactory
{
    /// <exception cref="VulkanUnavailableException">No Vulkan driver or no adapter matching <paramref name="deviceName"/>.</exception>
    public static VulkanComputeDevice Open(string projectRoot, string deviceName)
    {
        var options = new VulkanComputeOptions
        {
            ShaderDirectories = new[] { Path.Combine(projectRoot, "Assets", "SphFluid", "Shaders") },
        };
        if (!string.IsNullOrEmpty(deviceName)) options.DeviceName = deviceName;
        return new VulkanComputeDevice(options);
    }
}
