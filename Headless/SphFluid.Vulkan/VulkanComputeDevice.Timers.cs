using System;
using System.Collections.Generic;
using System.Linq;
using Silk.NET.Vulkan;
using SphFluid.Compute;

namespace SphFluid.Vulkan;

/// <summary>GPU timing: timestamp queries around dispatches and named sample ranges, read when a submit's fence has signalled.</summary>
public sealed unsafe partial class VulkanComputeDevice
{
    void WriteTimestamp(Frame f, uint query)
    {
        var (pool, index) = Slot(f.Timestamps, query);
        _vk.CmdWriteTimestamp(f.Cmd, PipelineStageFlags.ComputeShaderBit, pool, index);
    }

    public void BeginSample(string name)
    {
        ThrowIfDisposed();
        if (name == null) throw new ArgumentNullException(nameof(name));
        if (!_canTime) return;
        var f = BeginRecording();
        uint q = AllocateQuery(f, f.Timestamps, 1);
        WriteTimestamp(f, q);
        _openSamples[name] = q;
        _samplesCutBySubmit.Remove(name);
    }

    public void EndSample(string name)
    {
        ThrowIfDisposed();
        if (name == null) throw new ArgumentNullException(nameof(name));
        if (!_canTime) return;
        if (_samplesCutBySubmit.Remove(name))
            return;
        if (_recording == null || !_openSamples.Remove(name, out uint begin))
            throw new ComputeException($"EndSample('{name}') without a matching BeginSample('{name}') since the last Submit");
        var f = _recording;
        uint end = AllocateQuery(f, f.Timestamps, 1);
        WriteTimestamp(f, end);
        f.Samples.Add((name, begin, end));
        _sampleSerial[name] = f.Serial;
    }

    /// <summary>Every dispatch timed since the last call (with <see cref="AccumulateDispatchTimings"/> on),
    /// in submission order; waits for submitted work first.</summary>
    public IReadOnlyList<(string Kernel, double Milliseconds)> TakeDispatchTimings()
    {
        ThrowIfDisposed();
        WaitForSerial(_submittedSerial);
        var result = _accumulatedTimings.ToArray();
        _accumulatedTimings.Clear();
        return result;
    }

    public bool TryGetSampleMilliseconds(string name, out double milliseconds)
    {
        ThrowIfDisposed();
        milliseconds = 0;
        if (name == null || !_canTime) return false;
        if (_sampleSerial.TryGetValue(name, out ulong serial) && serial <= _submittedSerial && serial > _completedSerial) WaitForSerial(serial);
        return _sampleResults.TryGetValue(name, out milliseconds);
    }
}
