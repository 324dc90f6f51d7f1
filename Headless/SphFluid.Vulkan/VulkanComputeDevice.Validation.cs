using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using Silk.NET.Core.Native;
using Silk.NET.Vulkan;

namespace SphFluid.Vulkan;

public sealed unsafe partial class VulkanComputeDevice
{
    // VK_EXT_debug_utils through raw function pointers: Silk.NET's extension package is not needed.
    DebugUtilsMessengerEXT _messenger;
    GCHandle _self;
    readonly List<string> _validationMessages = new();
    readonly object _messageLock = new();

    /// <summary>Every warning and error the validation layer reported (empty without validation).</summary>
    public IReadOnlyList<string> ValidationMessages
    {
        get { lock (_messageLock) return _validationMessages.ToArray(); }
    }

    /// <summary>Forgets the messages collected so far (a test can then check only its own).</summary>
    public void ClearValidationMessages()
    {
        lock (_messageLock) _validationMessages.Clear();
    }

    DebugUtilsMessengerCreateInfoEXT MessengerCreateInfo()
    {
        if (!_self.IsAllocated) _self = GCHandle.Alloc(this, GCHandleType.Weak);
        return new DebugUtilsMessengerCreateInfoEXT
        {
            SType = StructureType.DebugUtilsMessengerCreateInfoExt,
            MessageSeverity = DebugUtilsMessageSeverityFlagsEXT.WarningBitExt | DebugUtilsMessageSeverityFlagsEXT.ErrorBitExt,
            MessageType = DebugUtilsMessageTypeFlagsEXT.GeneralBitExt | DebugUtilsMessageTypeFlagsEXT.ValidationBitExt | DebugUtilsMessageTypeFlagsEXT.PerformanceBitExt,
            PfnUserCallback = new PfnDebugUtilsMessengerCallbackEXT(&OnMessage),
            PUserData = (void*)GCHandle.ToIntPtr(_self),
        };
    }

    void CreateMessenger()
    {
        var info = MessengerCreateInfo();
        var create = (delegate* unmanaged[Cdecl]<Instance, DebugUtilsMessengerCreateInfoEXT*, AllocationCallbacks*, DebugUtilsMessengerEXT*, Result>)
            _vk.GetInstanceProcAddr(_instance, "vkCreateDebugUtilsMessengerEXT").Handle;
        if (create == null) throw new VulkanUnavailableException("vkCreateDebugUtilsMessengerEXT is missing although validation was enabled");
        DebugUtilsMessengerEXT messenger;
        Check(create(_instance, &info, null, &messenger), "vkCreateDebugUtilsMessengerEXT");
        _messenger = messenger;
    }

    void DestroyMessenger()
    {
        if (_messenger.Handle != 0 && _instance.Handle != 0)
        {
            var destroy = (delegate* unmanaged[Cdecl]<Instance, DebugUtilsMessengerEXT, AllocationCallbacks*, void>)
                _vk.GetInstanceProcAddr(_instance, "vkDestroyDebugUtilsMessengerEXT").Handle;
            if (destroy != null) destroy(_instance, _messenger, null);
            _messenger = default;
        }
    }

    void FreeSelfHandle()
    {
        if (_self.IsAllocated) _self.Free();
    }

    [UnmanagedCallersOnly(CallConvs = new[] { typeof(CallConvCdecl) })]
    static Silk.NET.Core.Bool32 OnMessage(DebugUtilsMessageSeverityFlagsEXT severity, DebugUtilsMessageTypeFlagsEXT type, DebugUtilsMessengerCallbackDataEXT* data, void* user)
    {
        try
        {
            if (user == null || data == null) return false;
            if (GCHandle.FromIntPtr((IntPtr)user).Target is not VulkanComputeDevice device) return false;
            string? id = data->PMessageIdName == null ? "" : SilkMarshal.PtrToString((nint)data->PMessageIdName);
            string? text = data->PMessage == null ? "" : SilkMarshal.PtrToString((nint)data->PMessage);
            // The loader reports drivers skipped by VK_LOADER_DRIVERS_SELECT as warnings: choices, not faults.
            bool error = (severity & DebugUtilsMessageSeverityFlagsEXT.ErrorBitExt) != 0;
            if (!error && id == "Loader Message") return false;
            string level = (severity & DebugUtilsMessageSeverityFlagsEXT.ErrorBitExt) != 0 ? "error" : "warning";
            lock (device._messageLock) device._validationMessages.Add($"[{level}] {id}: {text}");
        }
        catch
        {
            // Never let an exception cross into the driver.
        }
        return false;
    }
}
