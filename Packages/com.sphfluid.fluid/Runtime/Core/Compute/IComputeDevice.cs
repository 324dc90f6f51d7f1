using System;
using System.Numerics;

namespace SphFluid.Compute
{
    /// <summary>
    /// The GPU as the solver sees it, shaped like Unity's <c>CommandBuffer</c>: parameter
    /// setters and dispatches are recorded in order and run on <see cref="Submit"/>.
    /// Unity wraps a real CommandBuffer; the headless backend wraps Vulkan. The SPH pipeline
    /// is written once against this interface so both run the same dispatch sequence.
    /// </summary>
    /// <remarks>
    /// Parameter values are captured when a dispatch is recorded, exactly like
    /// <c>CommandBuffer.SetComputeFloatParam</c> followed by <c>DispatchCompute</c>.
    /// <see cref="IComputeBuffer.SetData{T}(T[])"/> and <see cref="IComputeBuffer.GetData{T}(T[])"/>
    /// submit any recorded work first, so uploads and read-backs see the commands before them.
    /// </remarks>
    public interface IComputeDevice : IDisposable
    {
        /// <summary>Human-readable adapter name, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".</summary>
        string DeviceName { get; }

        /// <summary>True for a device that runs kernels on CPU cores (lavapipe): each thread's loop runs on a core that
        /// hides no latency behind other threads, so the simulation walks each neighbourhood with one thread
        /// (Simulation.NeighbourLanes).</summary>
        bool RunsOnCpu { get; }

        /// <summary>The largest structured buffer this device binds, in bytes (Vulkan's maxStorageBufferRange, Unity's
        /// <c>SystemInfo.maxGraphicsBufferSize</c>): 128 MiB on lavapipe and at least that under D3D11. The simulation
        /// sizes its neighbour lists to it and refuses a scene whose particles do not fit (<c>DeviceCapacity</c>).</summary>
        long MaxBufferBytes { get; }

        /// <summary>Loads a compute shader by its asset name, the file name without extension
        /// (e.g. "ParticleSort" for Packages/com.sphfluid.fluid/Shaders/ParticleSort.compute). Unity resolves it to
        /// a ComputeShader asset the component references; the headless backend compiles the file.
        /// Throws <see cref="ComputeException"/> naming the program when there is none.</summary>
        IComputeProgram LoadProgram(string name);

        /// <summary>A structured buffer of <paramref name="count"/> elements of <paramref name="stride"/> bytes.</summary>
        IComputeBuffer CreateBuffer(string name, int count, int stride);

        /// <summary>A constant buffer of <paramref name="bytes"/> bytes (a multiple of 16) that holds one HLSL <c>cbuffer</c>'s
        /// values, laid out by HLSL's packing rules (Unity: a <c>ComputeBuffer</c> of type Constant). Bind it with
        /// <see cref="SetConstantBuffer"/> and fill it with <see cref="UpdateBuffer{T}"/>.</summary>
        IComputeBuffer CreateConstantBuffer(string name, int bytes);

        /// <summary>Binds <paramref name="buffer"/> (from <see cref="CreateConstantBuffer"/>) as the <c>cbuffer</c> named by
        /// <paramref name="propertyId"/> for every kernel of the program (Unity: <c>CommandBuffer.SetComputeConstantBufferParam</c>).</summary>
        void SetConstantBuffer(IComputeProgram program, int propertyId, IComputeBuffer buffer);

        /// <summary>Records an upload of the whole of <paramref name="data"/> to the start of <paramref name="buffer"/>, run in order
        /// with the dispatches around it: those recorded before it read the old contents, those after it the new
        /// (Unity: <c>CommandBuffer.SetBufferData</c>). The data is copied when the call is recorded, so the array may be reused.</summary>
        void UpdateBuffer<T>(IComputeBuffer buffer, T[] data) where T : struct;

        /// <summary>The integer id of a shader property name (Unity's <c>Shader.PropertyToID</c>).
        /// Look ids up once and keep them.</summary>
        int PropertyId(string name);

        void SetBuffer(IComputeProgram program, int kernel, int propertyId, IComputeBuffer buffer);
        void SetInt(IComputeProgram program, int propertyId, int value);
        void SetFloat(IComputeProgram program, int propertyId, float value);

        /// <summary>Sets an int2/int3/int4/uint3 global; each value fills one 4-byte component.</summary>
        void SetInts(IComputeProgram program, int propertyId, params int[] values);

        /// <summary>Sets a float2/float3/float4 global (unused trailing components are ignored).</summary>
        void SetVector(IComputeProgram program, int propertyId, Vector4 value);

        /// <summary>Sets a float4x4 global. Element <c>M{r}{c}</c> of the managed matrix is what the
        /// kernel reads as <c>m[r-1][c-1]</c>, so transforms are written for column vectors
        /// (<c>mul(m, float4(p, 1))</c>), as in Unity: translation lives in M14, M24, M34.</summary>
        void SetMatrix(IComputeProgram program, int propertyId, Matrix4x4 value);

        /// <summary>Selects a <c>multi_compile</c> keyword variant for later dispatches of the program.</summary>
        void SetKeyword(IComputeProgram program, string keyword, bool enabled);

        /// <summary>Records a dispatch of <paramref name="groupsX"/>·<paramref name="groupsY"/>·<paramref name="groupsZ"/>
        /// thread groups. Refused (with the resource's name) if the kernel reads a buffer that was never bound.</summary>
        void Dispatch(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ);

        /// <summary>A buffer of <paramref name="count"/> uints that kernels write as <c>RWStructuredBuffer&lt;uint&gt;</c> and
        /// <see cref="DispatchIndirect"/> reads its group counts from (Unity: <c>ComputeBufferType.IndirectArguments</c>).</summary>
        IComputeBuffer CreateArgumentsBuffer(string name, int count);

        /// <summary>Records a dispatch whose group counts (three uints: x, y, z) the GPU reads from
        /// <paramref name="arguments"/> at <paramref name="byteOffset"/> when it runs, so that earlier kernels decide how much
        /// work it does (0 groups: none) without a read-back (Unity: <c>CommandBuffer.DispatchCompute</c> with an
        /// indirect buffer). The buffer must come from <see cref="CreateArgumentsBuffer"/>.</summary>
        void DispatchIndirect(IComputeProgram program, int kernel, IComputeBuffer arguments, int byteOffset);

        /// <summary>Opens a named GPU timing range (Unity: <c>CommandBuffer.BeginSample</c>).</summary>
        void BeginSample(string name);

        void EndSample(string name);

        /// <summary>Runs everything recorded since the last submit, in order.</summary>
        void Submit();

        /// <summary>GPU time of the ranges with this name in the last completed submit (or frame) that recorded it,
        /// summed, in milliseconds; false where the device cannot time it (yet).</summary>
        bool TryGetSampleMilliseconds(string name, out double milliseconds);

        /// <summary>Starts an asynchronous read-back of a buffer (Unity: <c>AsyncGPUReadback</c>).</summary>
        IReadbackRequest RequestReadback(IComputeBuffer buffer);
    }
}
