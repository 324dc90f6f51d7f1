using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Runtime.InteropServices;
using System.Threading.Tasks;
using Silk.NET.Core.Native;
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
        public readonly List<QueryPool> QueryPools = new();
        public uint QueriesUsed;
        public readonly List<(string Kernel, uint Query)> DispatchQueries = new();
        public readonly List<(string Name, uint Begin, uint End)> Samples = new();
    }

    // ---------------------------------------------------------------- property ids (process-wide, like Shader.PropertyToID)

    static readonly object PropertyLock = new();
    static readonly Dictionary<string, int> PropertyIds = new(StringComparer.Ordinal);
    static readonly List<string> PropertyNames = new();

    public int PropertyId(string name) => PropertyIdOf(name);

    /// <summary>The process-wide id of a shader property name.</summary>
    public static int PropertyIdOf(string name)
    {
        if (name == null) throw new ArgumentNullException(nameof(name));
        lock (PropertyLock)
        {
            if (PropertyIds.TryGetValue(name, out int id)) return id;
            id = PropertyNames.Count;
            PropertyNames.Add(name);
            PropertyIds[name] = id;
            return id;
        }
    }

    /// <summary>The name behind a property id.</summary>
    public static string PropertyName(int id)
    {
        lock (PropertyLock)
        {
            if (id < 0 || id >= PropertyNames.Count) throw new ComputeException($"Property id {id} was not made by PropertyId");
            return PropertyNames[id];
        }
    }

    // ---------------------------------------------------------------- programs

    public IComputeProgram LoadProgram(string name)
    {
        ThrowIfDisposed();
        if (string.IsNullOrWhiteSpace(name)) throw new ArgumentException("LoadProgram needs the .compute file name without extension", nameof(name));
        string path = FindProgramFile(name);
        var source = ComputeSource.Load(path, IncludeDirectories);
        if (source.Kernels.Count == 0) throw new ComputeException($"{path} declares no kernel (#pragma kernel Name)");
        var program = new VulkanProgram(this, name, source);
        program.CompileCurrentVariants();
        return program;
    }

    IReadOnlyList<string> IncludeDirectories => ShaderDirectories.Concat(_options.IncludeDirectories.Select(Path.GetFullPath)).Distinct().ToList();

    string FindProgramFile(string name)
    {
        string file = name.EndsWith(".compute", StringComparison.OrdinalIgnoreCase) ? name : name + ".compute";
        if (Path.IsPathRooted(file))
        {
            if (File.Exists(file)) return Path.GetFullPath(file);
            throw new ComputeException($"Compute program '{name}' not found: {file} does not exist");
        }
        foreach (var dir in ShaderDirectories)
        {
            string candidate = Path.Combine(dir, file);
            if (File.Exists(candidate)) return Path.GetFullPath(candidate);
        }
        foreach (var dir in ShaderDirectories.Where(Directory.Exists))
        {
            var hit = Directory.EnumerateFiles(dir, Path.GetFileName(file), SearchOption.AllDirectories).OrderBy(p => p.Length).FirstOrDefault();
            if (hit != null) return Path.GetFullPath(hit);
        }
        throw new ComputeException($"Compute program '{name}' not found: no {file} in {(ShaderDirectories.Count == 0 ? "(no shader directories configured)" : string.Join(", ", ShaderDirectories))}");
    }

    VulkanProgram AsProgram(IComputeProgram program, string what)
    {
        if (program == null) throw new ArgumentNullException(nameof(program), $"{what}: program is null");
        if (program is not VulkanProgram p || p.Device != this) throw new ComputeException($"{what}: program '{program.Name}' was not loaded by this Vulkan device");
        return p;
    }

    internal KernelVariant GetVariant(VulkanProgram program, string kernel, IReadOnlyList<string> defines)
    {
        string key = Compiler.Key(program.Source, kernel, defines);
        if (_variantCache.TryGetValue(key, out var v)) return v;
        var words = Compiler.Compile(program.Source, kernel, defines, IncludeDirectories);
        return AddVariant(key, kernel, defines, words, program.Source.Path);
    }

    KernelVariant AddVariant(string key, string kernel, IReadOnlyList<string> defines, uint[] words, string path)
    {
        SpirvReflection reflection;
        try { reflection = SpirvReflection.Read(words); }
        catch (FormatException e) { throw new ComputeException($"{path}: kernel '{kernel}' produced unreadable SPIR-V: {e.Message}", e); }
        var v = new KernelVariant(kernel, defines, words, reflection);
        v.StorageBuffers = reflection.Resources.Where(r => r.Kind == SpirvResourceKind.StorageBuffer).ToArray();
        v.StorageBufferIds = v.StorageBuffers.Select(r => PropertyIdOf(r.Name)).ToArray();
        v.Textures = reflection.Resources.Where(r => r.Kind == SpirvResourceKind.StorageImage || r.Kind == SpirvResourceKind.SampledImage).ToArray();
        v.TextureIds = v.Textures.Select(r => PropertyIdOf(r.Name)).ToArray();
        v.Samplers = reflection.Resources.Where(r => r.Kind == SpirvResourceKind.Sampler).ToArray();
        v.UniformBlocks = reflection.UniformBlocks
            .Select(b => (b, b.Members.Values.Select(m => (PropertyIdOf(m.Name), m)).ToArray()))
            .ToArray();
        v.Unsupported = WhyUnrunnable(reflection, words);
        _variantCache[key] = v;
        return v;
    }

    /// <summary>Why this device cannot run a kernel variant that compiled, or null. Such a kernel fails alone, at its
    /// first dispatch, so the other kernels of its program stay usable (as a texture kernel beside buffer kernels).</summary>
    string WhyUnrunnable(SpirvReflection reflection, uint[] words)
    {
        if (reflection.UnsupportedResources.Count > 0)
            return $"it binds {string.Join(", ", reflection.UnsupportedResources.Select(r => $"'{r.Name}' ({r.HlslType})"))}; " +
                   "the headless backend binds structured and byte-address buffers, globals, Texture2D/3D, RWTexture2D/3D and SamplerState, " +
                   "but no typed buffers, texture arrays, cube or multisampled textures";
        foreach (var r in reflection.Resources)
            if (r.Name.EndsWith("@count", StringComparison.Ordinal))
                return $"it uses a hidden counter buffer '{r.Name}' (IncrementCounter/Append/Consume), which the headless backend does not support; count with InterlockedAdd on a buffer of its own";
        foreach (var r in reflection.Resources)
            if (r.Set != 0) return $"it puts '{r.Name}' in descriptor set {r.Set}; only set 0 is supported";
        if (!ScalarBlockLayout && !StructuredBufferPacking.FollowsStd430(words))
            return $"its structured buffers are packed as in D3D/Unity (e.g. 12-byte float3), which needs the scalarBlockLayout feature that {DeviceName} lacks";
        return null;
    }

    /// <summary>Compiles variants that are not yet cached in memory, several glslang processes at a time.</summary>
    internal void Precompile(VulkanProgram program, IReadOnlyList<(string Kernel, IReadOnlyList<string> Defines)> variants)
    {
        var todo = variants.Select(v => (v.Kernel, v.Defines, Key: Compiler.Key(program.Source, v.Kernel, v.Defines)))
            .Where(v => !_variantCache.ContainsKey(v.Key)).GroupBy(v => v.Key).Select(g => g.First()).ToList();
        if (todo.Count == 0) return;
        var words = new uint[todo.Count][];
        var includes = IncludeDirectories;
        try
        {
            Parallel.For(0, todo.Count, new ParallelOptions { MaxDegreeOfParallelism = Math.Max(1, Environment.ProcessorCount) },
                i => words[i] = Compiler.Compile(program.Source, todo[i].Kernel, todo[i].Defines, includes));
        }
        catch (AggregateException e)
        {
            var first = e.Flatten().InnerExceptions.OrderBy(x => x is ComputeException ? 0 : 1).First();
            if (first is ComputeException ce) throw new ComputeException(ce.Message, ce);
            throw;
        }
        for (int i = 0; i < todo.Count; i++) AddVariant(todo[i].Key, todo[i].Kernel, todo[i].Defines, words[i], program.Source.Path);
    }

    void CreatePipeline(KernelVariant v)
    {
        if (v.Created) return;
        fixed (uint* code = v.Spirv)
        {
            var moduleInfo = new ShaderModuleCreateInfo { SType = StructureType.ShaderModuleCreateInfo, CodeSize = (nuint)(v.Spirv.Length * 4), PCode = code };
            Check(_vk.CreateShaderModule(_device, &moduleInfo, null, out v.Module), $"vkCreateShaderModule ({v.Kernel})");
        }
        var resources = v.Reflection.Resources;
        var bindings = stackalloc DescriptorSetLayoutBinding[Math.Max(1, resources.Count)];
        for (int i = 0; i < resources.Count; i++)
        {
            bindings[i] = new DescriptorSetLayoutBinding
            {
                Binding = resources[i].Binding,
                DescriptorType = DescriptorTypeOf(resources[i].Kind),
                DescriptorCount = 1,
                StageFlags = ShaderStageFlags.ComputeBit,
            };
        }
        var setInfo = new DescriptorSetLayoutCreateInfo { SType = StructureType.DescriptorSetLayoutCreateInfo, BindingCount = (uint)resources.Count, PBindings = bindings };
        Check(_vk.CreateDescriptorSetLayout(_device, &setInfo, null, out v.SetLayout), "vkCreateDescriptorSetLayout");
        var setLayout = v.SetLayout;
        var layoutInfo = new PipelineLayoutCreateInfo { SType = StructureType.PipelineLayoutCreateInfo, SetLayoutCount = 1, PSetLayouts = &setLayout };
        Check(_vk.CreatePipelineLayout(_device, &layoutInfo, null, out v.Layout), "vkCreatePipelineLayout");
        var entry = (byte*)SilkMarshal.StringToPtr(v.Reflection.EntryPoint);
        try
        {
            var info = new ComputePipelineCreateInfo
            {
                SType = StructureType.ComputePipelineCreateInfo,
                Stage = new PipelineShaderStageCreateInfo { SType = StructureType.PipelineShaderStageCreateInfo, Stage = ShaderStageFlags.ComputeBit, Module = v.Module, PName = entry },
                Layout = v.Layout,
            };
            Pipeline pipeline;
            Check(_vk.CreateComputePipelines(_device, default, 1, &info, null, &pipeline), $"vkCreateComputePipelines ({v.Kernel})");
            v.Pipeline = pipeline;
        }
        finally { SilkMarshal.Free((nint)entry); }
        v.Created = true;
    }

    static DescriptorType DescriptorTypeOf(SpirvResourceKind kind) => kind switch
    {
        SpirvResourceKind.StorageBuffer => DescriptorType.StorageBuffer,
        SpirvResourceKind.StorageImage => DescriptorType.StorageImage,
        SpirvResourceKind.SampledImage => DescriptorType.SampledImage,
        SpirvResourceKind.Sampler => DescriptorType.Sampler,
        _ => DescriptorType.UniformBuffer,
    };

    void DestroyVariant(KernelVariant v)
    {
        if (!v.Created) return;
        _vk.DestroyPipeline(_device, v.Pipeline, null);
        _vk.DestroyPipelineLayout(_device, v.Layout, null);
        _vk.DestroyDescriptorSetLayout(_device, v.SetLayout, null);
        _vk.DestroyShaderModule(_device, v.Module, null);
        v.Created = false;
    }

    // ---------------------------------------------------------------- parameters

    public void SetBuffer(IComputeProgram program, int kernel, int propertyId, IComputeBuffer buffer)
    {
        ThrowIfDisposed();
        var p = AsProgram(program, "SetBuffer");
        p.CheckKernel(kernel);
        string name = PropertyName(propertyId);
        var b = AsBuffer(buffer, $"SetBuffer '{name}' on kernel '{p.KernelName(kernel)}'");
        if (b.IsConstant)
            throw new ComputeException($"SetBuffer '{name}' on kernel '{p.KernelName(kernel)}': buffer '{b.Name}' is a constant buffer; bind it with SetConstantBuffer");
        var variant = p.Variant(kernel);
        int index = Array.IndexOf(variant.StorageBufferIds, propertyId);
        if (index >= 0) CheckStride(p, variant, variant.StorageBuffers[index], b);
        else if (!p.AnyCompiledVariantDeclares(name) && !p.Source.DeclaresBuffer(name))
            throw new ComputeException($"SetBuffer: no kernel of {p.Path} declares a buffer named '{name}' (kernel '{p.KernelName(kernel)}' reads {Describe(variant.StorageBuffers)})");
        p.Bindings[kernel][propertyId] = b;
    }

    static string Describe(SpirvResource[] buffers) => buffers.Length == 0 ? "no buffer" : string.Join(", ", buffers.Select(r => r.Name));

    static void CheckStride(VulkanProgram p, KernelVariant v, SpirvResource r, VulkanBuffer b)
    {
        if (r.ArrayStride == 0 || r.ArrayStride == b.Stride) return;
        throw new ComputeException($"Stride mismatch: buffer '{b.Name}' has {b.Stride}-byte elements but kernel '{v.Kernel}' of {p.Path} reads '{r.Name}' as {r.ArrayStride}-byte elements " +
                                   "(laid out as D3D/Unity packs structured buffers: members one after another, float3 = 12 bytes; the C# struct must match)");
    }

    GlobalValue Global(IComputeProgram program, int propertyId, string what)
    {
        ThrowIfDisposed();
        var p = AsProgram(program, what);
        if (!p.Globals.TryGetValue(propertyId, out var g))
        {
            PropertyName(propertyId);
            g = new GlobalValue();
            p.Globals[propertyId] = g;
        }
        return g;
    }

    public void SetInt(IComputeProgram program, int propertyId, int value)
    {
        var g = Global(program, propertyId, "SetInt");
        g.Words[0] = (uint)value;
        g.Count = 1;
        g.IsMatrix = false;
    }

    public void SetFloat(IComputeProgram program, int propertyId, float value)
    {
        var g = Global(program, propertyId, "SetFloat");
        g.Words[0] = BitConverter.SingleToUInt32Bits(value);
        g.Count = 1;
        g.IsMatrix = false;
    }

    public void SetInts(IComputeProgram program, int propertyId, params int[] values)
    {
        if (values == null) throw new ArgumentNullException(nameof(values));
        if (values.Length > 16) throw new ComputeException($"SetInts '{PropertyName(propertyId)}': at most 16 values (was {values.Length})");
        var g = Global(program, propertyId, "SetInts");
        for (int i = 0; i < values.Length; i++) g.Words[i] = (uint)values[i];
        g.Count = values.Length;
        g.IsMatrix = false;
    }

    public void SetVector(IComputeProgram program, int propertyId, Vector4 value)
    {
        var g = Global(program, propertyId, "SetVector");
        g.Words[0] = BitConverter.SingleToUInt32Bits(value.X);
        g.Words[1] = BitConverter.SingleToUInt32Bits(value.Y);
        g.Words[2] = BitConverter.SingleToUInt32Bits(value.Z);
        g.Words[3] = BitConverter.SingleToUInt32Bits(value.W);
        g.Count = 4;
        g.IsMatrix = false;
    }

    public void SetMatrix(IComputeProgram program, int propertyId, Matrix4x4 m)
    {
        var g = Global(program, propertyId, "SetMatrix");
        float* src = (float*)&m; // M11 M12 M13 M14 M21 ... : managed row r, column c at 4(r-1)+(c-1)
        for (int i = 0; i < 16; i++) g.Words[i] = BitConverter.SingleToUInt32Bits(src[i]);
        g.Count = 16;
        g.IsMatrix = true;
    }

    public void SetConstantBuffer(IComputeProgram program, int propertyId, IComputeBuffer buffer)
    {
        ThrowIfDisposed();
        var p = AsProgram(program, "SetConstantBuffer");
        string name = PropertyName(propertyId);
        var b = AsBuffer(buffer, $"SetConstantBuffer '{name}' on {p.Path}");
        if (!b.IsConstant)
            throw new ComputeException($"SetConstantBuffer '{name}' on {p.Path}: buffer '{b.Name}' is a structured buffer; make it with CreateConstantBuffer");
        p.ConstantBuffers[propertyId] = b;
    }

    /// <summary>vkCmdUpdateBuffer between two barriers: the dispatches before it have read the old contents, the ones
    /// after it read the new.</summary>
    public void UpdateBuffer<T>(IComputeBuffer buffer, T[] data) where T : struct
    {
        ThrowIfDisposed();
        var b = AsBuffer(buffer, "UpdateBuffer");
        if (data == null) throw new ArgumentNullException(nameof(data), $"UpdateBuffer of '{b.Name}'");
        var bytes = MemoryMarshal.AsBytes(data.AsSpan());
        if (bytes.Length == 0) return;
        if (bytes.Length > b.SizeInBytes)
            throw new ArgumentOutOfRangeException(nameof(data), $"UpdateBuffer of '{b.Name}': {bytes.Length} bytes do not fit its {b.SizeInBytes}");
        if (bytes.Length % 4 != 0 || bytes.Length > 65536)
            throw new ComputeException($"UpdateBuffer of '{b.Name}': a recorded update takes a multiple of 4 bytes up to 65536 (was {bytes.Length}); use SetData for more");
        var frame = BeginRecording();
        b.LastUsedSerial = frame.Serial;
        Barrier(frame.Cmd, PipelineStageFlags.ComputeShaderBit, AccessFlags.ShaderReadBit | AccessFlags.UniformReadBit,
            PipelineStageFlags.TransferBit, AccessFlags.TransferWriteBit);
        fixed (byte* source = bytes) _vk.CmdUpdateBuffer(frame.Cmd, b.Handle, 0, (ulong)bytes.Length, source);
        Barrier(frame.Cmd, PipelineStageFlags.TransferBit, AccessFlags.TransferWriteBit,
            PipelineStageFlags.ComputeShaderBit, AccessFlags.ShaderReadBit | AccessFlags.UniformReadBit);
    }

    void Barrier(CommandBuffer cmd, PipelineStageFlags fromStage, AccessFlags from, PipelineStageFlags toStage, AccessFlags to)
    {
        var barrier = new MemoryBarrier { SType = StructureType.MemoryBarrier, SrcAccessMask = from, DstAccessMask = to };
        _vk.CmdPipelineBarrier(cmd, fromStage, toStage, 0, 1, &barrier, 0, null, 0, null);
    }

    public void SetKeyword(IComputeProgram program, string keyword, bool enabled)
    {
        ThrowIfDisposed();
        AsProgram(program, "SetKeyword").SetKeyword(keyword, enabled);
    }

    /// <summary>Writes one global where the kernel reads it. A matrix element HLSL reads as m[r][c] is SPIR-V
    /// column r, row c (glslang maps HLSL rows to SPIR-V columns), placed by the member's RowMajor/MatrixStride.</summary>
    static void WriteGlobal(byte* block, SpirvGlobal member, GlobalValue value)
    {
        uint* words = (uint*)(block + member.Offset);
        if (member.Columns > 0 && value.IsMatrix)
        {
            int hlslRows = member.Columns, hlslCols = member.Components, stride = member.MatrixStride / 4;
            for (int r = 0; r < hlslRows && r < 4; r++)
                for (int c = 0; c < hlslCols && c < 4; c++)
                {
                    int at = member.RowMajor ? c * stride + r : r * stride + c;
                    words[at] = value.Words[r * 4 + c];
                }
            return;
        }
        if (member.ArrayLength > 0)
        {
            int step = Math.Max(1, member.ArrayStride / 4);
            for (int i = 0; i < value.Count && i < member.ArrayLength; i++) words[i * step] = value.Words[i];
            return;
        }
        int n = Math.Min(value.Count, member.Size / 4);
        for (int i = 0; i < n; i++) words[i] = value.Words[i];
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

    void Record(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ, VulkanBuffer indirect, ulong indirectOffset)
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
        foreach (var (block, members) in v.UniformBlocks)
        {
            if (p.ConstantBuffers.TryGetValue(PropertyIdOf(block.Resource.Name), out var constants))
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
            q = AllocateQuery(frame, 2);
            WriteTimestamp(frame, q);
        }
        if (indirect != null)
        {
            indirect.LastUsedSerial = frame.Serial;
            _vk.CmdDispatchIndirect(cmd, indirect.Handle, indirectOffset);
        }
        else
        {
            _vk.CmdDispatch(cmd, (uint)groupsX, (uint)groupsY, (uint)groupsZ);
        }
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
        foreach (var qp in f.QueryPools) _vk.DestroyQueryPool(_device, qp, null);
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
        f.QueriesUsed = 0;
        f.DispatchQueries.Clear();
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

    uint AllocateQuery(Frame f, uint count)
    {
        // Keep a pair inside one pool.
        uint inPool = f.QueriesUsed % QueriesPerPool;
        if (inPool + count > QueriesPerPool) f.QueriesUsed += QueriesPerPool - inPool;
        uint first = f.QueriesUsed;
        for (uint q = first; q < first + count; q++)
        {
            if (q % QueriesPerPool != 0) continue;
            int poolIndex = (int)(q / QueriesPerPool);
            if (poolIndex == f.QueryPools.Count)
            {
                var info = new QueryPoolCreateInfo { SType = StructureType.QueryPoolCreateInfo, QueryType = QueryType.Timestamp, QueryCount = QueriesPerPool };
                Check(_vk.CreateQueryPool(_device, &info, null, out var pool), "vkCreateQueryPool");
                f.QueryPools.Add(pool);
            }
            _vk.CmdResetQueryPool(f.Cmd, f.QueryPools[poolIndex], 0, QueriesPerPool);
        }
        f.QueriesUsed = first + count;
        return first;
    }

    void WriteTimestamp(Frame f, uint query) =>
        _vk.CmdWriteTimestamp(f.Cmd, PipelineStageFlags.ComputeShaderBit, f.QueryPools[(int)(query / QueriesPerPool)], query % QueriesPerPool);

    public void BeginSample(string name)
    {
        ThrowIfDisposed();
        if (name == null) throw new ArgumentNullException(nameof(name));
        if (!_canTime) return;
        var f = BeginRecording();
        uint q = AllocateQuery(f, 1);
        WriteTimestamp(f, q);
        _openSamples[name] = q;
    }

    public void EndSample(string name)
    {
        ThrowIfDisposed();
        if (name == null) throw new ArgumentNullException(nameof(name));
        if (!_canTime) return;
        if (_recording == null || !_openSamples.Remove(name, out uint begin))
            throw new ComputeException($"EndSample('{name}') without a matching BeginSample('{name}') since the last Submit");
        var f = _recording;
        uint end = AllocateQuery(f, 1);
        WriteTimestamp(f, end);
        f.Samples.Add((name, begin, end));
        _sampleSerial[name] = f.Serial;
    }

    public void Submit()
    {
        ThrowIfDisposed();
        var f = _recording;
        if (f == null) return;
        _openSamples.Clear();
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
        if (f.QueriesUsed == 0) return;
        var stamps = new ulong[f.QueriesUsed];
        fixed (ulong* dst = stamps)
        {
            for (int i = 0; i < f.QueryPools.Count; i++)
            {
                uint first = (uint)i * QueriesPerPool;
                if (first >= f.QueriesUsed) break;
                uint n = Math.Min(QueriesPerPool, f.QueriesUsed - first);
                // Skipped slots (a pair never straddles pools) were reset but never written: read only what is available.
                _vk.GetQueryPoolResults(_device, f.QueryPools[i], 0, n, (nuint)(n * 8), dst + first, 8, QueryResultFlags.Result64Bit);
            }
        }
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
        foreach (var (name, begin, end) in f.Samples) _sampleResults[name] = Ms(begin, end);
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

    /// <summary>Every dispatch timed since the last call (with <see cref="AccumulateDispatchTimings"/> on),
    /// in submission order; waits for submitted work first.</summary>
    public IReadOnlyList<(string Kernel, double Milliseconds)> TakeDispatchTimings()
    {
        ThrowIfDisposed();
        WaitForSerial(_submittedSerial);
        var result = _accumulatedTimings.ToArray();
        _accumulatedTimings.Clear();
        return result;
    }

    public bool TryGetSampleMilliseconds(string name, out double milliseconds)
    {
        ThrowIfDisposed();
        milliseconds = 0;
        if (name == null || !_canTime) return false;
        if (_sampleSerial.TryGetValue(name, out ulong serial) && serial <= _submittedSerial && serial > _completedSerial) WaitForSerial(serial);
        return _sampleResults.TryGetValue(name, out milliseconds);
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
            for (int i = 0; i < _frames.Length; i++) { DestroyFrame(_frames[i]); _frames[i] = null; }
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
}
