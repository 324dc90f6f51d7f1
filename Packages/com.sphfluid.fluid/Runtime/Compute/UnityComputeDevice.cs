using System;
using System.Collections.Generic;
using SphFluid.Compute;
using UnityEngine;
using UnityEngine.Rendering;
using NMatrix4x4 = System.Numerics.Matrix4x4;
using NVector4 = System.Numerics.Vector4;

namespace SphFluid.Runtime
{
    /// <summary>
    /// The compute interface on Unity: parameters and dispatches are recorded into one
    /// <see cref="CommandBuffer"/> (which, like the interface, captures values when they are recorded)
    /// and run by <see cref="Graphics.ExecuteCommandBuffer"/> on <see cref="Submit"/>.
    /// Every buffer it creates is tracked, so <see cref="Dispose"/> releases whatever its user forgot.
    /// </summary>
    public sealed class UnityComputeDevice : IComputeDevice
    {
        /// <summary>ComputeBuffers alive across every device: 0 when nothing leaks (tests).
        /// A counter, not a resource: domain reloads reset it along with everything else.</summary>
        public static int LiveBufferTotal { get; private set; }

        readonly Dictionary<string, ComputeShader> _shaders = new Dictionary<string, ComputeShader>();
        readonly Dictionary<string, UnityComputeProgram> _programs = new Dictionary<string, UnityComputeProgram>();
        readonly HashSet<UnityComputeBuffer> _buffers = new HashSet<UnityComputeBuffer>();
        readonly Dictionary<string, GpuPassTimer> _timers = new Dictionary<string, GpuPassTimer>();
        CommandBuffer _commands;
        bool _pending, _disposing;

        /// <param name="shaders">The compute shader assets <see cref="LoadProgram"/> may hand out, by asset name.</param>
        public UnityComputeDevice(IEnumerable<ComputeShader> shaders)
        {
            if (shaders == null) throw new ArgumentNullException(nameof(shaders));
            foreach (ComputeShader shader in shaders)
                if (shader != null) _shaders[shader.name] = shader;
            _commands = new CommandBuffer { name = "SphFluid" };
        }

        public string DeviceName => SystemInfo.graphicsDeviceName;

        /// <summary>False: Unity's compute shaders run on the graphics device.</summary>
        public bool RunsOnCpu => false;

        public long MaxBufferBytes => SystemInfo.maxGraphicsBufferSize;

        /// <summary>Buffers of this device not yet released.</summary>
        public int LiveBufferCount => _buffers.Count;

        public bool IsDisposed => _commands == null;

        public IComputeProgram LoadProgram(string name)
        {
            ThrowIfDisposed();
            if (_programs.TryGetValue(name, out UnityComputeProgram program)) return program;
            if (!_shaders.TryGetValue(name, out ComputeShader shader))
            {
                string known = _shaders.Count == 0 ? "none" : string.Join(", ", _shaders.Keys);
                throw new ComputeException($"Compute shader '{name}' was not assigned (assigned: {known}); assign Packages/com.sphfluid.fluid/Shaders/{name}.compute");
            }
            program = new UnityComputeProgram(shader);
            _programs.Add(name, program);
            return program;
        }

        public IComputeBuffer CreateBuffer(string name, int count, int stride)
        {
            ThrowIfDisposed();
            if (count <= 0)
                throw new ArgumentOutOfRangeException(nameof(count), count, $"Compute buffer '{name}': count must be > 0");
            if (stride <= 0 || stride % 4 != 0 || stride > 2048)
                throw new ArgumentOutOfRangeException(nameof(stride), stride, $"Compute buffer '{name}': stride must be a multiple of 4 in [4, 2048] bytes");
            var buffer = new UnityComputeBuffer(this, name, count, stride, ComputeBufferType.Structured);
            _buffers.Add(buffer);
            LiveBufferTotal++;
            return buffer;
        }

        public IComputeBuffer CreateArgumentsBuffer(string name, int count)
        {
            ThrowIfDisposed();
            if (count < 3)
                throw new ArgumentOutOfRangeException(nameof(count), count, $"Arguments buffer '{name}': count must be >= 3 (x, y, z groups)");
            var buffer = new UnityComputeBuffer(this, name, count, 4, ComputeBufferType.IndirectArguments);
            _buffers.Add(buffer);
            LiveBufferTotal++;
            return buffer;
        }

        public IComputeBuffer CreateConstantBuffer(string name, int bytes)
        {
            ThrowIfDisposed();
            if (bytes <= 0 || bytes % 16 != 0 || bytes > 65536)
                throw new ArgumentOutOfRangeException(nameof(bytes), bytes, $"Constant buffer '{name}': size must be a multiple of 16 in [16, 65536] bytes");
            var buffer = new UnityComputeBuffer(this, name, 1, bytes, ComputeBufferType.Constant);
            _buffers.Add(buffer);
            LiveBufferTotal++;
            return buffer;
        }

        public void SetConstantBuffer(IComputeProgram program, int propertyId, IComputeBuffer buffer)
        {
            Record();
            UnityComputeBuffer unityBuffer = Live(buffer, program);
            _commands.SetComputeConstantBufferParam(ShaderOf(program), propertyId, unityBuffer.Buffer, 0, unityBuffer.Stride);
        }

        public void UpdateBuffer<T>(IComputeBuffer buffer, T[] data) where T : struct
        {
            Record();
            if (data == null) throw new ArgumentNullException(nameof(data), $"UpdateBuffer of '{buffer?.Name}'");
            _commands.SetBufferData(Live(buffer, null).Buffer, data);
        }

        UnityComputeBuffer Live(IComputeBuffer buffer, IComputeProgram program)
        {
            if (buffer is UnityComputeBuffer unityBuffer && !unityBuffer.IsReleased) return unityBuffer;
            throw new ComputeException($"Compute shader '{program?.Name}': buffer '{buffer?.Name}' is not a live buffer of this device");
        }

        /// <summary>Runs pending work before a buffer it may bind is released; while the device itself is
        /// being disposed, pending work is dropped instead.</summary>
        internal void FlushBeforeRelease()
        {
            if (_commands != null && !_disposing) Submit();
        }

        internal void Forget(UnityComputeBuffer buffer)
        {
            if (_buffers.Remove(buffer)) LiveBufferTotal--;
        }

        public int PropertyId(string name) => Shader.PropertyToID(name);

        public void SetBuffer(IComputeProgram program, int kernel, int propertyId, IComputeBuffer buffer)
        {
            Record();
            _commands.SetComputeBufferParam(ShaderOf(program), kernel, propertyId, Live(buffer, program).Buffer);
        }

        public void SetInt(IComputeProgram program, int propertyId, int value)
        {
            Record();
            _commands.SetComputeIntParam(ShaderOf(program), propertyId, value);
        }

        public void SetFloat(IComputeProgram program, int propertyId, float value)
        {
            Record();
            _commands.SetComputeFloatParam(ShaderOf(program), propertyId, value);
        }

        public void SetInts(IComputeProgram program, int propertyId, params int[] values)
        {
            Record();
            _commands.SetComputeIntParams(ShaderOf(program), propertyId, values);
        }

        public void SetVector(IComputeProgram program, int propertyId, NVector4 value)
        {
            Record();
            _commands.SetComputeVectorParam(ShaderOf(program), propertyId, value.ToUnity());
        }

        public void SetMatrix(IComputeProgram program, int propertyId, NMatrix4x4 value)
        {
            Record();
            _commands.SetComputeMatrixParam(ShaderOf(program), propertyId, value.ToUnity());
        }

        public void SetKeyword(IComputeProgram program, string keyword, bool enabled)
        {
            Record();
            UnityComputeProgram unityProgram = Program(program);
            LocalKeyword local = unityProgram.Keyword(keyword);
            // Recorded, so that dispatches recorded before it keep their variant when the buffer runs; and set on the
            // asset now, which is what a dispatch sees should Unity resolve the variant while recording.
            if (enabled) _commands.EnableKeyword(unityProgram.Shader, local);
            else _commands.DisableKeyword(unityProgram.Shader, local);
            unityProgram.Shader.SetKeyword(local, enabled);
        }

        public void Dispatch(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ)
        {
            Record();
            if (groupsX < 1 || groupsY < 1 || groupsZ < 1 || groupsX > 65535 || groupsY > 65535 || groupsZ > 65535)
                throw new ComputeException($"Compute shader '{program?.Name}': dispatch of ({groupsX}, {groupsY}, {groupsZ}) groups; each must be in [1, 65535]");
            _commands.DispatchCompute(ShaderOf(program), kernel, groupsX, groupsY, groupsZ);
        }

        public void DispatchIndirect(IComputeProgram program, int kernel, IComputeBuffer arguments, int byteOffset)
        {
            Record();
            if (!(arguments is UnityComputeBuffer unityBuffer) || unityBuffer.IsReleased)
                throw new ComputeException($"Compute shader '{program?.Name}': indirect arguments '{arguments?.Name}' are not a live buffer of this device");
            if (byteOffset < 0 || byteOffset % 4 != 0 || byteOffset + 12 > unityBuffer.Count * unityBuffer.Stride)
                throw new ComputeException($"Compute shader '{program?.Name}': indirect arguments offset must be a multiple of 4 in [0, {unityBuffer.Count * unityBuffer.Stride - 12}] bytes (was {byteOffset})");
            _commands.DispatchCompute(ShaderOf(program), kernel, unityBuffer.Buffer, (uint)byteOffset);
        }

        public void BeginSample(string name)
        {
            Record();
            GpuPassTimer timer = Timer(name);
            if (timer.Sampler != null) _commands.BeginSample(timer.Sampler);
            else _commands.BeginSample(timer.ProfilerName);
        }

        public void EndSample(string name)
        {
            Record();
            GpuPassTimer timer = Timer(name);
            if (timer.Sampler != null) _commands.EndSample(timer.Sampler);
            else _commands.EndSample(timer.ProfilerName);
        }

        public void Submit()
        {
            ThrowIfDisposed();
            if (!_pending) return;
            Graphics.ExecuteCommandBuffer(_commands);
            _commands.Clear();
            _pending = false;
        }

        /// <summary>Unity's GPU recorders report the time a sample name took over a whole recent frame
        /// (all ranges of that name, a few frames late), not a single range.</summary>
        public bool TryGetSampleMilliseconds(string name, out double milliseconds)
        {
            milliseconds = 0;
            return _timers.TryGetValue(name, out GpuPassTimer timer) && timer.TryGetMilliseconds(out milliseconds);
        }

        /// <summary>The timer of a range name this device has recorded; null before its first range.</summary>
        public GpuPassTimer RecordedTimer(string name) => _timers.TryGetValue(name, out GpuPassTimer timer) ? timer : null;

        public IReadbackRequest RequestReadback(IComputeBuffer buffer)
        {
            ThrowIfDisposed();
            if (!(buffer is UnityComputeBuffer unityBuffer) || unityBuffer.IsReleased)
                throw new ComputeException($"Read-back: buffer '{buffer?.Name}' is not a live buffer of this device");
            Submit(); // the read-back must see the work recorded before it
            return unityBuffer.StartReadback();
        }

        /// <summary>The timer of a range name, looked up once per device.</summary>
        GpuPassTimer Timer(string name)
        {
            if (_timers.TryGetValue(name, out GpuPassTimer timer)) return timer;
            timer = GpuPassTimer.Of(name);
            _timers.Add(name, timer);
            return timer;
        }

        static ComputeShader ShaderOf(IComputeProgram program) => Program(program).Shader;

        static UnityComputeProgram Program(IComputeProgram program)
        {
            if (program is UnityComputeProgram unityProgram) return unityProgram;
            throw new ComputeException($"Program '{program?.Name}' was not loaded by a UnityComputeDevice");
        }

        /// <summary>Every recording call comes here: refuses a disposed device and marks work to submit.</summary>
        void Record()
        {
            ThrowIfDisposed();
            _pending = true;
        }

        void ThrowIfDisposed()
        {
            if (_commands == null) throw new ObjectDisposedException(nameof(UnityComputeDevice));
        }

        /// <summary>Releases every buffer still alive and the command buffer.</summary>
        public void Dispose()
        {
            if (_commands == null) return;
            _disposing = true;
            _commands.Clear();
            _pending = false;
            foreach (UnityComputeBuffer buffer in new List<UnityComputeBuffer>(_buffers))
                buffer.Dispose();
            _buffers.Clear();
            _timers.Clear(); // the timers outlive the device: they stay enabled for the next one
            _programs.Clear();
            _commands.Release();
            _commands = null;
        }
    }
}
