using System;
using System.Linq;
using System.Numerics;
using System.Runtime.InteropServices;
using Silk.NET.Vulkan;
using SphFluid.Compute;

namespace SphFluid.Vulkan;

/// <summary>What a dispatch reads: buffers, constant buffers and globals set on a program, and the uploads recorded between dispatches.</summary>
public sealed unsafe partial class VulkanComputeDevice
{
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
}
