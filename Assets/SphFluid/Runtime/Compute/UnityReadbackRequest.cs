using System;
using System.Runtime.InteropServices;
using SphFluid.Compute;
using UnityEngine;
using UnityEngine.Rendering;

namespace SphFluid.Runtime
{
    /// <summary>
    /// An <see cref="AsyncGPUReadback"/> of a whole buffer. Unity keeps a finished request's data for one frame
    /// only, so the completion callback copies it at once: a caller may poll any number of frames later.
    /// </summary>
    public sealed class UnityReadbackRequest : IReadbackRequest
    {
        byte[] _bytes;
        bool _done, _failed;

        public UnityReadbackRequest(ComputeBuffer buffer)
        {
            AsyncGPUReadback.Request(buffer, OnComplete);
        }

        void OnComplete(AsyncGPUReadbackRequest request)
        {
            if (request.hasError) _failed = true;
            else _bytes = request.GetData<byte>().ToArray();
            _done = true;
        }

        public bool IsDone => _done;

        public bool HasError => _failed;

        public void GetData<T>(T[] destination) where T : struct
        {
            if (destination == null) throw new ArgumentNullException(nameof(destination));
            if (!_done) throw new ComputeException("Read-back: GetData before the request is done");
            if (_failed) throw new ComputeException("Read-back: the request failed");
            ReadOnlySpan<T> values = MemoryMarshal.Cast<byte, T>(_bytes);
            int n = Math.Min(values.Length, destination.Length);
            for (int i = 0; i < n; i++) destination[i] = values[i];
        }
    }
}
