using System;
using System.IO;
using SphFluid.Compute;
using SphFluid.Headless.Cli;
using SphFluid.Vulkan;

namespace SphFluid.Headless.Runs;

/// <summary>Opens the headless Vulkan device on the shaders of the fluid package a scene's project uses (its Shaders/).</summary>
public static class DeviceFactory
{
    /// <exception cref="VulkanUnavailableException">No Vulkan driver, or no adapter has the name SPHFLUID_VULKAN_DEVICE gives.</exception>
    /// <exception cref="UsageException">No adapter's name contains <paramref name="deviceName"/> (the --device argument), or
    /// an environment variable of the device's holds a value it refuses.</exception>
    /// <summary>The device a run was given (tests share theirs; the run must not dispose it), else a new one that the
    /// caller disposes through <paramref name="owned"/>; a new one whose shader cache cannot be written is warned of on
    /// <paramref name="warnings"/>, since every run would then compile its kernels afresh without saying why.</summary>
    public static IComputeDevice GivenOrOpen(IComputeDevice? given, string packageFolder, string? deviceName, string command, TextWriter warnings,
        out IDisposable? owned)
    {
        owned = null;
        if (given != null) return given;
        var opened = Open(packageFolder, deviceName, command);
        owned = opened;
        if (opened.Compiler.CacheProblem() is string why)
            warnings.WriteLine($"{command}: warning: the shader cache '{opened.Compiler.CacheDirectory}' cannot be written ({why}); every run " +
                "compiles afresh each kernel not already kept there (set SPHFLUID_SHADER_CACHE to a folder it can write)");
        return opened;
    }

    /// <summary>The device as the runs' first line names it: the adapter, and for a Vulkan device its driver's version.</summary>
    public static string Describe(IComputeDevice device)
    {
        return device is VulkanComputeDevice vulkan && vulkan.Driver.Length > 0 ? $"{device.DeviceName}, driver {vulkan.Driver}" : device.DeviceName;
    }

    public static VulkanComputeDevice Open(string packageFolder, string? deviceName, string command)
    {
        VulkanComputeOptions options;
        try
        {
            options = new VulkanComputeOptions();
        }
        catch (ArgumentException e)
        {
            // An environment variable's value the options refuse: the invocation's fault, as a bad argument is.
            throw new UsageException($"{command}: {e.Message}");
        }
        options.ShaderDirectories = new[] { Path.Combine(packageFolder, "Shaders") };
        if (!string.IsNullOrEmpty(deviceName)) options.DeviceName = deviceName;
        try
        {
            return new VulkanComputeDevice(options);
        }
        catch (VulkanUnavailableException e) when (e.Adapters != null)
        {
            // Named by --device, the argument is wrong (exit 2); named by the environment, no device was to be had here.
            string adapters = string.Join(", ", e.Adapters);
            if (!string.IsNullOrEmpty(deviceName))
                throw new UsageException($"{command}: --device '{deviceName}' matches no Vulkan adapter (adapters: {adapters})");
            throw new VulkanUnavailableException($"SPHFLUID_VULKAN_DEVICE '{options.DeviceName}' matches no Vulkan adapter (adapters: {adapters}; " +
                "unset it, or pass --device)", e) { Adapters = e.Adapters };
        }
    }
}
