using System.Numerics;
using SphFluid.Compute;

namespace SphFluid.Tests
{
    /// <summary>
    /// A device that forwards every call to a real one: tests derive from it and override the calls they watch
    /// or bend (counting buffers, stretching the time step). Disposing it leaves the real device open.
    /// </summary>
    abstract class ForwardingDevice : IComputeDevice
    {
        protected ForwardingDevice(IComputeDevice inner) { Inner = inner; }

        protected IComputeDevice Inner { get; }

        /// <summary>The buffer the real device knows for one this device handed out (identity by default).</summary>
        protected virtual IComputeBuffer Unwrap(IComputeBuffer buffer) => buffer;

        public string DeviceName => Inner.DeviceName;
        public bool RunsOnCpu => Inner.RunsOnCpu;
        public virtual long MaxBufferBytes => Inner.MaxBufferBytes;
        public virtual IComputeProgram LoadProgram(string name) => Inner.LoadProgram(name);
        public virtual IComputeBuffer CreateBuffer(string name, int count, int stride) => Inner.CreateBuffer(name, count, stride);
        public virtual IComputeBuffer CreateConstantBuffer(string name, int bytes) => Inner.CreateConstantBuffer(name, bytes);
        public void SetConstantBuffer(IComputeProgram program, int propertyId, IComputeBuffer buffer) => Inner.SetConstantBuffer(program, propertyId, Unwrap(buffer));
        public virtual void UpdateBuffer<T>(IComputeBuffer buffer, T[] data) where T : struct => Inner.UpdateBuffer(Unwrap(buffer), data);
        public int PropertyId(string name) => Inner.PropertyId(name);
        public void SetBuffer(IComputeProgram program, int kernel, int propertyId, IComputeBuffer buffer) => Inner.SetBuffer(program, kernel, propertyId, Unwrap(buffer));
        public void SetInt(IComputeProgram program, int propertyId, int value) => Inner.SetInt(program, propertyId, value);
        public void SetFloat(IComputeProgram program, int propertyId, float value) => Inner.SetFloat(program, propertyId, value);
        public void SetInts(IComputeProgram program, int propertyId, params int[] values) => Inner.SetInts(program, propertyId, values);
        public void SetVector(IComputeProgram program, int propertyId, Vector4 value) => Inner.SetVector(program, propertyId, value);
        public void SetMatrix(IComputeProgram program, int propertyId, Matrix4x4 value) => Inner.SetMatrix(program, propertyId, value);
        public virtual void SetKeyword(IComputeProgram program, string keyword, bool enabled) => Inner.SetKeyword(program, keyword, enabled);
        public virtual void Dispatch(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ) => Inner.Dispatch(program, kernel, groupsX, groupsY, groupsZ);
        public virtual IComputeBuffer CreateArgumentsBuffer(string name, int count) => Inner.CreateArgumentsBuffer(name, count);
        public virtual void DispatchIndirect(IComputeProgram program, int kernel, IComputeBuffer arguments, int byteOffset) =>
            Inner.DispatchIndirect(program, kernel, Unwrap(arguments), byteOffset);
        public void BeginSample(string name) => Inner.BeginSample(name);
        public void EndSample(string name) => Inner.EndSample(name);
        public void Submit() => Inner.Submit();
        public bool TryGetSampleMilliseconds(string name, out double milliseconds) => Inner.TryGetSampleMilliseconds(name, out milliseconds);
        public IReadbackRequest RequestReadback(IComputeBuffer buffer) => Inner.RequestReadback(Unwrap(buffer));
        public void Dispose() { }
    }
}
