using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Profiling;

namespace SphFluid.Runtime
{
    /// <summary>
    /// The GPU timing of one named pass: its profiler sampler and the one <see cref="Recorder"/> that reads it.
    /// </summary>
    /// <remarks>
    /// <see cref="Sampler.GetRecorder"/> wraps a new pair of native recorders on every call, so a recorder fetched
    /// to read is not the one that was enabled, and reads 0. The timer keeps the recorder it enabled and reads
    /// that one. Timers live for the whole scripting domain, one per pass name (Unity keeps one sampler per
    /// name anyway): a reset, which makes a new device, then creates no recorder and loses no frame of timing.
    /// Main thread only, like every Unity call of the device.
    /// </remarks>
    public sealed class GpuPassTimer
    {
        /// <summary>Profiler ranges are named "SphFluid.&lt;pass&gt;" so that no built-in sampler name is taken.</summary>
        public const string NamePrefix = "SphFluid.";

        static readonly Dictionary<string, GpuPassTimer> ByPass = new Dictionary<string, GpuPassTimer>();

        readonly Recorder _recorder;

        GpuPassTimer(string pass)
        {
            Pass = pass;
            ProfilerName = NamePrefix + pass;
            if (!SystemInfo.supportsGpuRecorder) return;
            CustomSampler sampler = CustomSampler.Create(ProfilerName, true);
            if (sampler == null || !sampler.isValid) return;
            Sampler = sampler;
            Recorder recorder = sampler.GetRecorder();
            if (recorder == null || !recorder.isValid) return;
            recorder.enabled = true;
            _recorder = recorder;
        }

        /// <summary>The timer of a pass, created on its first use.</summary>
        public static GpuPassTimer Of(string pass)
        {
            if (ByPass.TryGetValue(pass, out GpuPassTimer timer)) return timer;
            timer = new GpuPassTimer(pass);
            ByPass.Add(pass, timer);
            return timer;
        }

        public string Pass { get; }

        /// <summary>"SphFluid.&lt;pass&gt;", built once: a range costs no string.</summary>
        public string ProfilerName { get; }

        /// <summary>The GPU-timed sampler; null where the platform cannot time the GPU (ranges are then plain
        /// named samples).</summary>
        public CustomSampler Sampler { get; }

        /// <summary>The recorder enabled at creation; tests check that every read goes to this very one.</summary>
        public Recorder Recorder => _recorder;

        /// <summary>GPU time of every range of this pass over a recent frame (Unity reports it a few frames
        /// late), ms; false where it cannot be timed or nothing was recorded yet.</summary>
        public bool TryGetMilliseconds(out double milliseconds)
        {
            milliseconds = 0;
            if (_recorder == null || !_recorder.isValid) return false;
            long nanoseconds = _recorder.gpuElapsedNanoseconds;
            if (nanoseconds <= 0) return false;
            milliseconds = nanoseconds * 1e-6;
            return true;
        }
    }
}
