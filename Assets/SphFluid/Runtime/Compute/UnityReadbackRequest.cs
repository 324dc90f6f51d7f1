using System;
using SphFluid.Compute;
using Unity.Collections;
using UnityEngine.Rendering;

namespace SphFluid.Runtime
{
    /// <summary>An <see cref="AsyncGPUReadbackRequest"/> in flight.</summary>
    public sealed class UnityReadbackRequest : IReadbackRequest
    {
        AsyncGPUReadbackRequest _request;

        public UnityReadbackRequest(AsyncGPUReadbackRequest request)
        {
            _request = request;
        }

        public bool IsDone => _request.done;

        public bool HasError => _request.hasError;

        public void GetData<T>(T[] destination) where T : struct
        {
            if (destination == null) throw new ArgumentNullException(nameof(destination));
            if (!_request.done) throw new ComputeException("Read-back: GetData before the request is done");
            if (_request.hasError) throw new ComputeException("Read-back: the request failed");
            NativeArray<T> data = _request.GetData<T>();
            int n = Math.Min(data.Length, destination.Length);
            for (int i = 0; i < n; i++) destination[i] = data[i];
        }
    }
}
