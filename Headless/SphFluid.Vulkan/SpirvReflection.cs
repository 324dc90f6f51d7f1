using System;
using System.Collections.Generic;
using System.Text;

namespace SphFluid.Vulkan;

/// <summary>Kind of a resource a kernel binds.</summary>
public enum SpirvResourceKind { StorageBuffer, UniformBuffer, StorageImage, SampledImage, Sampler }

/// <summary>One descriptor a kernel declares, by the HLSL name of the variable.</summary>
/// <param name="ElementType">For a structured buffer, its element type in HLSL words: "uint", "float4", or the struct's name.</param>
/// <param name="ElementIsStruct">True when <paramref name="ElementType"/> names a struct.</param>
/// <param name="ImageDimensions">For a texture: 2 or 3 (<c>Texture2D</c>, <c>RWTexture3D</c>...); its
/// <paramref name="ElementType"/> is the scalar it holds ("float", "uint", "int").</param>
/// <param name="ImageFormat">For an <c>RWTexture</c>: the SPIR-V image format glslang chose from its element type
/// (1 Rgba32f, 3 R32f, 6 Rg32f, 24 R32i, 30 Rgba32ui, 33 R32ui); 0 where any format of that scalar fits.</param>
public sealed record SpirvResource(string Name, SpirvResourceKind Kind, uint Set, uint Binding, int ArrayStride, bool ReadOnly,
    string ElementType = "", bool ElementIsStruct = false, int ImageDimensions = 0, uint ImageFormat = 0);

/// <summary>One member of the <c>$Global</c> uniform block: where HLSL reads it and how it is shaped.</summary>
/// <param name="Columns">SPIR-V columns of a matrix (HLSL rows); 0 for scalars and vectors.</param>
/// <param name="Components">Components of a vector (or of each SPIR-V column of a matrix); 1 for scalars.</param>
public sealed record SpirvGlobal(string Name, int Offset, int Size, int Components, int Columns, int MatrixStride, bool RowMajor, int ArrayLength, int ArrayStride);

/// <summary>A uniform block (<c>$Global</c>, or a named <c>cbuffer</c>) and its members by name.</summary>
public sealed record SpirvUniformBlock(SpirvResource Resource, int Size, IReadOnlyDictionary<string, SpirvGlobal> Members);

/// <summary>
/// What the host must know about one compiled kernel, read straight from the SPIR-V decorations
/// (names, bindings, block offsets, strides, local size). Reading the words ourselves avoids a
/// spirv-cross process per variant and sees exactly what the driver will see.
/// </summary>
public sealed class SpirvReflection
{
    public string EntryPoint { get; private init; } = "";
    public uint LocalSizeX { get; private init; } = 1;
    public uint LocalSizeY { get; private init; } = 1;
    public uint LocalSizeZ { get; private init; } = 1;
    public IReadOnlyList<SpirvResource> Resources { get; private init; } = Array.Empty<SpirvResource>();
    /// <summary>The <c>$Global</c> block's members by name; empty when the kernel reads no global.</summary>
    public IReadOnlyDictionary<string, SpirvGlobal> Globals { get; private init; } = new Dictionary<string, SpirvGlobal>();
    public int GlobalBlockSize { get; private init; }
    public SpirvResource? GlobalBlock { get; private init; }
    /// <summary>Every uniform block, <c>$Global</c> included; globals set by name may live in any of them.</summary>
    public IReadOnlyList<SpirvUniformBlock> UniformBlocks { get; private init; } = Array.Empty<SpirvUniformBlock>();
    /// <summary>Bound resources the backend cannot provide (texture arrays, cube maps, multisampled textures, typed
    /// buffers): their names and HLSL types ("Texture2DArray", "Buffer").</summary>
    public IReadOnlyList<(string Name, string HlslType)> UnsupportedResources { get; private init; } = Array.Empty<(string, string)>();

    const uint Magic = 0x07230203;

    sealed class TypeInfo
    {
        public ushort Op;
        public uint[] Operands = Array.Empty<uint>();
    }

    public static SpirvReflection Read(ReadOnlySpan<uint> words)
    {
        if (words.Length < 5 || words[0] != Magic) throw new FormatException("not a SPIR-V module (bad magic number)");

        var names = new Dictionary<uint, string>();
        var memberNames = new Dictionary<(uint, uint), string>();
        var decorations = new Dictionary<(uint id, uint deco), uint>();
        var memberDecorations = new Dictionary<(uint id, uint member, uint deco), uint>();
        var types = new Dictionary<uint, TypeInfo>();
        var constants = new Dictionary<uint, uint>();
        var variables = new List<(uint type, uint id, uint storage)>();
        string entry = "";
        uint entryId = 0;
        uint lx = 1, ly = 1, lz = 1;

        for (int i = 5; i < words.Length;)
        {
            uint head = words[i];
            int count = (int)(head >> 16);
            ushort op = (ushort)(head & 0xFFFF);
            if (count == 0 || i + count > words.Length) throw new FormatException($"truncated SPIR-V instruction at word {i}");
            var ops = words.Slice(i + 1, count - 1);
            switch (op)
            {
                case 5: names[ops[0]] = ReadString(ops.Slice(1)); break; // OpName
                case 6: memberNames[(ops[0], ops[1])] = ReadString(ops.Slice(2)); break; // OpMemberName
                case 15: // OpEntryPoint
                    entryId = ops[1];
                    entry = ReadString(ops.Slice(2));
                    break;
                case 16: // OpExecutionMode
                    if (ops[1] == 17 && ops.Length >= 5) { lx = ops[2]; ly = ops[3]; lz = ops[4]; }
                    break;
                case 71: decorations[(ops[0], ops[1])] = ops.Length > 2 ? ops[2] : 1; break; // OpDecorate
                case 72: memberDecorations[(ops[0], ops[1], ops[2])] = ops.Length > 3 ? ops[3] : 1; break; // OpMemberDecorate
                case 21: case 22: case 23: case 24: case 25: case 26: case 27: case 28: case 29: case 30: case 32: // int float vector matrix image sampler sampled-image array rtarray struct pointer
                    types[ops[0]] = new TypeInfo { Op = op, Operands = ops.Slice(1).ToArray() };
                    break;
                case 43: // OpConstant
                    if (ops.Length >= 3) constants[ops[1]] = ops[2];
                    break;
                case 59: variables.Add((ops[0], ops[1], ops[2])); break; // OpVariable
            }
            i += count;
        }

        const uint DecoBlock = 2, DecoBufferBlock = 3, DecoRowMajor = 4, DecoArrayStride = 6, DecoMatrixStride = 7,
            DecoNonWritable = 24, DecoBinding = 33, DecoSet = 34, DecoOffset = 35;
        const uint StorageUniform = 2, StorageStorageBuffer = 12;

        var resources = new List<SpirvResource>();
        var globals = new Dictionary<string, SpirvGlobal>();
        var blocks = new List<SpirvUniformBlock>();
        int globalSize = 0;
        SpirvResource? globalBlock = null;

        int SizeOf(uint typeId, uint parent, uint member)
        {
            var t = types[typeId];
            switch (t.Op)
            {
                case 21: case 22: return (int)t.Operands[0] / 8;
                case 23: return (int)t.Operands[1] * SizeOf(t.Operands[0], 0, 0);
                case 24:
                {
                    int columns = (int)t.Operands[1];
                    int rows = (int)types[t.Operands[0]].Operands[1];
                    int stride = memberDecorations.TryGetValue((parent, member, DecoMatrixStride), out uint ms) ? (int)ms : 16;
                    bool rowMajor = memberDecorations.ContainsKey((parent, member, DecoRowMajor));
                    return rowMajor ? (rows - 1) * stride + columns * 4 : (columns - 1) * stride + rows * 4;
                }
                case 28:
                {
                    int length = constants.TryGetValue(t.Operands[1], out uint n) ? (int)n : 1;
                    int stride = decorations.TryGetValue((typeId, DecoArrayStride), out uint s) ? (int)s : SizeOf(t.Operands[0], parent, member);
                    return length * stride;
                }
                case 29: return 0;
                case 30:
                {
                    int size = 0;
                    for (uint m = 0; m < t.Operands.Length; m++)
                    {
                        int off = memberDecorations.TryGetValue((typeId, m, DecoOffset), out uint o) ? (int)o : size;
                        size = Math.Max(size, off + SizeOf(t.Operands[m], typeId, m));
                    }
                    return size;
                }
                default: return 4;
            }
        }

        var unsupported = new List<(string, string)>();
        string HlslTypeName(uint typeId)
        {
            if (!types.TryGetValue(typeId, out var t)) return "?";
            switch (t.Op)
            {
                case 21: return t.Operands[1] == 1 ? "int" : "uint";
                case 22: return t.Operands[0] == 64 ? "double" : t.Operands[0] == 16 ? "half" : "float";
                case 23: return HlslTypeName(t.Operands[0]) + t.Operands[1];
                case 24: return HlslTypeName(types[t.Operands[0]].Operands[0]) + t.Operands[1] + "x" + types[t.Operands[0]].Operands[1];
                default: return "?";
            }
        }

        // HLSL's name for a texture, typed buffer or sampler type, from the SPIR-V image operands
        // (sampled type, Dim, Depth, Arrayed, MS, Sampled, Format).
        string OpaqueTypeName(uint typeId)
        {
            if (!types.TryGetValue(typeId, out var t)) return "resource";
            if (t.Op == 28 || t.Op == 29) return OpaqueTypeName(t.Operands[0]) + "[]";
            if (t.Op == 26) return "SamplerState";
            if (t.Op == 27) return OpaqueTypeName(t.Operands[0]);
            if (t.Op != 25 || t.Operands.Length < 6) return "resource";
            string rw = t.Operands[5] == 2 ? "RW" : "";
            string shape = t.Operands[1] switch { 0 => "Texture1D", 1 => "Texture2D", 2 => "Texture3D", 3 => "TextureCube", 5 => "Buffer", _ => "Texture" };
            return rw + shape + (t.Operands[4] == 1 ? "MS" : "") + (t.Operands[3] == 1 ? "Array" : "");
        }

        foreach (var (ptrType, id, storage) in variables)
        {
            if (storage == 0 && decorations.ContainsKey((id, DecoBinding)) && types.TryGetValue(ptrType, out var imagePtr) && imagePtr.Op == 32
                && types.TryGetValue(imagePtr.Operands[1], out var image) && image.Op == 25 && image.Operands.Length >= 7
                && (image.Operands[1] == 1 || image.Operands[1] == 2) && image.Operands[3] == 0 && image.Operands[4] == 0
                && (image.Operands[5] == 1 || image.Operands[5] == 2))
            {
                // A Texture2D/3D or RWTexture2D/3D (Dim 2D or 3D, not arrayed, not multisampled): bound by the backend.
                bool storageImage = image.Operands[5] == 2;
                resources.Add(new SpirvResource(names.TryGetValue(id, out var imageName) ? imageName : $"%{id}",
                    storageImage ? SpirvResourceKind.StorageImage : SpirvResourceKind.SampledImage,
                    decorations.TryGetValue((id, DecoSet), out uint imageSet) ? imageSet : 0, decorations[(id, DecoBinding)], 0, !storageImage,
                    HlslTypeName(image.Operands[0]), false, image.Operands[1] == 1 ? 2 : 3, image.Operands[6]));
                continue;
            }
            if (storage == 0 && decorations.ContainsKey((id, DecoBinding)) && types.TryGetValue(ptrType, out var samplerPtr) && samplerPtr.Op == 32
                && types.TryGetValue(samplerPtr.Operands[1], out var sampler) && sampler.Op == 26)
            {
                resources.Add(new SpirvResource(names.TryGetValue(id, out var samplerName) ? samplerName : $"%{id}", SpirvResourceKind.Sampler,
                    decorations.TryGetValue((id, DecoSet), out uint samplerSet) ? samplerSet : 0, decorations[(id, DecoBinding)], 0, true));
                continue;
            }
            if (storage == 0 && decorations.ContainsKey((id, DecoBinding)))
            {
                unsupported.Add((names.TryGetValue(id, out var un) && un.Length > 0 ? un : $"%{id}",
                    types.TryGetValue(ptrType, out var opaque) && opaque.Op == 32 ? OpaqueTypeName(opaque.Operands[1]) : "resource"));
                continue;
            }
            if (storage != StorageUniform && storage != StorageStorageBuffer) continue;
            if (!types.TryGetValue(ptrType, out var ptr) || ptr.Op != 32) continue;
            uint blockType = ptr.Operands[1];
            if (!types.TryGetValue(blockType, out var block) || block.Op != 30) continue;
            uint set = decorations.TryGetValue((id, DecoSet), out uint s) ? s : 0;
            uint binding = decorations.TryGetValue((id, DecoBinding), out uint b) ? b : 0;
            string typeName = names.TryGetValue(blockType, out var tn) ? tn : "";
            string varName = names.TryGetValue(id, out var vn) && vn.Length > 0 ? vn : typeName;

            bool isSsbo = storage == StorageStorageBuffer || decorations.ContainsKey((blockType, DecoBufferBlock));
            if (isSsbo)
            {
                // A structured buffer is a block whose one member is the runtime array of elements.
                int stride = 0;
                string elementType = "";
                bool elementIsStruct = false;
                bool readOnly = block.Operands.Length > 0 && memberDecorations.ContainsKey((blockType, 0, DecoNonWritable));
                if (block.Operands.Length > 0 && types.TryGetValue(block.Operands[^1], out var arr) && (arr.Op == 29 || arr.Op == 28))
                {
                    stride = decorations.TryGetValue((block.Operands[^1], DecoArrayStride), out uint st) ? (int)st : 0;
                    uint elementId = arr.Operands[0];
                    elementIsStruct = types.TryGetValue(elementId, out var et) && et.Op == 30;
                    elementType = elementIsStruct ? (names.TryGetValue(elementId, out var sn) ? sn : "struct") : HlslTypeName(elementId);
                }
                resources.Add(new SpirvResource(varName, SpirvResourceKind.StorageBuffer, set, binding, stride, readOnly, elementType, elementIsStruct));
            }
            else if (decorations.ContainsKey((blockType, DecoBlock)))
            {
                var res = new SpirvResource(typeName == "$Global" ? "$Global" : varName, SpirvResourceKind.UniformBuffer, set, binding, 0, true);
                resources.Add(res);
                var members = new Dictionary<string, SpirvGlobal>();
                int blockSize = 0;
                for (uint m = 0; m < block.Operands.Length; m++)
                {
                    if (!memberNames.TryGetValue((blockType, m), out var name)) continue;
                    uint mt = block.Operands[m];
                    int offset = memberDecorations.TryGetValue((blockType, m, DecoOffset), out uint o) ? (int)o : 0;
                    int size = SizeOf(mt, blockType, m);
                    int arrayLength = 0, arrayStride = 0;
                    var t = types[mt];
                    if (t.Op == 28)
                    {
                        arrayLength = constants.TryGetValue(t.Operands[1], out uint n) ? (int)n : 1;
                        arrayStride = decorations.TryGetValue((mt, DecoArrayStride), out uint ast) ? (int)ast : 16;
                        t = types[t.Operands[0]];
                    }
                    int components = 1, columns = 0, matrixStride = 0;
                    bool rowMajor = false;
                    if (t.Op == 23) components = (int)t.Operands[1];
                    else if (t.Op == 24)
                    {
                        columns = (int)t.Operands[1];
                        components = (int)types[t.Operands[0]].Operands[1];
                        matrixStride = memberDecorations.TryGetValue((blockType, m, DecoMatrixStride), out uint ms) ? (int)ms : 16;
                        rowMajor = memberDecorations.ContainsKey((blockType, m, DecoRowMajor));
                    }
                    members[name] = new SpirvGlobal(name, offset, size, components, columns, matrixStride, rowMajor, arrayLength, arrayStride);
                    blockSize = Math.Max(blockSize, offset + size);
                }
                blockSize = (blockSize + 15) & ~15;
                blocks.Add(new SpirvUniformBlock(res, blockSize, members));
                if (typeName == "$Global")
                {
                    globalBlock = res;
                    globalSize = blockSize;
                    foreach (var kv in members) globals[kv.Key] = kv.Value;
                }
            }
        }

        return new SpirvReflection
        {
            EntryPoint = entry,
            LocalSizeX = lx, LocalSizeY = ly, LocalSizeZ = lz,
            Resources = resources,
            Globals = globals,
            GlobalBlockSize = globalSize,
            UniformBlocks = blocks,
            UnsupportedResources = unsupported,
            GlobalBlock = globalBlock,
        };
    }

    static string ReadString(ReadOnlySpan<uint> words)
    {
        var bytes = new List<byte>(words.Length * 4);
        foreach (uint w in words)
        {
            for (int k = 0; k < 4; k++)
            {
                byte c = (byte)(w >> (8 * k));
                if (c == 0) return Encoding.UTF8.GetString(bytes.ToArray());
                bytes.Add(c);
            }
        }
        return Encoding.UTF8.GetString(bytes.ToArray());
    }
}
