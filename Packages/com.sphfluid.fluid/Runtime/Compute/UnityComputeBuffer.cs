using System;
using System.Runtime.InteropServices;
using SphFluid.Compute;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>A structured <see cref="UnityEngine.ComputeBuffer"/> owned by a <see cref="UnityComputeDevice"/>.</summary>
    public sealed class UnityComputeBuffer : IComputeBuffer
    {
        readonly UnityComputeDevice _device;
        ComputeBuffer _buffer;
        UnityReadbackRequest _readback;

        internal UnityComputeBuffer(UnityComputeDevice device, string name, int count, int stride, ComputeBufferType type)
        {
            _device = device;
            Name = name;
            Count = count;
            Stride = stride;
            _buffer = new ComputeBuffer(count, stride, type);
        }

        public string Name { get; }

        public int Count { get; }

        public int Stride { get; }

        /// <summary>The Unity buffer, for binding to materials; null once released.</summary>
        public ComputeBuffer Buffer => _buffer;

        public bool IsReleased => _buffer == null;

        public void SetData<T>(T[] data) where T : struct
        {
            if (data == null) throw new ArgumentNullException(nameof(data));
            SetData(data, 0, 0, data.Length);
        }

        public void SetData<T>(T[] data, int sourceIndex, int bufferIndex, int count) where T : struct
        {
            ThrowIfReleased();
            if (data == null) throw new ArgumentNullException(nameof(data));
            CheckElementSize<T>();
            if (sourceIndex < 0 || count < 0 || sourceIndex + count > data.Length || bufferIndex < 0 || bufferIndex + count > Count)
                throw new ComputeException($"Compute buffer '{Name}': SetData of {count} elements from [{sourceIndex}] to [{bufferIndex}] does not fit ({data.Length} given, {Count} in the buffer)");
            _device.Submit(); // uploads land after the work recorded before them
            _buffer.SetData(data, sourceIndex, bufferIndex, count);
        }

        public void GetData<T>(T[] data) where T : struct
        {
            ThrowIfReleased();
            if (data == null) throw new ArgumentNullException(nameof(data));
            CheckElementSize<T>();
            if (data.Length > Count)
                throw new ComputeException($"Compute buffer '{Name}': GetData of {data.Length} elements, but the buffer holds {Count}");
            _device.Submit();
            _buffer.GetData(data, 0, 0, data.Length);
        }

        /// <summary>Starts a read-back of the whole buffer. The previous request of this buffer is restarted once
        /// it is spent (done, and read or failed), which is how the simulation uses its per-frame read-backs; a
        /// caller still waiting on it, or one that dropped it unread, gets a new request instead.</summary>
        internal UnityReadbackRequest StartReadback()
        {
            ThrowIfReleased();
            if (_readback == null || !_readback.IsSpent) _readback = new UnityReadbackRequest(_buffer, Count * Stride);
            _readback.Start();
            return _readback;
        }

        void CheckElementSize<T>() where T : struct
        {
            int size = Marshal.SizeOf<T>();
            if (size != Stride)
                throw new ComputeException($"Compute buffer '{Name}': element type {typeof(T).Name} is {size} bytes, the buffer's stride is {Stride}");
        }

        void ThrowIfReleased()
        {
            if (_buffer == null) throw new ObjectDisposedException($"Compute buffer '{Name}'");
        }

        public void Dispose()
        {
            if (_buffer == null) return;
            _device.FlushBeforeRelease(); // recorded commands that bind this buffer run before it goes
            _buffer.Release();
            _buffer = null;
            _readback = null;
            _device.Forget(this);
        }
    }
}
