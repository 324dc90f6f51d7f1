using System;
using System.Collections.Generic;

namespace SphFluid.Vulkan;

/// <summary>How a <see cref="VulkanComputeDevice"/> is set up.</summary>
public sealed class VulkanComputeOptions
{
    /// <summary>Folders searched (top level first, then recursively) for <c>&lt;name&gt;.compute</c>;
    /// they are also include folders for <c>#include</c>.</summary>
    public IReadOnlyList<string> ShaderDirectories { get; set; } = Array.Empty<string>();

    /// <summary>Extra include folders passed to glslang (the .compute file's own folder always is one).</summary>
    public IReadOnlyList<string> IncludeDirectories { get; set; } = Array.Empty<string>();

    /// <summary>Case-insensitive substring of the adapter name to use; default from SPHFLUID_VULKAN_DEVICE,
    /// else the best type (discrete &gt; integrated &gt; virtual &gt; CPU).</summary>
    public string? DeviceName { get; set; } = Environment.GetEnvironmentVariable("SPHFLUID_VULKAN_DEVICE");

    /// <summary>Enables VK_LAYER_KHRONOS_validation and collects its messages in
    /// <see cref="VulkanComputeDevice.ValidationMessages"/>. Fails if the layer is not installed.</summary>
    public bool Validation { get; set; }

    /// <summary>With <see cref="Validation"/>: also Khronos synchronization validation (hazards between dispatches).</summary>
    public bool SynchronizationValidation { get; set; }

    /// <summary>Writes a timestamp pair around every dispatch (<see cref="VulkanComputeDevice.LastDispatchTimings"/>).</summary>
    public bool TimeDispatches { get; set; } = true;

    /// <summary>Enables robustBufferAccess where the device has it: an out-of-range buffer read returns zero or an
    /// in-range value and an out-of-range write is dropped, as D3D11 (and so Unity) defines it, instead of
    /// undefined behaviour. On by default so kernels behave as they do in Unity.</summary>
    public bool RobustBufferAccess { get; set; } = true;

    /// <summary>Maps storage buffers straight into host memory where the device offers memory that is both
    /// device-local and host-visible (lavapipe, integrated GPUs). Off forces the staging-copy path a discrete GPU takes
    /// (default from <see cref="MapBuffersVariable"/>: 0 turns it off, to rehearse a discrete GPU on lavapipe; 1, empty or
    /// unset leaves it on). Any other value makes the constructor throw an <see cref="ArgumentException"/>: "off", "false"
    /// or "no" read as on while every value but "0" did, and the run rehearsed nothing without saying so.</summary>
    public bool MapDeviceBuffers { get; set; } = MapBuffersFromEnvironment();

    /// <summary>The environment variable that sets <see cref="MapDeviceBuffers"/>'s default.</summary>
    public const string MapBuffersVariable = "SPHFLUID_VULKAN_MAP_BUFFERS";

    static bool MapBuffersFromEnvironment()
    {
        string? value = Environment.GetEnvironmentVariable(MapBuffersVariable);
        return value switch
        {
            null or "" or "1" => true,
            "0" => false,
            _ => throw new ArgumentException($"{MapBuffersVariable} must be 0 (stage every buffer through host copies, as a discrete GPU " +
                $"does) or 1 (map device-local memory where the device has it), or unset (was '{value}')"),
        };
    }

    /// <summary>Where compiled SPIR-V is cached; default <see cref="ShaderCompiler.DefaultCacheDirectory"/>.</summary>
    public string? ShaderCacheDirectory { get; set; }
}
