using System;
using System.Runtime.InteropServices;
using SphFluid.Compute;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Rendering;

namespace SphFluid.Runtime
{
    /// <summary>
    /// An <see cref="AsyncGPUReadback"/> of a whole buffer. Unity keeps a finished request's data for one frame
    /// only, so the completion callback copies it at once: a caller may poll any number of frames later.
    /// </summary>
    /// <remarks>
    /// The simulation reads its motion and diagnostics back every frame, so one request object per buffer is
    /// restarted rather than a new one made: the copy, the callback delegate and the object itself are
    /// allocated once (see <see cref="UnityComputeBuffer.StartReadback"/> for when it may be restarted).
    /// </remarks>
    public sealed class UnityReadbackRequest : IReadbackRequest
    {
        readonly ComputeBuffer _buffer;
        readonly byte[] _bytes;
        readonly Action<AsyncGPUReadbackRequest> _onComplete;
        bool _inFlight, _done, _failed, _read;

        internal UnityReadbackRequest(ComputeBuffer buffer, int byteCount)
        {
            _buffer = buffer;
            _bytes = new byte[byteCount];
            _onComplete = OnComplete;
        }

        /// <summary>Finished, and its caller has read it or seen it fail: nobody waits on it any more.</summary>
        internal bool IsSpent => _done && (_read || _failed);

        /// <summary>How many read-backs this object has carried (tests check it is reused).</summary>
        public int Starts { get; private set; }

        internal void Start()
        {
            if (_inFlight) throw new ComputeException("Read-back: a request still in flight cannot be restarted");
            _inFlight = true;
            _done = _failed = _read = false;
            Starts++;
            AsyncGPUReadback.Request(_buffer, _onComplete);
        }

        void OnComplete(AsyncGPUReadbackRequest request)
        {
            _inFlight = false;
            if (request.hasError) _failed = true;
            else
            {
                NativeArray<byte> data = request.GetData<byte>();
                NativeArray<byte>.Copy(data, _bytes, Math.Min(data.Length, _bytes.Length));
            }
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
            _read = true;
        }
    }
}
