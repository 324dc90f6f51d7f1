using System.Numerics;
using SphFluid.Compute;

namespace SphFluid.Tests.Health
{
    /// <summary>
    /// A device that runs every sub-step <see cref="Factor"/> times longer than the solver asked for: the kind of
    /// bug a broken time-step controller would be. No scene that validation lets through is unstable on its own,
    /// so this is how a test proves the health check catches a blow-up through the runner.
    /// </summary>
    sealed class OversteppingDevice : IComputeDevice
    {
        readonly IComputeDevice _inner;
        readonly int _timeStepId;

        public OversteppingDevice(IComputeDevice inner, float factor)
        {
            _inner = inner;
            Factor = factor;
            _timeStepId = inner.PropertyId("_TimeStep");
        }

        public float Factor { get; }

        public string DeviceName => _inner.DeviceName;
        public IComputeProgram LoadProgram(string name) => _inner.LoadProgram(name);
        public IComputeBuffer CreateBuffer(string name, int count, int stride) => _inner.CreateBuffer(name, count, stride);
        public int PropertyId(string name) => _inner.PropertyId(name);
        public void SetBuffer(IComputeProgram program, int kernel, int propertyId, IComputeBuffer buffer) => _inner.SetBuffer(program, kernel, propertyId, buffer);
        public void SetInt(IComputeProgram program, int propertyId, int value) => _inner.SetInt(program, propertyId, value);
        public void SetFloat(IComputeProgram program, int propertyId, float value) =>
            _inner.SetFloat(program, propertyId, propertyId == _timeStepId ? value * Factor : value);
        public void SetInts(IComputeProgram program, int propertyId, params int[] values) => _inner.SetInts(program, propertyId, values);
        public void SetVector(IComputeProgram program, int propertyId, Vector4 value) => _inner.SetVector(program, propertyId, value);
        public void SetMatrix(IComputeProgram program, int propertyId, Matrix4x4 value) => _inner.SetMatrix(program, propertyId, value);
        public void SetKeyword(IComputeProgram program, string keyword, bool enabled) => _inner.SetKeyword(program, keyword, enabled);
        public void Dispatch(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ) => _inner.Dispatch(program, kernel, groupsX, groupsY, groupsZ);
        public void BeginSample(string name) => _inner.BeginSample(name);
        public void EndSample(string name) => _inner.EndSample(name);
        public void Submit() => _inner.Submit();
        public bool TryGetSampleMilliseconds(string name, out double milliseconds) => _inner.TryGetSampleMilliseconds(name, out milliseconds);
        public IReadbackRequest RequestReadback(IComputeBuffer buffer) => _inner.RequestReadback(buffer);

        /// <summary>The shared test device stays open.</summary>
        public void Dispose() { }
    }
}
