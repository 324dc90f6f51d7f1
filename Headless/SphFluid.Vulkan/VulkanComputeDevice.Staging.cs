using System;
using Silk.NET.Vulkan;
using SphFluid.Compute;
using VkBuffer = Silk.NET.Vulkan.Buffer;

namespace SphFluid.Vulkan;

/// <summary>Device memory: memory types, raw buffers, the staging buffer host copies go through, and one-off command buffers.</summary>
public sealed unsafe partial class VulkanComputeDevice
{
    uint FindMemoryType(uint typeBits, MemoryPropertyFlags required, MemoryPropertyFlags preferred, MemoryPropertyFlags avoided)
    {
        int best = -1, bestScore = int.MinValue;
        for (int i = 0; i < _memory.MemoryTypeCount; i++)
        {
            if ((typeBits & (1u << i)) == 0) continue;
            var flags = _memory.MemoryTypes[i].PropertyFlags;
            if ((flags & required) != required) continue;
            int score = ((flags & preferred) == preferred ? 2 : 0) - ((flags & avoided) != 0 ? 1 : 0);
            if (score > bestScore) { best = i; bestScore = score; }
        }
        if (best < 0) throw new ComputeException($"No Vulkan memory type with {required} for this buffer");
        return (uint)best;
    }

    (VkBuffer, DeviceMemory, MemoryPropertyFlags) CreateRawBuffer(ulong size, BufferUsageFlags usage, MemoryPropertyFlags required, MemoryPropertyFlags preferred, MemoryPropertyFlags avoided, string what)
    {
        var info = new BufferCreateInfo { SType = StructureType.BufferCreateInfo, Size = size, Usage = usage, SharingMode = SharingMode.Exclusive };
        VkBuffer buffer;
        Check(_vk.CreateBuffer(_device, &info, null, &buffer), $"vkCreateBuffer ({what}, {size} bytes)");
        _vk.GetBufferMemoryRequirements(_device, buffer, out var req);
        uint type = FindMemoryType(req.MemoryTypeBits, required, preferred, avoided);
        var alloc = new MemoryAllocateInfo { SType = StructureType.MemoryAllocateInfo, AllocationSize = req.Size, MemoryTypeIndex = type };
        DeviceMemory memory;
        var r = _vk.AllocateMemory(_device, &alloc, null, &memory);
        if (r != Result.Success)
        {
            _vk.DestroyBuffer(_device, buffer, null);
            throw new ComputeException($"Out of GPU memory allocating {what} ({size} bytes): {r}");
        }
        Check(_vk.BindBufferMemory(_device, buffer, memory, 0), "vkBindBufferMemory");
        return (buffer, memory, _memory.MemoryTypes[(int)type].PropertyFlags);
    }

    void EnsureStaging(ulong size)
    {
        if (_stagingSize >= size) return;
        if (_staging.Handle != 0)
        {
            _vk.DestroyBuffer(_device, _staging, null);
            _vk.FreeMemory(_device, _stagingMemory, null);
            _staging = default;
        }
        ulong newSize = Math.Max(size, Math.Max(_stagingSize * 2, 1UL << 20));
        var (b, m, _) = CreateRawBuffer(newSize, BufferUsageFlags.TransferSrcBit | BufferUsageFlags.TransferDstBit,
            MemoryPropertyFlags.HostVisibleBit | MemoryPropertyFlags.HostCoherentBit, MemoryPropertyFlags.HostCachedBit, 0, "staging buffer");
        _staging = b;
        _stagingMemory = m;
        void* p;
        Check(_vk.MapMemory(_device, m, 0, Vk.WholeSize, 0, &p), "vkMapMemory (staging)");
        _stagingMapped = (byte*)p;
        _stagingSize = newSize;
    }

    /// <summary>Records and runs a one-off command buffer, waiting for it (uploads, read-backs, clears).</summary>
    void Immediate(Action<CommandBuffer> record)
    {
        Check(_vk.ResetCommandBuffer(_immediateCmd, 0), "vkResetCommandBuffer");
        var begin = new CommandBufferBeginInfo { SType = StructureType.CommandBufferBeginInfo, Flags = CommandBufferUsageFlags.OneTimeSubmitBit };
        Check(_vk.BeginCommandBuffer(_immediateCmd, &begin), "vkBeginCommandBuffer");
        FullBarrier(_immediateCmd);
        record(_immediateCmd);
        FullBarrier(_immediateCmd);
        Check(_vk.EndCommandBuffer(_immediateCmd), "vkEndCommandBuffer");
        var cmd = _immediateCmd;
        var submit = new SubmitInfo { SType = StructureType.SubmitInfo, CommandBufferCount = 1, PCommandBuffers = &cmd };
        var fence = _immediateFence;
        Check(_vk.ResetFences(_device, 1, &fence), "vkResetFences");
        Check(_vk.QueueSubmit(_queue, 1, &submit, fence), "vkQueueSubmit");
        SubmitCount++;
        Check(_vk.WaitForFences(_device, 1, &fence, true, ulong.MaxValue), "vkWaitForFences");
    }

    /// <summary>Orders everything before against everything after on the queue: compute, transfers and host reads.</summary>
    void FullBarrier(CommandBuffer cmd)
    {
        var barrier = new MemoryBarrier
        {
            SType = StructureType.MemoryBarrier,
            SrcAccessMask = AccessFlags.ShaderWriteBit | AccessFlags.TransferWriteBit | AccessFlags.ShaderReadBit | AccessFlags.TransferReadBit,
            DstAccessMask = AccessFlags.ShaderReadBit | AccessFlags.ShaderWriteBit | AccessFlags.TransferReadBit | AccessFlags.TransferWriteBit | AccessFlags.HostReadBit | AccessFlags.UniformReadBit
                | AccessFlags.IndirectCommandReadBit,
        };
        _vk.CmdPipelineBarrier(cmd, PipelineStageFlags.ComputeShaderBit | PipelineStageFlags.TransferBit,
            PipelineStageFlags.ComputeShaderBit | PipelineStageFlags.TransferBit | PipelineStageFlags.HostBit | PipelineStageFlags.DrawIndirectBit,
            0, 1, &barrier, 0, null, 0, null);
    }
}
