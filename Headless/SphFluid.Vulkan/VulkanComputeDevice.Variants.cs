using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using Silk.NET.Core.Native;
using Silk.NET.Vulkan;
using SphFluid.Compute;

namespace SphFluid.Vulkan;

/// <summary>Programs and their kernel variants: found, compiled (several glslang processes at a time), reflected, cached by content, and made into pipelines on first dispatch.</summary>
public sealed unsafe partial class VulkanComputeDevice
{
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

    /// <summary>Every kernel variant this device has run (dispatched with groups to run), as its kernel name and its defines,
    /// e.g. "DensitySolveError MULTIPHASE": what a test suite can hold one device's work to another's by.</summary>
    public IReadOnlyCollection<string> DispatchedVariants =>
        _variantCache.Values.Where(v => v.Created).Select(v => string.Join(" ", new[] { v.Kernel }.Concat(v.Defines))).ToHashSet(StringComparer.Ordinal);

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
            .Select(b => (b, PropertyIdOf(b.Resource.Name), b.Members.Values.Select(m => (PropertyIdOf(m.Name), m)).ToArray()))
            .ToArray();
        v.Unsupported = WhyUnrunnable(reflection, words);
        _variantCache[key] = v;
        return v;
    }

    /// <summary>Why this device cannot run a kernel variant that compiled, or null. Such a kernel fails alone, at its
    /// first dispatch, so the other kernels of its program stay usable (as a texture kernel beside buffer kernels).</summary>
    string? WhyUnrunnable(SpirvReflection reflection, uint[] words)
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
}
