using System;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using SphFluid.Compute;
using Silk.NET.Vulkan;
using VkBuffer = Silk.NET.Vulkan.Buffer;

namespace SphFluid.Vulkan;

/// <summary>A structured buffer in device memory. Disposing twice is harmless; using it after
/// disposal throws naming it. Destruction waits until no recorded or running dispatch uses it.</summary>
public sealed unsafe class VulkanBuffer : IComputeBuffer
{
    readonly VulkanComputeDevice _device;
    internal VulkanComputeDevice Device => _device;
    internal VkBuffer Handle;
    internal DeviceMemory Memory;
    /// <summary>Host pointer when the memory is host-visible and coherent (lavapipe, UMA); else null and copies go through staging.</summary>
    internal byte* Mapped;
    /// <summary>Serial of the last submit that used this buffer (for deferred destruction).</summary>
    internal ulong LastUsedSerial;

    public string Name { get; }
    public int Count { get; }
    public int Stride { get; }
    public long SizeInBytes => (long)Count * Stride;
    public bool IsDisposed { get; private set; }

    /// <summary>A constant buffer (<see cref="VulkanComputeDevice.CreateConstantBuffer"/>): bound as a cbuffer, never as a structured buffer.</summary>
    internal bool IsConstant { get; init; }

    internal VulkanBuffer(VulkanComputeDevice device, string name, int count, int stride)
    {
        _device = device;
        Name = name;
        Count = count;
        Stride = stride;
    }

    internal void ThrowIfDisposed()
    {
        if (IsDisposed) throw new ObjectDisposedException(Name, $"Compute buffer '{Name}' ({Count} x {Stride} bytes) was used after it was disposed");
    }

    public void SetData<T>(T[] data) where T : struct
    {
        if (data == null) throw new ArgumentNullException(nameof(data), $"SetData of buffer '{Name}'");
        SetData(data, 0, 0, data.Length);
    }

    public void SetData<T>(T[] data, int sourceIndex, int bufferIndex, int count) where T : struct
    {
        ThrowIfDisposed();
        if (data == null) throw new ArgumentNullException(nameof(data), $"SetData of buffer '{Name}'");
        int size = Unsafe.SizeOf<T>();
        if (sourceIndex < 0 || count < 0 || sourceIndex + (long)count > data.Length)
            throw new ArgumentOutOfRangeException(nameof(count), $"SetData of buffer '{Name}': source range [{sourceIndex}, {sourceIndex + (long)count}) is outside the array of {data.Length}");
        long byteOffset = (long)bufferIndex * size, bytes = (long)count * size;
        if (bufferIndex < 0 || byteOffset + bytes > SizeInBytes)
            throw new ArgumentOutOfRangeException(nameof(bufferIndex), $"SetData of buffer '{Name}': {count} elements of {size} bytes at element {bufferIndex} do not fit its {Count} x {Stride} bytes");
        if (count == 0) return;
        _device.Upload(this, byteOffset, MemoryMarshal.AsBytes(data.AsSpan(sourceIndex, count)));
    }

    public void GetData<T>(T[] data) where T : struct
    {
        ThrowIfDisposed();
        if (data == null) throw new ArgumentNullException(nameof(data), $"GetData of buffer '{Name}'");
        var bytes = MemoryMarshal.AsBytes(data.AsSpan());
        if (bytes.Length > SizeInBytes)
            throw new ArgumentOutOfRangeException(nameof(data), $"GetData of buffer '{Name}': {bytes.Length} bytes requested but it holds {SizeInBytes}");
        if (bytes.Length == 0) return;
        _device.Download(this, 0, bytes);
    }

    public void Dispose()
    {
        if (IsDisposed) return;
        IsDisposed = true;
        _device.Release(this);
    }

    public override string ToString() => $"{Name} ({Count} x {Stride} bytes)";
}
