using System;
using System.Collections.Generic;

namespace SphFluid.Vulkan;

/// <summary>
/// Lays out structured buffers as D3D (and so Unity) does, by rewriting the SPIR-V decorations glslang wrote.
/// D3D packs a structured buffer's elements tightly: every member sits at the next multiple of its scalar
/// size, a float3 takes 12 bytes and an array's stride is its element's size, so
/// <c>StructuredBuffer&lt;float3&gt;</c> has 12-byte elements and <c>struct { float3 a; float3 b; float c; }</c>
/// is 28 bytes. glslang has no HLSL switch for that and always writes std430 offsets (a float3 aligned to 16),
/// which would read a Unity-laid-out buffer at the wrong addresses. The rewritten offsets, strides and matrix
/// strides are legal under Vulkan's scalar block layout (core feature <c>scalarBlockLayout</c> of Vulkan 1.2),
/// which the device enables and spirv-val checks with <c>--scalar-block-layout</c>. Uniform blocks
/// (<c>$Global</c>, <c>cbuffer</c>) are left alone: their globals are written by name at whatever offsets they have.
/// </summary>
public static class StructuredBufferPacking
{
    const ushort OpTypeInt = 21, OpTypeFloat = 22, OpTypeVector = 23, OpTypeMatrix = 24, OpTypeArray = 28, OpTypeRuntimeArray = 29,
        OpTypeStruct = 30, OpTypePointer = 32, OpConstant = 43, OpVariable = 59, OpDecorate = 71, OpMemberDecorate = 72;
    const uint DecoBufferBlock = 3, DecoRowMajor = 4, DecoArrayStride = 6, DecoMatrixStride = 7, DecoOffset = 35;
    const uint StorageUniform = 2, StoragePushConstant = 9, StorageStorageBuffer = 12;

    /// <summary>A copy of <paramref name="spirv"/> whose storage-buffer types carry D3D's packing.</summary>
    /// <exception cref="FormatException">The module cannot be repacked (a type shared with a uniform block that
    /// the new packing would change, or a missing decoration); the message says which.</exception>
    public static uint[] Apply(uint[] spirv) => Repack(spirv, std430: false);

    /// <summary>True when the module's structured buffers are also legal under std430, so a device without
    /// scalar block layout can run it (true of structs built from whole 16-byte groups, as the project's own are).</summary>
    public static bool FollowsStd430(uint[] spirv)
    {
        try { return Repack(spirv, std430: true).AsSpan().SequenceEqual(spirv); }
        catch (FormatException) { return false; }
    }

    static uint[] Repack(uint[] spirv, bool std430)
    {
        var words = (uint[])spirv.Clone();
        var module = new Module(words);
        var storageRoots = new List<uint>();
        var uniformRoots = new List<uint>();
        foreach (var (pointerType, storage) in module.Variables)
        {
            if (!module.Types.TryGetValue(pointerType, out var pointer) || pointer.Op != OpTypePointer) continue;
            uint block = pointer.Operands[1];
            bool isStorage = storage == StorageStorageBuffer || (storage == StorageUniform && module.Decorations.ContainsKey((block, DecoBufferBlock)));
            if (isStorage) storageRoots.Add(block);
            else if (storage == StorageUniform || storage == StoragePushConstant) uniformRoots.Add(block);
        }
        if (storageRoots.Count == 0) return words;

        var layouts = new Dictionary<uint, (int Size, int Align)>();
        var changes = new List<(int Word, uint Value, uint Type)>();
        foreach (uint root in storageRoots) Layout(module, root, std430, layouts, changes);

        var uniformTypes = new HashSet<uint>();
        foreach (uint root in uniformRoots) Reach(module, root, uniformTypes);
        foreach (var (word, value, type) in changes)
        {
            if (words[word] == value) continue;
            if (uniformTypes.Contains(type))
                throw new FormatException($"type '{module.NameOf(type)}' is used by a structured buffer and by a cbuffer, and the two need different layouts; declare a separate struct for each");
            words[word] = value;
        }
        return words;
    }

    /// <summary>Size and alignment of a type under D3D's packing (or std430's, to compare), recording the
    /// decoration words that must say so. std430 differs only in aligning a vector of 2 to twice its scalar and a
    /// vector of 3 or 4 to four times it.</summary>
    static (int Size, int Align) Layout(Module m, uint type, bool std430, Dictionary<uint, (int, int)> done, List<(int, uint, uint)> changes)
    {
        if (done.TryGetValue(type, out var known)) return known;
        if (!m.Types.TryGetValue(type, out var t)) throw new FormatException($"type %{type} of a structured buffer is not declared");
        (int Size, int Align) result;
        switch (t.Op)
        {
            case OpTypeInt:
            case OpTypeFloat:
                result = ((int)t.Operands[0] / 8, (int)t.Operands[0] / 8);
                break;
            case OpTypeVector:
            {
                var scalar = Layout(m, t.Operands[0], std430, done, changes);
                int n = (int)t.Operands[1];
                result = (scalar.Size * n, std430 ? scalar.Align * (n == 2 ? 2 : 4) : scalar.Align);
                break;
            }
            case OpTypeMatrix:
            {
                var column = Layout(m, t.Operands[0], std430, done, changes);
                result = (RoundUp(column.Size, column.Align) * (int)t.Operands[1], column.Align);
                break;
            }
            case OpTypeArray:
            case OpTypeRuntimeArray:
            {
                var element = Layout(m, t.Operands[0], std430, done, changes);
                int stride = RoundUp(element.Size, element.Align);
                changes.Add((m.DecorationWord(type, DecoArrayStride), (uint)stride, type));
                uint length = 0; // a runtime array ends its block, so its size never places a member
                if (t.Op == OpTypeArray && !m.Constants.TryGetValue(t.Operands[1], out length))
                    throw new FormatException($"array '{m.NameOf(type)}' in a structured buffer has a length that is not a constant");
                result = (stride * (int)length, element.Align);
                break;
            }
            case OpTypeStruct:
            {
                int offset = 0, align = 1;
                for (int member = 0; member < t.Operands.Length; member++)
                {
                    uint memberType = t.Operands[member];
                    var inner = Layout(m, memberType, std430, done, changes);
                    offset = RoundUp(offset, inner.Align);
                    changes.Add((m.MemberDecorationWord(type, member, DecoOffset), (uint)offset, type));
                    uint matrix = MatrixInside(m, memberType);
                    if (matrix != 0)
                    {
                        // The stride between the stored vectors: SPIR-V columns, or rows where the member is RowMajor.
                        var mt = m.Types[matrix];
                        int columns = (int)mt.Operands[1];
                        var column = m.Types[mt.Operands[0]];
                        int rows = (int)column.Operands[1];
                        int scalar = Layout(m, column.Operands[0], std430, done, changes).Size;
                        bool rowMajor = m.MemberDecorations.ContainsKey((type, member, DecoRowMajor));
                        int vector = rowMajor ? columns : rows;
                        int stride = std430 ? scalar * (vector == 2 ? 2 : 4) : scalar * vector;
                        changes.Add((m.MemberDecorationWord(type, member, DecoMatrixStride), (uint)stride, type));
                    }
                    offset += inner.Size;
                    align = Math.Max(align, inner.Align);
                }
                result = (RoundUp(offset, align), align);
                break;
            }
            default:
                throw new FormatException($"type '{m.NameOf(type)}' (SPIR-V opcode {t.Op}) cannot be laid out in a structured buffer");
        }
        done[type] = result;
        return result;
    }

    /// <summary>The matrix type a member holds directly or through arrays, else 0.</summary>
    static uint MatrixInside(Module m, uint type)
    {
        while (m.Types.TryGetValue(type, out var t))
        {
            if (t.Op == OpTypeMatrix) return type;
            if (t.Op != OpTypeArray && t.Op != OpTypeRuntimeArray) return 0;
            type = t.Operands[0];
        }
        return 0;
    }

    static void Reach(Module m, uint type, HashSet<uint> seen)
    {
        if (!seen.Add(type) || !m.Types.TryGetValue(type, out var t)) return;
        switch (t.Op)
        {
            case OpTypeStruct: foreach (uint member in t.Operands) Reach(m, member, seen); break;
            case OpTypeArray: case OpTypeRuntimeArray: case OpTypeVector: case OpTypeMatrix: Reach(m, t.Operands[0], seen); break;
        }
    }

    static int RoundUp(int value, int align) => (value + align - 1) / align * align;

    /// <summary>The instructions the packing needs, with the positions of the decoration words it rewrites.</summary>
    sealed class Module
    {
        public readonly Dictionary<uint, (ushort Op, uint[] Operands)> Types = new();
        public readonly Dictionary<uint, uint> Constants = new();
        public readonly Dictionary<(uint Id, uint Decoration), int> Decorations = new();
        public readonly Dictionary<(uint Id, int Member, uint Decoration), int> MemberDecorations = new();
        public readonly List<(uint PointerType, uint Storage)> Variables = new();
        readonly Dictionary<uint, string> _names = new();

        public Module(uint[] words)
        {
            if (words.Length < 5 || words[0] != 0x07230203) throw new FormatException("not a SPIR-V module (bad magic number)");
            for (int i = 5; i < words.Length;)
            {
                int count = (int)(words[i] >> 16);
                ushort op = (ushort)(words[i] & 0xFFFF);
                if (count == 0 || i + count > words.Length) throw new FormatException($"truncated SPIR-V instruction at word {i}");
                switch (op)
                {
                    case 5: _names[words[i + 1]] = ReadString(words, i + 2, i + count); break; // OpName
                    case OpTypeInt: case OpTypeFloat: case OpTypeVector: case OpTypeMatrix: case OpTypeArray: case OpTypeRuntimeArray: case OpTypeStruct: case OpTypePointer:
                        Types[words[i + 1]] = (op, words.AsSpan(i + 2, count - 2).ToArray());
                        break;
                    case OpConstant: if (count >= 4) Constants[words[i + 2]] = words[i + 3]; break;
                    case OpVariable: Variables.Add((words[i + 1], words[i + 3])); break;
                    case OpDecorate: Decorations[(words[i + 1], words[i + 2])] = count > 3 ? i + 3 : -1; break;
                    case OpMemberDecorate: MemberDecorations[(words[i + 1], (int)words[i + 2], words[i + 3])] = count > 4 ? i + 4 : -1; break;
                }
                i += count;
            }
        }

        public int DecorationWord(uint id, uint decoration) =>
            Decorations.TryGetValue((id, decoration), out int word) && word >= 0 ? word
                : throw new FormatException($"'{NameOf(id)}' in a structured buffer has no decoration {decoration} to rewrite");

        public int MemberDecorationWord(uint id, int member, uint decoration) =>
            MemberDecorations.TryGetValue((id, member, decoration), out int word) && word >= 0 ? word
                : throw new FormatException($"member {member} of '{NameOf(id)}' in a structured buffer has no decoration {decoration} to rewrite");

        public string NameOf(uint id) => _names.TryGetValue(id, out var n) && n.Length > 0 ? n : "%" + id;

        static string ReadString(uint[] words, int from, int end)
        {
            var bytes = new List<byte>();
            for (int w = from; w < end; w++)
                for (int k = 0; k < 4; k++)
                {
                    byte c = (byte)(words[w] >> (8 * k));
                    if (c == 0) return System.Text.Encoding.UTF8.GetString(bytes.ToArray());
                    bytes.Add(c);
                }
            return System.Text.Encoding.UTF8.GetString(bytes.ToArray());
        }
    }
}
