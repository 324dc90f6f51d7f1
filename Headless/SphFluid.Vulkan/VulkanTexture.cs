using System;
using System.Runtime.InteropServices;
using Silk.NET.Vulkan;
using SphFluid.Compute;

namespace SphFluid.Vulkan;

/// <summary>
/// A 2D or 3D texture a kernel reads as <c>Texture2D/3D</c> or writes as <c>RWTexture2D/3D</c> (Unity: a
/// RenderTexture with random write, or a volume). One mip level, in Vulkan's GENERAL layout between
/// commands, so dispatches need no layout transitions (only host copies change it, and change it back). Disposing twice is harmless; using it after disposal
/// throws naming it; destruction waits until no recorded or running dispatch uses it.
/// </summary>
public sealed class VulkanTexture : IDisposable
{
    readonly VulkanComputeDevice _device;
    internal VulkanComputeDevice Device => _device;
    internal Image Image;
    internal DeviceMemory Memory;
    internal ImageView View;
    internal ulong LastUsedSerial;

    public string Name { get; }
    public int Width { get; }
    public int Height { get; }
    /// <summary>1 for a 2D texture.</summary>
    public int Depth { get; }
    /// <summary>2 or 3.</summary>
    public int Dimensions { get; }
    public VulkanTextureFormat Format { get; }
    public long SizeInBytes => (long)Width * Height * Depth * Format.BytesPerTexel();
    public bool IsDisposed { get; private set; }

    /// <summary>How <c>sampler&lt;Name&gt;</c> filters this texture; linear by default, as a new Unity texture.</summary>
    public TextureFilter Filter { get; set; } = TextureFilter.Linear;

    /// <summary>How <c>sampler&lt;Name&gt;</c> wraps this texture; repeat by default, as a new Unity texture.</summary>
    public TextureWrap Wrap { get; set; } = TextureWrap.Repeat;

    internal VulkanTexture(VulkanComputeDevice device, string name, int width, int height, int depth, int dimensions, VulkanTextureFormat format)
    {
        _device = device;
        Name = name;
        Width = width;
        Height = height;
        Depth = depth;
        Dimensions = dimensions;
        Format = format;
    }

    internal void ThrowIfDisposed()
    {
        if (IsDisposed) throw new ObjectDisposedException(Name, $"Texture '{Name}' ({this}) was used after it was disposed");
    }

    /// <summary>Uploads every texel, x fastest, then y, then z; the array must hold exactly the texture's bytes.</summary>
    public void SetData<T>(T[] data) where T : struct
    {
        ThrowIfDisposed();
        if (data == null) throw new ArgumentNullException(nameof(data), $"SetData of texture '{Name}'");
        var bytes = MemoryMarshal.AsBytes(data.AsSpan());
        if (bytes.Length != SizeInBytes)
            throw new ComputeException($"SetData of texture '{Name}' ({this}): {bytes.Length} bytes given, it holds exactly {SizeInBytes}");
        _device.UploadTexture(this, bytes);
    }

    /// <summary>Blocking read-back of every texel, x fastest (submits recorded work first).</summary>
    public void GetData<T>(T[] data) where T : struct
    {
        ThrowIfDisposed();
        if (data == null) throw new ArgumentNullException(nameof(data), $"GetData of texture '{Name}'");
        var bytes = MemoryMarshal.AsBytes(data.AsSpan());
        if (bytes.Length != SizeInBytes)
            throw new ComputeException($"GetData of texture '{Name}' ({this}): {bytes.Length} bytes requested, it holds exactly {SizeInBytes}");
        _device.DownloadTexture(this, bytes);
    }

    public void Dispose()
    {
        if (IsDisposed) return;
        IsDisposed = true;
        _device.Release(this);
    }

    public override string ToString() =>
        Dimensions == 2 ? $"{Width} x {Height} {Format}" : $"{Width} x {Height} x {Depth} {Format}";
}
