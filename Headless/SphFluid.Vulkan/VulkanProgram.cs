using System;
using System.Collections.Generic;
using System.Linq;
using SphFluid.Compute;
using Silk.NET.Vulkan;

namespace SphFluid.Vulkan;

/// <summary>One compiled kernel variant: its reflection and, once dispatched, its pipeline.</summary>
public sealed class KernelVariant
{
    public string Kernel { get; }
    public IReadOnlyList<string> Defines { get; }
    public SpirvReflection Reflection { get; }
    internal uint[] Spirv;
    internal ShaderModule Module;
    internal DescriptorSetLayout SetLayout;
    internal PipelineLayout Layout;
    internal Pipeline Pipeline;
    internal bool Created;
    /// <summary>Why this device cannot run the variant (it fails at dispatch), or null.</summary>
    internal string? Unsupported;
    /// <summary>Property ids of the storage buffers, parallel to <see cref="StorageBuffers"/>.</summary>
    internal int[] StorageBufferIds = Array.Empty<int>();
    internal SpirvResource[] StorageBuffers = Array.Empty<SpirvResource>();
    /// <summary>Property ids of the textures, parallel to <see cref="Textures"/>.</summary>
    internal int[] TextureIds = Array.Empty<int>();
    internal SpirvResource[] Textures = Array.Empty<SpirvResource>();
    internal SpirvResource[] Samplers = Array.Empty<SpirvResource>();
    /// <summary>Each uniform block with its own property id (a cbuffer bound by name) and its members' ids.</summary>
    internal (SpirvUniformBlock Block, int BlockId, (int Id, SpirvGlobal Member)[] Members)[] UniformBlocks =
        Array.Empty<(SpirvUniformBlock, int, (int, SpirvGlobal)[])>();

    internal KernelVariant(string kernel, IReadOnlyList<string> defines, uint[] spirv, SpirvReflection reflection)
    {
        Kernel = kernel;
        Defines = defines;
        Spirv = spirv;
        Reflection = reflection;
    }
}

/// <summary>A value set with SetInt/SetFloat/SetInts/SetVector/SetMatrix, as 4-byte words in managed order.</summary>
sealed class GlobalValue
{
    public readonly uint[] Words = new uint[16];
    public int Count;
    public bool IsMatrix;
}

/// <summary>
/// A loaded <c>.compute</c> file: its kernels and keywords, the values and buffers set on it, and
/// its compiled variants (compiled on first use, per kernel and keyword combination).
/// </summary>
public sealed class VulkanProgram : IComputeProgram
{
    internal readonly VulkanComputeDevice Device;
    internal readonly ComputeSource Source;
    readonly Dictionary<string, int> _kernelIndex = new(StringComparer.Ordinal);
    internal readonly HashSet<string> EnabledKeywords = new(StringComparer.Ordinal);
    internal readonly Dictionary<int, GlobalValue> Globals = new();
    internal readonly Dictionary<int, VulkanBuffer>[] Bindings;
    /// <summary>Constant buffers bound by cbuffer name (SetConstantBuffer), for every kernel.</summary>
    internal readonly Dictionary<int, VulkanBuffer> ConstantBuffers = new();
    internal readonly Dictionary<int, VulkanTexture>[] TextureBindings;
    readonly Dictionary<string, KernelVariant>[] _variants;
    string[] _currentDefines = Array.Empty<string>();
    string _currentDefinesKey = "";

    public string Name { get; }
    public IReadOnlyList<string> Keywords => Source.Keywords;
    public IReadOnlyList<string> KernelNames { get; }

    internal VulkanProgram(VulkanComputeDevice device, string name, ComputeSource source)
    {
        Device = device;
        Name = name;
        Source = source;
        KernelNames = source.Kernels.Select(k => k.Name).ToList();
        for (int i = 0; i < source.Kernels.Count; i++) _kernelIndex.TryAdd(source.Kernels[i].Name, i);
        Bindings = new Dictionary<int, VulkanBuffer>[source.Kernels.Count];
        TextureBindings = new Dictionary<int, VulkanTexture>[source.Kernels.Count];
        _variants = new Dictionary<string, KernelVariant>[source.Kernels.Count];
        for (int i = 0; i < Bindings.Length; i++)
        {
            Bindings[i] = new Dictionary<int, VulkanBuffer>();
            TextureBindings[i] = new Dictionary<int, VulkanTexture>();
            _variants[i] = new Dictionary<string, KernelVariant>(StringComparer.Ordinal);
        }
        UpdateDefines();
    }

    /// <summary>The path of the <c>.compute</c> file.</summary>
    public string Path => Source.Path;

    public int FindKernel(string kernelName)
    {
        if (kernelName != null && _kernelIndex.TryGetValue(kernelName, out int i)) return i;
        throw new ComputeException($"Kernel '{kernelName}' not found in {Source.Path}; its #pragma kernel entries are: {string.Join(", ", KernelNames)}");
    }

    public bool HasKernel(string kernelName) => kernelName != null && _kernelIndex.ContainsKey(kernelName);

    public void GetKernelThreadGroupSizes(int kernel, out uint x, out uint y, out uint z)
    {
        var r = Variant(kernel).Reflection;
        x = r.LocalSizeX; y = r.LocalSizeY; z = r.LocalSizeZ;
    }

    /// <summary>What the kernel's variant for the keywords enabled now declares (compiles it on first use).</summary>
    public SpirvReflection Reflect(int kernel) => Variant(kernel).Reflection;

    /// <summary>Every keyword combination the file's multi_compile sets allow (one keyword or none per set).</summary>
    public IReadOnlyList<IReadOnlyList<string>> KeywordCombinations()
    {
        IEnumerable<List<string>> combos = new[] { new List<string>() };
        foreach (var set in Source.KeywordSets)
            combos = combos.SelectMany(c => set.Select(k => k == null ? c : c.Append(k).ToList())).ToList();
        return combos.Select(c => (IReadOnlyList<string>)c).ToList();
    }

    internal void CheckKernel(int kernel)
    {
        if (kernel < 0 || kernel >= Bindings.Length)
            throw new ComputeException($"Kernel index {kernel} is out of range for {Source.Path} ({Bindings.Length} kernels: {string.Join(", ", KernelNames)})");
    }

    internal string KernelName(int kernel) => Source.Kernels[kernel].Name;

    internal void SetKeyword(string keyword, bool enabled)
    {
        if (!Source.Keywords.Contains(keyword))
            throw new ComputeException($"Keyword '{keyword}' is not declared by a multi_compile pragma in {Source.Path}; declared: {(Source.Keywords.Count == 0 ? "none" : string.Join(", ", Source.Keywords))}");
        bool changed = enabled ? EnabledKeywords.Add(keyword) : EnabledKeywords.Remove(keyword);
        if (changed) UpdateDefines();
    }

    void UpdateDefines()
    {
        _currentDefines = Source.VariantKeywords(EnabledKeywords).ToArray();
        _currentDefinesKey = string.Join(" ", _currentDefines);
    }

    /// <summary>The kernel's variant for the keywords enabled now (compiled on first use).</summary>
    internal KernelVariant Variant(int kernel)
    {
        CheckKernel(kernel);
        if (_variants[kernel].TryGetValue(_currentDefinesKey, out var v)) return v;
        var decl = Source.Kernels[kernel];
        var defines = decl.Defines.Concat(_currentDefines).ToArray();
        v = Device.GetVariant(this, decl.Name, defines);
        _variants[kernel][_currentDefinesKey] = v;
        return v;
    }

    /// <summary>Compiles the current variant of every kernel, in parallel (LoadProgram does this, so syntax
    /// errors surface at load time and later dispatches find everything compiled).</summary>
    internal void CompileCurrentVariants()
    {
        var defines = Source.Kernels.Select(k => k.Defines.Concat(_currentDefines).ToArray()).ToArray();
        Device.Precompile(this, Source.Kernels.Select((k, i) => (k.Name, (IReadOnlyList<string>)defines[i])).ToList());
        for (int i = 0; i < Source.Kernels.Count; i++) Variant(i);
    }

    /// <summary>Compiles every kernel in every keyword combination, several at a time (a build check;
    /// dispatches compile only what they use).</summary>
    public void CompileAllVariants()
    {
        var list = new List<(string Kernel, IReadOnlyList<string> Defines)>();
        foreach (var combo in KeywordCombinations())
        {
            var keywords = Source.VariantKeywords(combo.ToList());
            foreach (var k in Source.Kernels) list.Add((k.Name, k.Defines.Concat(keywords).ToArray()));
        }
        Device.Precompile(this, list);
    }

    internal bool AnyCompiledVariantDeclares(string name) =>
        _variants.Any(d => d.Values.Any(v => v.Reflection.Resources.Any(r => r.Name == name)));

    public override string ToString() => Source.Path;
}
