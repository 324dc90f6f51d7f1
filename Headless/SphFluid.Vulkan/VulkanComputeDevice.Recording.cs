using System;
using System.Collections.Generic;
using System.Linq;
using System.Runtime.InteropServices;
using Silk.NET.Vulkan;
using SphFluid.Compute;
using VkBuffer = Silk.NET.Vulkan.Buffer;

namespace SphFluid.Vulkan;

public sealed unsafe partial class VulkanComputeDevice
{
    /// <summary>Everything one submit needs, reused two submits later once its fence has signalled.</summary>
    sealed class Frame
    {
        public CommandPool Pool;
        public CommandBuffer Cmd;
        public Fence Fence;
        public bool InFlight;
        public ulong Serial;
        public readonly List<DescriptorPool> DescriptorPools = new();
        public int DescriptorPoolIndex;
        public readonly List<(VkBuffer Buffer, DeviceMemory Memory, ulong Size, IntPtr Mapped)> UniformChunks = new();
        public int ChunkIndex;
        public ulong ChunkOffset;
        public readonly QuerySet Timestamps = new(QueryType.Timestamp);
        public readonly QuerySet Invocations = new(QueryType.PipelineStatistics, QueryPipelineStatisticFlags.ComputeShaderInvocationsBit);
        public int Dispatches;
        public readonly List<(string Kernel, uint Query)> DispatchQueries = new();
        public readonly List<(string Kernel, uint Query)> InvocationQueries = new();
        public readonly List<(string Name, uint Begin, uint End)> Samples = new();
    }

    // ---------------------------------------------------------------- recording

    public void Dispatch(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ) =>
        Record(program, kernel, groupsX, groupsY, groupsZ, null, 0);

    public void DispatchIndirect(IComputeProgram program, int kernel, IComputeBuffer arguments, int byteOffset)
    {
        ThrowIfDisposed();
        var p = AsProgram(program, "DispatchIndirect");
        p.CheckKernel(kernel);
        var args = AsBuffer(arguments, $"DispatchIndirect of kernel '{p.KernelName(kernel)}'");
        long bytes = (long)args.Count * args.Stride;
        if (byteOffset < 0 || byteOffset % 4 != 0 || byteOffset + 12L > bytes)
            throw new ComputeException($"DispatchIndirect of kernel '{p.KernelName(kernel)}': the arguments offset must be a multiple of 4 in [0, {bytes - 12}] bytes of '{args.Name}' (was {byteOffset})");
        Record(program, kernel, 1, 1, 1, args, (ulong)byteOffset);
    }

    void Record(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ, VulkanBuffer? indirect, ulong indirectOffset)
    {
        ThrowIfDisposed();
        var p = AsProgram(program, "Dispatch");
        p.CheckKernel(kernel);
        if (groupsX < 0 || groupsY < 0 || groupsZ < 0)
            throw new ArgumentOutOfRangeException(nameof(groupsX), $"Dispatch of kernel '{p.KernelName(kernel)}': group counts must be >= 0 (were {groupsX}, {groupsY}, {groupsZ})");
        var limits = _limits;
        uint* max = limits.MaxComputeWorkGroupCount;
        if ((uint)groupsX > max[0] || (uint)groupsY > max[1] || (uint)groupsZ > max[2])
            throw new ComputeException($"Dispatch of kernel '{p.KernelName(kernel)}' in {p.Path}: {groupsX} x {groupsY} x {groupsZ} groups exceed this device's limit of {max[0]} x {max[1]} x {max[2]}");
        var v = p.Variant(kernel);
        if (v.Unsupported != null) throw new ComputeException($"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: {v.Unsupported}");
        var bound = p.Bindings[kernel];
        int nBuffers = v.StorageBuffers.Length;
        var resolved = new VulkanBuffer[nBuffers];
        for (int i = 0; i < nBuffers; i++)
        {
            if (!bound.TryGetValue(v.StorageBufferIds[i], out var b))
                throw new ComputeException($"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: buffer '{v.StorageBuffers[i].Name}' was never bound (SetBuffer)");
            if (b.IsDisposed)
                throw new ObjectDisposedException(b.Name, $"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: buffer '{b.Name}' bound to '{v.StorageBuffers[i].Name}' was disposed");
            CheckStride(p, v, v.StorageBuffers[i], b);
            resolved[i] = b;
        }
        var boundTextures = p.TextureBindings[kernel];
        int nTextures = v.Textures.Length;
        var textures = new VulkanTexture[nTextures];
        for (int i = 0; i < nTextures; i++)
        {
            if (!boundTextures.TryGetValue(v.TextureIds[i], out var t))
                throw new ComputeException($"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: texture '{v.Textures[i].Name}' ({Declaration(v.Textures[i])}) was never bound (SetTexture)");
            if (t.IsDisposed)
                throw new ObjectDisposedException(t.Name, $"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: texture '{t.Name}' bound to '{v.Textures[i].Name}' was disposed");
            CheckTexture(p, v, v.Textures[i], t);
            textures[i] = t;
        }
        var samplers = new Sampler[v.Samplers.Length];
        for (int i = 0; i < samplers.Length; i++)
        {
            var settings = SamplerFor(p, v, v.Samplers[i], textures);
            if (settings.Filter == TextureFilter.Linear) CheckLinearFiltering(p, v, v.Samplers[i], textures);
            samplers[i] = SamplerObject(settings);
        }
        if (groupsX == 0 || groupsY == 0 || groupsZ == 0) return;
        CreatePipeline(v);

        var frame = BeginRecording();
        if (frame.Dispatches >= DispatchesPerSubmit)
        {
            SubmitPart();
            frame = BeginRecording();
        }
        frame.Dispatches++;
        var cmd = frame.Cmd;
        var set = AllocateDescriptorSet(frame, v.SetLayout);
        int nWrites = v.Reflection.Resources.Count;
        var infos = stackalloc DescriptorBufferInfo[Math.Max(1, nWrites)];
        var writes = stackalloc WriteDescriptorSet[Math.Max(1, nWrites)];
        int w = 0;
        for (int i = 0; i < nBuffers; i++)
        {
            resolved[i].LastUsedSerial = frame.Serial;
            infos[w] = new DescriptorBufferInfo(resolved[i].Handle, 0, Vk.WholeSize);
            writes[w] = new WriteDescriptorSet
            {
                SType = StructureType.WriteDescriptorSet, DstSet = set, DstBinding = v.StorageBuffers[i].Binding, DescriptorCount = 1,
                DescriptorType = DescriptorType.StorageBuffer, PBufferInfo = &infos[w],
            };
            w++;
        }
        foreach (var (block, blockId, members) in v.UniformBlocks)
        {
            if (p.ConstantBuffers.TryGetValue(blockId, out var constants))
            {
                if (constants.IsDisposed)
                    throw new ObjectDisposedException(constants.Name, $"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: constant buffer '{constants.Name}' bound to cbuffer '{block.Resource.Name}' was disposed");
                if (constants.SizeInBytes < block.Size)
                    throw new ComputeException($"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: cbuffer '{block.Resource.Name}' is {block.Size} bytes but constant buffer '{constants.Name}' holds {constants.SizeInBytes}");
                constants.LastUsedSerial = frame.Serial;
                infos[w] = new DescriptorBufferInfo(constants.Handle, 0, (ulong)constants.SizeInBytes);
                writes[w] = new WriteDescriptorSet
                {
                    SType = StructureType.WriteDescriptorSet, DstSet = set, DstBinding = block.Resource.Binding, DescriptorCount = 1,
                    DescriptorType = DescriptorType.UniformBuffer, PBufferInfo = &infos[w],
                };
                w++;
                continue;
            }
            if (block.Resource.Name != "$Global" && !members.Any(m => p.Globals.ContainsKey(m.Id)))
                throw new ComputeException($"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: cbuffer '{block.Resource.Name}' was never bound (SetConstantBuffer) and none of its members was set");
            var (buffer, offset, at) = AllocateUniform(frame, (ulong)Math.Max(16, block.Size));
            byte* ptr = (byte*)at;
            new Span<byte>(ptr, Math.Max(16, block.Size)).Clear();
            foreach (var (id, member) in members)
                if (p.Globals.TryGetValue(id, out var value) && value.Count > 0) WriteGlobal(ptr, member, value);
            infos[w] = new DescriptorBufferInfo(buffer, offset, (ulong)Math.Max(16, block.Size));
            writes[w] = new WriteDescriptorSet
            {
                SType = StructureType.WriteDescriptorSet, DstSet = set, DstBinding = block.Resource.Binding, DescriptorCount = 1,
                DescriptorType = DescriptorType.UniformBuffer, PBufferInfo = &infos[w],
            };
            w++;
        }
        var images = stackalloc DescriptorImageInfo[Math.Max(1, nTextures + samplers.Length)];
        for (int i = 0; i < nTextures; i++)
        {
            textures[i].LastUsedSerial = frame.Serial;
            images[i] = new DescriptorImageInfo(default, textures[i].View, ImageLayout.General);
            writes[w] = new WriteDescriptorSet
            {
                SType = StructureType.WriteDescriptorSet, DstSet = set, DstBinding = v.Textures[i].Binding, DescriptorCount = 1,
                DescriptorType = DescriptorTypeOf(v.Textures[i].Kind), PImageInfo = &images[i],
            };
            w++;
        }
        for (int i = 0; i < samplers.Length; i++)
        {
            images[nTextures + i] = new DescriptorImageInfo(samplers[i], default, ImageLayout.Undefined);
            writes[w] = new WriteDescriptorSet
            {
                SType = StructureType.WriteDescriptorSet, DstSet = set, DstBinding = v.Samplers[i].Binding, DescriptorCount = 1,
                DescriptorType = DescriptorType.Sampler, PImageInfo = &images[nTextures + i],
            };
            w++;
        }
        if (w > 0) _vk.UpdateDescriptorSets(_device, (uint)w, writes, 0, null);

        _vk.CmdBindPipeline(cmd, PipelineBindPoint.Compute, v.Pipeline);
        _vk.CmdBindDescriptorSets(cmd, PipelineBindPoint.Compute, v.Layout, 0, 1, &set, 0, null);
        bool timed = _options.TimeDispatches && _canTime;
        uint q = 0;
        if (timed)
        {
            q = AllocateQuery(frame, frame.Timestamps, 2);
            WriteTimestamp(frame, q);
        }
        bool counted = CountInvocations;
        uint counter = counted ? BeginInvocationCount(frame) : 0;
        if (indirect != null)
        {
            indirect.LastUsedSerial = frame.Serial;
            _vk.CmdDispatchIndirect(cmd, indirect.Handle, indirectOffset);
        }
        else
        {
            _vk.CmdDispatch(cmd, (uint)groupsX, (uint)groupsY, (uint)groupsZ);
        }
        if (counted) EndInvocationCount(frame, v.Kernel, counter);
        if (timed)
        {
            WriteTimestamp(frame, q + 1);
            frame.DispatchQueries.Add((v.Kernel, q));
        }
        // A later dispatch may read what this one wrote as its indirect arguments.
        var barrier = new MemoryBarrier
        {
            SType = StructureType.MemoryBarrier,
            SrcAccessMask = AccessFlags.ShaderWriteBit,
            DstAccessMask = AccessFlags.ShaderReadBit | AccessFlags.ShaderWriteBit | AccessFlags.IndirectCommandReadBit,
        };
        _vk.CmdPipelineBarrier(cmd, PipelineStageFlags.ComputeShaderBit, PipelineStageFlags.ComputeShaderBit | PipelineStageFlags.DrawIndirectBit,
            0, 1, &barrier, 0, null, 0, null);
        DispatchCount++;
    }

    Frame CreateFrame()
    {
        var f = new Frame();
        var poolInfo = new CommandPoolCreateInfo { SType = StructureType.CommandPoolCreateInfo, QueueFamilyIndex = _queueFamily, Flags = CommandPoolCreateFlags.TransientBit };
        Check(_vk.CreateCommandPool(_device, &poolInfo, null, out f.Pool), "vkCreateCommandPool");
        var alloc = new CommandBufferAllocateInfo { SType = StructureType.CommandBufferAllocateInfo, CommandPool = f.Pool, Level = CommandBufferLevel.Primary, CommandBufferCount = 1 };
        Check(_vk.AllocateCommandBuffers(_device, &alloc, out f.Cmd), "vkAllocateCommandBuffers");
        var fenceInfo = new FenceCreateInfo { SType = StructureType.FenceCreateInfo };
        Check(_vk.CreateFence(_device, &fenceInfo, null, out f.Fence), "vkCreateFence");
        return f;
    }

    void DestroyFrame(Frame f)
    {
        if (f == null) return;
        foreach (var pool in f.DescriptorPools) _vk.DestroyDescriptorPool(_device, pool, null);
        foreach (var c in f.UniformChunks)
        {
            _vk.UnmapMemory(_device, c.Memory);
            _vk.DestroyBuffer(_device, c.Buffer, null);
            _vk.FreeMemory(_device, c.Memory, null);
        }
        foreach (var qp in f.Timestamps.Pools.Concat(f.Invocations.Pools)) _vk.DestroyQueryPool(_device, qp, null);
        if (f.Fence.Handle != 0) _vk.DestroyFence(_device, f.Fence, null);
        if (f.Pool.Handle != 0) _vk.DestroyCommandPool(_device, f.Pool, null);
    }

    Frame BeginRecording()
    {
        if (_recording != null) return _recording;
        var f = _frames[_nextFrame];
        if (f.InFlight) WaitFrame(f);
        Check(_vk.ResetCommandPool(_device, f.Pool, 0), "vkResetCommandPool");
        foreach (var pool in f.DescriptorPools) _vk.ResetDescriptorPool(_device, pool, 0);
        f.DescriptorPoolIndex = 0;
        f.ChunkIndex = 0;
        f.ChunkOffset = 0;
        f.Timestamps.Used = 0;
        f.Invocations.Used = 0;
        f.Dispatches = 0;
        f.DispatchQueries.Clear();
        f.InvocationQueries.Clear();
        f.Samples.Clear();
        f.Serial = _submittedSerial + 1;
        var begin = new CommandBufferBeginInfo { SType = StructureType.CommandBufferBeginInfo, Flags = CommandBufferUsageFlags.OneTimeSubmitBit };
        Check(_vk.BeginCommandBuffer(f.Cmd, &begin), "vkBeginCommandBuffer");
        FullBarrier(f.Cmd);
        _recording = f;
        return f;
    }

    const uint PoolSizeCount = 5;
    static readonly DescriptorPoolSize* PoolSizes = CreatePoolSizes();

    static DescriptorPoolSize* CreatePoolSizes()
    {
        var sizes = (DescriptorPoolSize*)NativeMemory.Alloc(PoolSizeCount, (nuint)sizeof(DescriptorPoolSize));
        sizes[0] = new DescriptorPoolSize(DescriptorType.StorageBuffer, SetsPerDescriptorPool * 8);
        sizes[1] = new DescriptorPoolSize(DescriptorType.UniformBuffer, SetsPerDescriptorPool * 2);
        sizes[2] = new DescriptorPoolSize(DescriptorType.StorageImage, SetsPerDescriptorPool * 2);
        sizes[3] = new DescriptorPoolSize(DescriptorType.SampledImage, SetsPerDescriptorPool * 2);
        sizes[4] = new DescriptorPoolSize(DescriptorType.Sampler, SetsPerDescriptorPool * 2);
        return sizes;
    }

    DescriptorSet AllocateDescriptorSet(Frame f, DescriptorSetLayout layout)
    {
        while (true)
        {
            if (f.DescriptorPoolIndex == f.DescriptorPools.Count)
            {
                var sizes = PoolSizes;
                var info = new DescriptorPoolCreateInfo { SType = StructureType.DescriptorPoolCreateInfo, MaxSets = SetsPerDescriptorPool, PoolSizeCount = PoolSizeCount, PPoolSizes = sizes };
                Check(_vk.CreateDescriptorPool(_device, &info, null, out var pool), "vkCreateDescriptorPool");
                f.DescriptorPools.Add(pool);
            }
            var alloc = new DescriptorSetAllocateInfo
            {
                SType = StructureType.DescriptorSetAllocateInfo, DescriptorPool = f.DescriptorPools[f.DescriptorPoolIndex], DescriptorSetCount = 1, PSetLayouts = &layout,
            };
            DescriptorSet set;
            var r = _vk.AllocateDescriptorSets(_device, &alloc, &set);
            if (r == Result.Success) return set;
            if (r != Result.ErrorOutOfPoolMemory && r != Result.ErrorFragmentedPool) Check(r, "vkAllocateDescriptorSets");
            f.DescriptorPoolIndex++;
        }
    }

    (VkBuffer Buffer, ulong Offset, IntPtr Pointer) AllocateUniform(Frame f, ulong size)
    {
        ulong align = Math.Max(16UL, _limits.MinUniformBufferOffsetAlignment);
        while (true)
        {
            if (f.ChunkIndex == f.UniformChunks.Count)
            {
                ulong chunkSize = Math.Max(UniformChunkSize, size);
                var (b, m, _) = CreateRawBuffer(chunkSize, BufferUsageFlags.UniformBufferBit,
                    MemoryPropertyFlags.HostVisibleBit | MemoryPropertyFlags.HostCoherentBit, 0, 0, "uniform ring");
                void* p;
                Check(_vk.MapMemory(_device, m, 0, Vk.WholeSize, 0, &p), "vkMapMemory (uniform ring)");
                f.UniformChunks.Add((b, m, chunkSize, (IntPtr)p));
            }
            var chunk = f.UniformChunks[f.ChunkIndex];
            ulong offset = (f.ChunkOffset + align - 1) / align * align;
            if (offset + size <= chunk.Size)
            {
                f.ChunkOffset = offset + size;
                return (chunk.Buffer, offset, chunk.Mapped + (nint)offset);
            }
            f.ChunkIndex++;
            f.ChunkOffset = 0;
        }
    }

    public void Submit()
    {
        ThrowIfDisposed();
        _openSamples.Clear();
        _samplesCutBySubmit.Clear();
        SubmitRecording();
    }

    /// <summary>Submits the part of a frame recorded so far (<see cref="DispatchesPerSubmit"/>); the samples open across
    /// it go untimed, and their EndSample is accepted.</summary>
    void SubmitPart()
    {
        SplitSubmitCount++;
        _samplesCutBySubmit.UnionWith(_openSamples.Keys);
        _openSamples.Clear();
        SubmitRecording();
    }

    void SubmitRecording()
    {
        var f = _recording;
        if (f == null) return;
        FullBarrier(f.Cmd);
        Check(_vk.EndCommandBuffer(f.Cmd), "vkEndCommandBuffer");
        var cmd = f.Cmd;
        var submit = new SubmitInfo { SType = StructureType.SubmitInfo, CommandBufferCount = 1, PCommandBuffers = &cmd };
        var fence = f.Fence;
        Check(_vk.ResetFences(_device, 1, &fence), "vkResetFences");
        _recording = null;
        Check(_vk.QueueSubmit(_queue, 1, &submit, fence), "vkQueueSubmit");
        SubmitCount++;
        f.InFlight = true;
        _submittedSerial = f.Serial;
        _nextFrame = (_nextFrame + 1) % FrameCount;
    }

    void WaitFrame(Frame f)
    {
        if (!f.InFlight) return;
        var fence = f.Fence;
        Check(_vk.WaitForFences(_device, 1, &fence, true, ulong.MaxValue), "vkWaitForFences");
        f.InFlight = false;
        _completedSerial = Math.Max(_completedSerial, f.Serial);
        Harvest(f);
        ReleaseDeferred();
    }

    void WaitForSerial(ulong serial)
    {
        foreach (var f in _frames.Where(f => f.InFlight && f.Serial <= serial).OrderBy(f => f.Serial).ToList()) WaitFrame(f);
    }

    /// <summary>Submits what is recorded and waits until the GPU has finished everything.</summary>
    public void WaitIdle()
    {
        ThrowIfDisposed();
        Submit();
        WaitForSerial(ulong.MaxValue);
    }

    void Harvest(Frame f)
    {
        HarvestInvocations(f);
        if (f.Timestamps.Used == 0) return;
        var stamps = ReadQueries(f.Timestamps);
        double Ms(uint begin, uint end) => ((stamps[end] - stamps[begin]) & _timestampMask) * _timestampPeriodNs / 1e6;
        if (f.DispatchQueries.Count > 0)
        {
            var timings = new (string, double)[f.DispatchQueries.Count];
            for (int i = 0; i < timings.Length; i++) timings[i] = (f.DispatchQueries[i].Kernel, Ms(f.DispatchQueries[i].Query, f.DispatchQueries[i].Query + 1));
            if (f.Serial >= _lastDispatchTimingsSerial)
            {
                _lastDispatchTimings = timings;
                _lastDispatchTimingsSerial = f.Serial;
            }
            if (AccumulateDispatchTimings) _accumulatedTimings.AddRange(timings);
        }
        // A name timed more than once in one submit (a pass that runs twice in a sub-step, or in every sub-step of a
        // frame) reports the sum, as Unity's GPU recorders do over a frame.
        _submitSampleSums.Clear();
        foreach (var (name, begin, end) in f.Samples)
        {
            _submitSampleSums.TryGetValue(name, out double sum);
            _submitSampleSums[name] = sum + Ms(begin, end);
        }
        foreach (var (name, ms) in _submitSampleSums) _sampleResults[name] = ms;
    }

    /// <summary>GPU time of every dispatch of the last submit that recorded any, in order (waits for it).
    /// Empty where the device cannot time or <see cref="VulkanComputeOptions.TimeDispatches"/> is off.</summary>
    public IReadOnlyList<(string Kernel, double Milliseconds)> LastDispatchTimings
    {
        get
        {
            ThrowIfDisposed();
            WaitForSerial(_submittedSerial);
            return _lastDispatchTimings;
        }
    }

    readonly List<(string Kernel, double Milliseconds)> _accumulatedTimings = new();

    /// <summary>When true, every timed dispatch is also kept for <see cref="TakeDispatchTimings"/>
    /// (a benchmark over many submits); off by default so a long run does not grow a list.</summary>
    public bool AccumulateDispatchTimings { get; set; }

}
