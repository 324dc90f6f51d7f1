using System;
using Silk.NET.Vulkan;
using SphFluid.Compute;
using VkBuffer = Silk.NET.Vulkan.Buffer;

namespace SphFluid.Vulkan;

/// <summary>Compute, argument and constant buffers: creation, uploads and downloads through staging, read-backs and deferred destruction.</summary>
public sealed unsafe partial class VulkanComputeDevice
{
    public IComputeBuffer CreateArgumentsBuffer(string name, int count)
    {
        if (count < 3) throw new ArgumentOutOfRangeException(nameof(count), count, $"Arguments buffer '{name}': count must be >= 3 (x, y, z groups)");
        return CreateBuffer(name, count, 4);
    }

    public IComputeBuffer CreateBuffer(string name, int count, int stride)
    {
        ThrowIfDisposed();
        if (string.IsNullOrEmpty(name)) throw new ArgumentException("A compute buffer needs a name (it appears in every error about it)", nameof(name));
        if (count <= 0) throw new ArgumentOutOfRangeException(nameof(count), count, $"Compute buffer '{name}': count must be > 0");
        if (stride <= 0 || stride % 4 != 0 || stride > 2048)
            throw new ArgumentOutOfRangeException(nameof(stride), stride, $"Compute buffer '{name}': stride must be a multiple of 4 in [4, 2048] bytes");
        ulong size = (ulong)count * (ulong)stride;
        if (size > _limits.MaxStorageBufferRange)
            throw new ComputeException($"Compute buffer '{name}' ({count} x {stride} = {size} bytes) exceeds this device's storage buffer range of {_limits.MaxStorageBufferRange} bytes");
        // Every buffer may hold indirect dispatch arguments (CreateArgumentsBuffer is a uint buffer like any other).
        return NewBuffer(name, count, stride, BufferUsageFlags.StorageBufferBit | BufferUsageFlags.IndirectBufferBit, false);
    }

    public IComputeBuffer CreateConstantBuffer(string name, int bytes)
    {
        ThrowIfDisposed();
        if (string.IsNullOrEmpty(name)) throw new ArgumentException("A constant buffer needs a name (it appears in every error about it)", nameof(name));
        if (bytes <= 0 || bytes % 16 != 0 || bytes > 65536)
            throw new ArgumentOutOfRangeException(nameof(bytes), bytes, $"Constant buffer '{name}': size must be a multiple of 16 in [16, 65536] bytes");
        if ((uint)bytes > _limits.MaxUniformBufferRange)
            throw new ComputeException($"Constant buffer '{name}' ({bytes} bytes) exceeds this device's uniform buffer range of {_limits.MaxUniformBufferRange} bytes");
        return NewBuffer(name, 1, bytes, BufferUsageFlags.UniformBufferBit, true);
    }

    VulkanBuffer NewBuffer(string name, int count, int stride, BufferUsageFlags usage, bool constant)
    {
        ulong size = (ulong)count * (ulong)stride;
        var buffer = new VulkanBuffer(this, name, count, stride) { IsConstant = constant };
        var (b, m, flags) = CreateRawBuffer(size, usage | BufferUsageFlags.TransferSrcBit | BufferUsageFlags.TransferDstBit,
            MemoryPropertyFlags.DeviceLocalBit, MemoryPropertyFlags.DeviceLocalBit, MemoryPropertyFlags.HostVisibleBit, $"buffer '{name}'");
        buffer.Handle = b;
        buffer.Memory = m;
        const MemoryPropertyFlags mappable = MemoryPropertyFlags.HostVisibleBit | MemoryPropertyFlags.HostCoherentBit;
        if ((flags & mappable) == mappable && _options.MapDeviceBuffers)
        {
            void* p;
            Check(_vk.MapMemory(_device, m, 0, Vk.WholeSize, 0, &p), "vkMapMemory");
            buffer.Mapped = (byte*)p;
            new Span<byte>(p, checked((int)Math.Min(size, int.MaxValue))).Clear();
            if (size > int.MaxValue) new Span<byte>((byte*)p + int.MaxValue, (int)(size - int.MaxValue)).Clear();
        }
        else
        {
            Immediate(cmd => _vk.CmdFillBuffer(cmd, b, 0, Vk.WholeSize, 0));
        }
        _liveBuffers.Add(buffer);
        return buffer;
    }

    internal void Upload(VulkanBuffer buffer, long byteOffset, ReadOnlySpan<byte> data)
    {
        ThrowIfDisposed();
        WaitIdle();
        if (buffer.Mapped != null)
        {
            data.CopyTo(new Span<byte>(buffer.Mapped + byteOffset, data.Length));
            return;
        }
        EnsureStaging((ulong)data.Length);
        data.CopyTo(new Span<byte>(_stagingMapped, data.Length));
        var region = new BufferCopy(0, (ulong)byteOffset, (ulong)data.Length);
        Immediate(cmd => _vk.CmdCopyBuffer(cmd, _staging, buffer.Handle, 1, in region));
    }

    internal void Download(VulkanBuffer buffer, long byteOffset, Span<byte> data)
    {
        ThrowIfDisposed();
        WaitIdle();
        if (buffer.Mapped != null)
        {
            new ReadOnlySpan<byte>(buffer.Mapped + byteOffset, data.Length).CopyTo(data);
            return;
        }
        EnsureStaging((ulong)data.Length);
        var region = new BufferCopy((ulong)byteOffset, 0, (ulong)data.Length);
        Immediate(cmd => _vk.CmdCopyBuffer(cmd, buffer.Handle, _staging, 1, in region));
        new ReadOnlySpan<byte>(_stagingMapped, data.Length).CopyTo(data);
    }

    internal void Release(VulkanBuffer buffer)
    {
        if (_disposed || !_liveBuffers.Contains(buffer)) return;
        if (buffer.LastUsedSerial > _completedSerial) _deferredRelease.Add(buffer);
        else DestroyBuffer(buffer);
    }

    void DestroyBuffer(VulkanBuffer buffer)
    {
        if (!_liveBuffers.Remove(buffer)) return;
        if (buffer.Mapped != null) _vk.UnmapMemory(_device, buffer.Memory);
        _vk.DestroyBuffer(_device, buffer.Handle, null);
        _vk.FreeMemory(_device, buffer.Memory, null);
        buffer.Mapped = null;
        buffer.Handle = default;
        buffer.Memory = default;
    }

    void ReleaseDeferred()
    {
        for (int i = _deferredRelease.Count - 1; i >= 0; i--)
        {
            if (_deferredRelease[i].LastUsedSerial > _completedSerial) continue;
            DestroyBuffer(_deferredRelease[i]);
            _deferredRelease.RemoveAt(i);
        }
        ReleaseDeferredTextures();
    }

    public IReadbackRequest RequestReadback(IComputeBuffer buffer)
    {
        var b = AsBuffer(buffer, "RequestReadback");
        var data = new byte[b.SizeInBytes];
        Download(b, 0, data);
        return new VulkanReadbackRequest(b.Name, data);
    }

    VulkanBuffer AsBuffer(IComputeBuffer buffer, string what)
    {
        if (buffer == null) throw new ArgumentNullException(nameof(buffer), $"{what}: buffer is null");
        if (buffer is not VulkanBuffer b || !ReferenceEquals(b.Device, this))
            throw new ComputeException($"{what}: buffer '{buffer.Name}' was not created by this Vulkan device");
        b.ThrowIfDisposed();
        return b;
    }
}
