using System;
using System.Runtime.InteropServices;
using SphFluid.Compute;

namespace SphFluid.Vulkan;

/// <summary>A read-back that completed when it was requested: the headless device waits for the GPU,
/// so there is never a frame of latency to model.</summary>
sealed class VulkanReadbackRequest : IReadbackRequest
{
    readonly byte[] _data;
    readonly string _bufferName;

    public VulkanReadbackRequest(string bufferName, byte[] data)
    {
        _bufferName = bufferName;
        _data = data;
    }

    public bool IsDone => true;
    public bool HasError => false;

    public void GetData<T>(T[] destination) where T : struct
    {
        if (destination == null) throw new ArgumentNullException(nameof(destination));
        var bytes = MemoryMarshal.AsBytes(destination.AsSpan());
        int n = Math.Min(bytes.Length, _data.Length);
        _data.AsSpan(0, n).CopyTo(bytes);
    }

    public override string ToString() => $"read-back of '{_bufferName}' ({_data.Length} bytes)";
}
