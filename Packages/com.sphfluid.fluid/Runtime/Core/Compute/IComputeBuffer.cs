using System;

namespace SphFluid.Compute
{
    /// <summary>A structured GPU buffer (Unity's <c>ComputeBuffer</c> of type Structured).</summary>
    public interface IComputeBuffer : IDisposable
    {
        string Name { get; }
        int Count { get; }

        /// <summary>Bytes per element; must equal the HLSL struct's size (build structs from 16-byte groups).</summary>
        int Stride { get; }

        /// <summary>Uploads the whole array; its element size must equal <see cref="Stride"/>.</summary>
        void SetData<T>(T[] data) where T : struct;

        /// <summary>Uploads <paramref name="count"/> elements from <paramref name="data"/>[<paramref name="sourceIndex"/>]
        /// to element <paramref name="bufferIndex"/>.</summary>
        void SetData<T>(T[] data, int sourceIndex, int bufferIndex, int count) where T : struct;

        /// <summary>Blocking read-back of the first <c>data.Length</c> elements (submits recorded work first).
        /// For tests and tools; per-frame code uses <see cref="IComputeDevice.RequestReadback"/>.</summary>
        void GetData<T>(T[] data) where T : struct;
    }
}
