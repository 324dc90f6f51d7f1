using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Threading.Tasks;
using Silk.NET.Core.Native;
using Silk.NET.Vulkan;
using SphFluid.Compute;
using VkBuffer = Silk.NET.Vulkan.Buffer;
using VkSemaphore = Silk.NET.Vulkan.Semaphore;

namespace SphFluid.Vulkan;

/// <summary>Vulkan could not be set up here (no loader, no driver, no compute-capable device), or no adapter has the
/// name asked for.</summary>
public sealed class VulkanUnavailableException : Exception
{
    public VulkanUnavailableException(string message, Exception? inner = null) : base(message, inner) { }

    /// <summary>The adapters there are, where none has the name asked for (<see cref="VulkanComputeOptions.DeviceName"/>);
    /// null where Vulkan itself is missing. The caller knows who asked, an argument or the environment, and says so.</summary>
    public IReadOnlyList<string>? Adapters { get; init; }
}

/// <summary>
/// The headless implementation of <see cref="IComputeDevice"/>: runs the project's own <c>.compute</c>
/// kernels through Vulkan (lavapipe in CI, or a real GPU). Work is recorded like a Unity CommandBuffer
/// into one Vulkan command buffer per <see cref="Submit"/>; every dispatch captures its own globals
/// (in a host-visible uniform ring) and buffer bindings (in a per-submit descriptor pool), and is
/// followed by a compute-to-compute memory barrier. Not thread-safe: use it from one thread.
/// </summary>
public sealed unsafe partial class VulkanComputeDevice : IComputeDevice
{
    const int FrameCount = 2;
    const uint QueriesPerPool = 4096;
    const ulong UniformChunkSize = 1 << 20;
    const uint SetsPerDescriptorPool = 1024;

    /// <summary>Dispatches one command buffer records before it is submitted and recording goes on in the next. Lavapipe
    /// (Mesa 25.0.7) crashed in a memset while recording a DFSPH frame of 84 sub-steps, some 60 000 dispatches, though
    /// 56 sub-steps ran; a frame that records more is submitted in parts.</summary>
    internal const int DispatchesPerSubmit = 16384;

    readonly Vk _vk;
    readonly VulkanComputeOptions _options;
    Instance _instance;
    PhysicalDevice _physical;
    Device _device;
    Queue _queue;
    uint _queueFamily;
    PhysicalDeviceLimits _limits;
    uint _deviceApiVersion;
    PhysicalDeviceMemoryProperties _memory;
    readonly bool _canTime;
    readonly double _timestampPeriodNs;
    readonly ulong _timestampMask;
    bool _disposed;

    readonly Frame[] _frames = new Frame[FrameCount];
    int _nextFrame;
    Frame? _recording;
    ulong _submittedSerial, _completedSerial;

    CommandPool _immediatePool;
    CommandBuffer _immediateCmd;
    Fence _immediateFence;
    VkBuffer _staging;
    DeviceMemory _stagingMemory;
    byte* _stagingMapped;
    ulong _stagingSize;

    readonly HashSet<VulkanBuffer> _liveBuffers = new();
    readonly List<VulkanBuffer> _deferredRelease = new();
    readonly Dictionary<string, KernelVariant> _variantCache = new(StringComparer.Ordinal);
    readonly Dictionary<string, double> _sampleResults = new(StringComparer.Ordinal);
    readonly Dictionary<string, double> _submitSampleSums = new(StringComparer.Ordinal);
    readonly Dictionary<string, ulong> _sampleSerial = new(StringComparer.Ordinal);
    readonly Dictionary<string, uint> _openSamples = new(StringComparer.Ordinal);
    readonly HashSet<string> _samplesCutBySubmit = new(StringComparer.Ordinal); // open when a part was submitted: untimed
    IReadOnlyList<(string Kernel, double Milliseconds)> _lastDispatchTimings = Array.Empty<(string, double)>();
    ulong _lastDispatchTimingsSerial;

    /// <summary>Adapter name, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".</summary>
    public string DeviceName { get; }
    /// <summary>The driver's own version string (Vulkan 1.2 <c>driverInfo</c>), e.g. "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)" for
    /// lavapipe, whose adapter name is the same across Mesa releases that differ threefold in speed; empty on a 1.1 device.</summary>
    public string Driver { get; }
    /// <summary>Vulkan device type: DiscreteGpu, IntegratedGpu, VirtualGpu, Cpu or Other.</summary>
    public string DeviceType { get; }

    public bool RunsOnCpu => DeviceType == nameof(PhysicalDeviceType.Cpu);

    /// <summary>The device's maxStorageBufferRange: CreateBuffer refuses anything larger.</summary>
    public long MaxBufferBytes => _limits.MaxStorageBufferRange;

    /// <summary>Vulkan API version the device reports, e.g. "1.3.230".</summary>
    public string ApiVersion { get; }
    public ShaderCompiler Compiler { get; }
    public IReadOnlyList<string> ShaderDirectories { get; }
    public bool ValidationEnabled { get; }
    /// <summary>Whether out-of-range buffer accesses are defined (D3D-like) on this device.</summary>
    public bool RobustBufferAccess { get; private set; }
    /// <summary>Whether the device lays out buffers with scalar alignment (Vulkan 1.2 <c>scalarBlockLayout</c>), which
    /// structured buffers packed as in D3D/Unity need; without it, kernels that use such buffers are refused at dispatch.</summary>
    public bool ScalarBlockLayout { get; private set; }
    /// <summary>Number of dispatches recorded since the device was created.</summary>
    public long DispatchCount { get; private set; }
    /// <summary>Number of Vulkan queue submissions (frames plus uploads/read-backs through staging).</summary>
    public long SubmitCount { get; private set; }

    /// <summary>Submits made part-way through a recording that reached <see cref="DispatchesPerSubmit"/> dispatches: the
    /// sample ranges open across one go untimed, and a name timed on both sides reads only the later part's sum.</summary>
    public long SplitSubmitCount { get; private set; }

    public VulkanComputeDevice(VulkanComputeOptions? options = null)
    {
        _options = options ?? new VulkanComputeOptions();
        ShaderDirectories = _options.ShaderDirectories.Select(Path.GetFullPath).ToList();
        Compiler = new ShaderCompiler(_options.ShaderCacheDirectory);
        try
        {
            _vk = new Vk(Vk.CreateDefaultContext(new[] { "libvulkan.so.1", "libvulkan.so", "vulkan-1.dll", "libvulkan.1.dylib" }));
        }
        catch (Exception e)
        {
            throw new VulkanUnavailableException("The Vulkan loader (libvulkan.so.1, Debian package libvulkan1) could not be loaded", e);
        }

        try
        {
            ValidationEnabled = _options.Validation;
            CreateInstance();
            SelectPhysicalDevice(out var props, out var timestampBits);
            DeviceName = SilkMarshal.PtrToString((nint)props.DeviceName) ?? "unnamed Vulkan device";
            DeviceType = props.DeviceType.ToString();
            ApiVersion = $"{props.ApiVersion >> 22}.{(props.ApiVersion >> 12) & 0x3FF}.{props.ApiVersion & 0xFFF}";
            _limits = props.Limits;
            _deviceApiVersion = props.ApiVersion;
            Driver = DriverInfo();
            _vk.GetPhysicalDeviceMemoryProperties(_physical, out _memory);
            _canTime = timestampBits > 0 && props.Limits.TimestampPeriod > 0;
            _timestampPeriodNs = props.Limits.TimestampPeriod;
            _timestampMask = timestampBits >= 64 ? ulong.MaxValue : (1UL << (int)timestampBits) - 1;
            CreateDevice();
            CreateImmediateContext();
            for (int i = 0; i < FrameCount; i++) _frames[i] = CreateFrame();
        }
        catch
        {
            DestroyEverything();
            throw;
        }
    }

    // ---------------------------------------------------------------- setup

    static readonly string ValidationLayer = "VK_LAYER_KHRONOS_validation";

    /// <summary>True when the Khronos validation layer is installed (package vulkan-validationlayers).</summary>
    public static bool IsValidationLayerAvailable()
    {
        try
        {
            var vk = new Vk(Vk.CreateDefaultContext(new[] { "libvulkan.so.1", "libvulkan.so", "vulkan-1.dll" }));
            uint count = 0;
            vk.EnumerateInstanceLayerProperties(&count, null);
            var layers = new LayerProperties[count];
            fixed (LayerProperties* p = layers) vk.EnumerateInstanceLayerProperties(&count, p);
            for (int i = 0; i < count; i++)
                fixed (byte* n = layers[i].LayerName)
                    if (SilkMarshal.PtrToString((nint)n) == ValidationLayer) return true;
            return false;
        }
        catch (Exception)
        {
            return false;
        }
    }

    void Check(Result r, string what)
    {
        if (r != Result.Success) throw new ComputeException($"Vulkan {what} failed: {r}");
    }

    void CreateInstance()
    {
        var appName = (byte*)SilkMarshal.StringToPtr("SphFluid");
        var layerName = (byte*)SilkMarshal.StringToPtr(ValidationLayer);
        var extensions = stackalloc byte*[2];
        extensions[0] = (byte*)SilkMarshal.StringToPtr("VK_EXT_debug_utils");
        extensions[1] = (byte*)SilkMarshal.StringToPtr("VK_EXT_validation_features");
        try
        {
            var app = new ApplicationInfo
            {
                SType = StructureType.ApplicationInfo,
                PApplicationName = appName,
                PEngineName = appName,
                ApiVersion = Vk.Version12, // a 1.1 device still works; 1.2 makes scalarBlockLayout core where the device has it
            };
            var info = new InstanceCreateInfo { SType = StructureType.InstanceCreateInfo, PApplicationInfo = &app };
            var messengerInfo = default(DebugUtilsMessengerCreateInfoEXT);
            var features = stackalloc ValidationFeatureEnableEXT[1] { ValidationFeatureEnableEXT.SynchronizationValidationExt };
            var validationFeatures = new ValidationFeaturesEXT
            {
                SType = StructureType.ValidationFeaturesExt,
                EnabledValidationFeatureCount = 1,
                PEnabledValidationFeatures = features,
            };
            if (ValidationEnabled)
            {
                if (!IsValidationLayerAvailable())
                    throw new VulkanUnavailableException($"Validation was requested but {ValidationLayer} is not installed (Debian package vulkan-validationlayers)");
                messengerInfo = MessengerCreateInfo();
                info.EnabledLayerCount = 1;
                info.PpEnabledLayerNames = &layerName;
                info.EnabledExtensionCount = 1;
                info.PpEnabledExtensionNames = extensions;
                if (_options.SynchronizationValidation)
                {
                    // The layer only reads VkValidationFeaturesEXT when its extension is enabled.
                    info.EnabledExtensionCount = 2;
                    validationFeatures.PNext = &messengerInfo;
                    info.PNext = &validationFeatures;
                }
                else info.PNext = &messengerInfo;
            }
            Instance instance;
            var r = _vk.CreateInstance(&info, null, &instance);
            if (r != Result.Success)
                throw new VulkanUnavailableException($"vkCreateInstance failed ({r}): no usable Vulkan driver (install mesa-vulkan-drivers for lavapipe)");
            _instance = instance;
            if (ValidationEnabled) CreateMessenger();
        }
        finally
        {
            SilkMarshal.Free((nint)appName);
            SilkMarshal.Free((nint)layerName);
            SilkMarshal.Free((nint)extensions[0]);
            SilkMarshal.Free((nint)extensions[1]);
        }
    }

    static int TypeRank(PhysicalDeviceType t) => t switch
    {
        PhysicalDeviceType.DiscreteGpu => 0,
        PhysicalDeviceType.IntegratedGpu => 1,
        PhysicalDeviceType.VirtualGpu => 2,
        PhysicalDeviceType.Cpu => 3,
        _ => 4,
    };

    void SelectPhysicalDevice(out PhysicalDeviceProperties chosenProps, out uint timestampBits)
    {
        uint count = 0;
        _vk.EnumeratePhysicalDevices(_instance, &count, null);
        if (count == 0) throw new VulkanUnavailableException("Vulkan found no physical device (check VK_LOADER_DRIVERS_SELECT / VK_DRIVER_FILES; install mesa-vulkan-drivers for lavapipe)");
        var devices = new PhysicalDevice[count];
        fixed (PhysicalDevice* p = devices) _vk.EnumeratePhysicalDevices(_instance, &count, p);

        var candidates = new List<(PhysicalDevice dev, PhysicalDeviceProperties props, uint family, uint tsBits, string name)>();
        foreach (var dev in devices)
        {
            _vk.GetPhysicalDeviceProperties(dev, out var props);
            uint qc = 0;
            _vk.GetPhysicalDeviceQueueFamilyProperties(dev, &qc, null);
            var families = new QueueFamilyProperties[qc];
            fixed (QueueFamilyProperties* f = families) _vk.GetPhysicalDeviceQueueFamilyProperties(dev, &qc, f);
            // Prefer a compute queue that also times (and a dedicated compute family over the graphics one).
            int best = -1;
            for (int i = 0; i < qc; i++)
            {
                if ((families[i].QueueFlags & QueueFlags.ComputeBit) == 0 || families[i].QueueCount == 0) continue;
                if (best < 0 || (families[best].TimestampValidBits == 0 && families[i].TimestampValidBits > 0)) best = i;
            }
            if (best < 0) continue;
            candidates.Add((dev, props, (uint)best, families[best].TimestampValidBits, SilkMarshal.PtrToString((nint)props.DeviceName) ?? ""));
        }
        if (candidates.Count == 0) throw new VulkanUnavailableException("No Vulkan device has a compute queue");

        string? wanted = _options.DeviceName;
        IEnumerable<(PhysicalDevice dev, PhysicalDeviceProperties props, uint family, uint tsBits, string name)> pool = candidates;
        if (!string.IsNullOrWhiteSpace(wanted))
        {
            pool = candidates.Where(c => NameMatches(c.name, wanted)).ToList();
            if (!pool.Any())
                throw new VulkanUnavailableException($"no Vulkan adapter's name contains '{wanted}' (adapters: {string.Join(", ", candidates.Select(c => c.name))})")
                    { Adapters = candidates.Select(c => c.name).ToList() };
        }
        var chosen = pool.OrderBy(c => TypeRank(c.props.DeviceType)).First();
        _physical = chosen.dev;
        _queueFamily = chosen.family;
        chosenProps = chosen.props;
        timestampBits = chosen.tsBits;
    }

    /// <summary>Whether the adapter <paramref name="adapter"/> is the one asked for: its name contains
    /// <paramref name="wanted"/>, ignoring case. Mesa's CPU Vulkan driver, lavapipe, names its adapter after the
    /// rasteriser it shares code with ("llvmpipe (LLVM 15.0.6, 256 bits)"), so "lavapipe", the name the docs use,
    /// finds it too.</summary>
    public static bool NameMatches(string adapter, string wanted) =>
        adapter.Contains(wanted, StringComparison.OrdinalIgnoreCase)
        || (wanted.Trim().Equals("lavapipe", StringComparison.OrdinalIgnoreCase) && adapter.Contains("llvmpipe", StringComparison.OrdinalIgnoreCase));

    void CreateDevice()
    {
        float priority = 1f;
        var queueInfo = new DeviceQueueCreateInfo
        {
            SType = StructureType.DeviceQueueCreateInfo,
            QueueFamilyIndex = _queueFamily,
            QueueCount = 1,
            PQueuePriorities = &priority,
        };
        _vk.GetPhysicalDeviceFeatures(_physical, out var supported);
        var features = new PhysicalDeviceFeatures
        {
            RobustBufferAccess = _options.RobustBufferAccess && supported.RobustBufferAccess,
            // RWTexture<float2> is an Rg32f storage image, one of the "extended" formats.
            ShaderStorageImageExtendedFormats = supported.ShaderStorageImageExtendedFormats,
            // Costs nothing until a query uses it (CountInvocations).
            PipelineStatisticsQuery = supported.PipelineStatisticsQuery,
        };
        RobustBufferAccess = features.RobustBufferAccess;
        CanCountInvocations = features.PipelineStatisticsQuery;
        var info = new DeviceCreateInfo
        {
            SType = StructureType.DeviceCreateInfo, QueueCreateInfoCount = 1, PQueueCreateInfos = &queueInfo, PEnabledFeatures = &features,
        };

        // Structured buffers are packed as D3D packs them (StructuredBufferPacking), which needs scalar block
        // layout: core in Vulkan 1.2, else the extension it came from.
        var scalarLayout = new PhysicalDeviceScalarBlockLayoutFeatures { SType = StructureType.PhysicalDeviceScalarBlockLayoutFeatures };
        var query = new PhysicalDeviceFeatures2 { SType = StructureType.PhysicalDeviceFeatures2, PNext = &scalarLayout };
        bool core12 = _deviceApiVersion >= Vk.Version12;
        bool extension = !core12 && HasDeviceExtension(ScalarBlockLayoutExtension);
        if (core12 || extension) _vk.GetPhysicalDeviceFeatures2(_physical, &query);
        ScalarBlockLayout = scalarLayout.ScalarBlockLayout;
        var extensionName = (byte*)SilkMarshal.StringToPtr(ScalarBlockLayoutExtension);
        try
        {
            if (ScalarBlockLayout)
            {
                scalarLayout = new PhysicalDeviceScalarBlockLayoutFeatures { SType = StructureType.PhysicalDeviceScalarBlockLayoutFeatures, ScalarBlockLayout = true };
                info.PNext = &scalarLayout;
                if (extension)
                {
                    info.EnabledExtensionCount = 1;
                    info.PpEnabledExtensionNames = &extensionName;
                }
            }
            Device device;
            Check(_vk.CreateDevice(_physical, &info, null, &device), "vkCreateDevice");
            _device = device;
        }
        finally { SilkMarshal.Free((nint)extensionName); }
        _vk.GetDeviceQueue(_device, _queueFamily, 0, out _queue);
    }

    string DriverInfo()
    {
        if (_deviceApiVersion < Vk.Version12) return "";
        var driver = new PhysicalDeviceDriverProperties { SType = StructureType.PhysicalDeviceDriverProperties };
        var query = new PhysicalDeviceProperties2 { SType = StructureType.PhysicalDeviceProperties2, PNext = &driver };
        _vk.GetPhysicalDeviceProperties2(_physical, &query);
        return SilkMarshal.PtrToString((nint)driver.DriverInfo) ?? "";
    }

    const string ScalarBlockLayoutExtension = "VK_EXT_scalar_block_layout";

    bool HasDeviceExtension(string name)
    {
        uint count = 0;
        _vk.EnumerateDeviceExtensionProperties(_physical, (byte*)null, &count, null);
        var extensions = new ExtensionProperties[count];
        fixed (ExtensionProperties* p = extensions) _vk.EnumerateDeviceExtensionProperties(_physical, (byte*)null, &count, p);
        for (int i = 0; i < count; i++)
            fixed (byte* n = extensions[i].ExtensionName)
                if (SilkMarshal.PtrToString((nint)n) == name) return true;
        return false;
    }

    void CreateImmediateContext()
    {
        var poolInfo = new CommandPoolCreateInfo { SType = StructureType.CommandPoolCreateInfo, QueueFamilyIndex = _queueFamily, Flags = CommandPoolCreateFlags.ResetCommandBufferBit };
        Check(_vk.CreateCommandPool(_device, &poolInfo, null, out _immediatePool), "vkCreateCommandPool");
        var alloc = new CommandBufferAllocateInfo { SType = StructureType.CommandBufferAllocateInfo, CommandPool = _immediatePool, Level = CommandBufferLevel.Primary, CommandBufferCount = 1 };
        Check(_vk.AllocateCommandBuffers(_device, &alloc, out _immediateCmd), "vkAllocateCommandBuffers");
        var fenceInfo = new FenceCreateInfo { SType = StructureType.FenceCreateInfo };
        Check(_vk.CreateFence(_device, &fenceInfo, null, out _immediateFence), "vkCreateFence");
    }

    // ---------------------------------------------------------------- teardown

    public void Dispose()
    {
        if (_disposed) return;
        try
        {
            if (_device.Handle != 0)
            {
                if (_recording != null)
                {
                    _vk.EndCommandBuffer(_recording.Cmd);
                    _recording = null;
                }
                _vk.DeviceWaitIdle(_device);
                foreach (var f in _frames) if (f != null && f.InFlight) WaitFrame(f);
            }
        }
        finally
        {
            _disposed = true;
            DestroyEverything();
        }
    }

    void DestroyEverything()
    {
        if (_device.Handle != 0)
        {
            foreach (var b in _liveBuffers.ToList()) DestroyBuffer(b);
            _deferredRelease.Clear();
            DestroyAllTextures();
            foreach (var v in _variantCache.Values) DestroyVariant(v);
            _variantCache.Clear();
            foreach (var frame in _frames) DestroyFrame(frame);
            Array.Clear(_frames);
            if (_staging.Handle != 0)
            {
                _vk.DestroyBuffer(_device, _staging, null);
                _vk.FreeMemory(_device, _stagingMemory, null);
                _staging = default;
            }
            if (_immediateFence.Handle != 0) _vk.DestroyFence(_device, _immediateFence, null);
            if (_immediatePool.Handle != 0) _vk.DestroyCommandPool(_device, _immediatePool, null);
            _vk.DestroyDevice(_device, null);
            _device = default;
        }
        DestroyMessenger();
        if (_instance.Handle != 0)
        {
            _vk.DestroyInstance(_instance, null);
            _instance = default;
        }
        FreeSelfHandle();
    }

    void ThrowIfDisposed()
    {
        if (_disposed) throw new ObjectDisposedException(nameof(VulkanComputeDevice), "The Vulkan compute device was disposed");
    }
}
