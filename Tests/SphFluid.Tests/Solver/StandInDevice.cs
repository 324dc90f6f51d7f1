using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Compute;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// A device that records nothing and computes nothing: every call returns at once, read-backs are done as soon
    /// as they are asked for and read as zeros. What a frame allocates on it is what the solver itself allocates,
    /// with no backend in the count (Unity's command-buffer device is measured in the PlayMode tests).
    /// </summary>
    sealed class StandInDevice : IComputeDevice
    {
        /// <summary>Every kernel's group width: the sort and the scan check theirs against 256.</summary>
        const uint GroupWidth = 256;

        readonly Dictionary<string, int> _ids = new Dictionary<string, int>();

        public string DeviceName => "stand-in (no GPU work)";
        public bool RunsOnCpu => false;
        public long MaxBufferBytes => 1L << 31;

        /// <summary>Dispatches recorded so far: a frame that did nothing would also allocate nothing.</summary>
        public long Dispatches { get; private set; }

        public IComputeProgram LoadProgram(string name) => new Program(name);
        public IComputeBuffer CreateBuffer(string name, int count, int stride) => new Buffer(name, count, stride);
        public IComputeBuffer CreateConstantBuffer(string name, int bytes) => new Buffer(name, 1, bytes);
        public void SetConstantBuffer(IComputeProgram program, int propertyId, IComputeBuffer buffer) { }
        public void UpdateBuffer<T>(IComputeBuffer buffer, T[] data) where T : struct { }

        public int PropertyId(string name)
        {
            if (!_ids.TryGetValue(name, out int id)) _ids[name] = id = _ids.Count;
            return id;
        }

        public void SetBuffer(IComputeProgram program, int kernel, int propertyId, IComputeBuffer buffer) { }
        public void SetInt(IComputeProgram program, int propertyId, int value) { }
        public void SetFloat(IComputeProgram program, int propertyId, float value) { }
        public void SetInts(IComputeProgram program, int propertyId, params int[] values) { }
        public void SetVector(IComputeProgram program, int propertyId, Vector4 value) { }
        public void SetMatrix(IComputeProgram program, int propertyId, Matrix4x4 value) { }
        public void SetKeyword(IComputeProgram program, string keyword, bool enabled) { }
        public void Dispatch(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ) => Dispatches++;
        public IComputeBuffer CreateArgumentsBuffer(string name, int count) => new Buffer(name, count, 4);
        public void DispatchIndirect(IComputeProgram program, int kernel, IComputeBuffer arguments, int byteOffset) => Dispatches++;
        public void BeginSample(string name) { }
        public void EndSample(string name) { }
        public void Submit() { }

        public bool TryGetSampleMilliseconds(string name, out double milliseconds)
        {
            milliseconds = 0;
            return false;
        }

        public IReadbackRequest RequestReadback(IComputeBuffer buffer) => ((Buffer)buffer).Readback;

        public void Dispose() { }

        sealed class Program : IComputeProgram
        {
            readonly List<string> _kernels = new List<string>();

            public Program(string name) { Name = name; }

            public string Name { get; }

            public int FindKernel(string kernelName)
            {
                int k = _kernels.IndexOf(kernelName);
                if (k >= 0) return k;
                _kernels.Add(kernelName);
                return _kernels.Count - 1;
            }

            public bool HasKernel(string kernelName) => true;

            public void GetKernelThreadGroupSizes(int kernel, out uint x, out uint y, out uint z)
            {
                x = GroupWidth;
                y = z = 1;
            }

            public IReadOnlyList<string> Keywords { get; } = Array.Empty<string>();
        }

        sealed class Buffer : IComputeBuffer
        {
            public Buffer(string name, int count, int stride)
            {
                Name = name;
                Count = count;
                Stride = stride;
            }

            public string Name { get; }
            public int Count { get; }
            public int Stride { get; }

            /// <summary>The one request of this buffer, always done: asking again makes nothing new.</summary>
            public IReadbackRequest Readback { get; } = new DoneReadback();

            public void SetData<T>(T[] data) where T : struct { }
            public void SetData<T>(T[] data, int sourceIndex, int bufferIndex, int count) where T : struct { }
            public void GetData<T>(T[] data) where T : struct => Array.Clear(data, 0, data.Length);
            public void Dispose() { }
        }

        sealed class DoneReadback : IReadbackRequest
        {
            public bool IsDone => true;
            public bool HasError => false;
            public void GetData<T>(T[] destination) where T : struct => Array.Clear(destination, 0, destination.Length);
        }
    }
}
