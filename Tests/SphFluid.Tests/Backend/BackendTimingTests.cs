using System.Linq;
using NUnit.Framework;
using SphFluid.Compute;

namespace SphFluid.Tests.Backend
{
    /// <summary>GPU timestamp queries time named ranges and every dispatch.</summary>
    public sealed class BackendTimingTests
    {
        const int Items = 100000;

        /// <summary>BackendBuffers' AddOne bound to a new buffer of <see cref="Items"/> counters, which the caller disposes.</summary>
        static IComputeBuffer BindAddOne(IComputeDevice device, out IComputeProgram program, out int kernel)
        {
            program = device.LoadProgram("BackendBuffers");
            kernel = program.FindKernel("AddOne");
            var counter = device.CreateBuffer("Counter", Items, sizeof(uint));
            device.SetBuffer(program, kernel, device.PropertyId("_Counter"), counter);
            device.SetInt(program, device.PropertyId("_ItemCount"), Items);
            return counter;
        }

        [Test]
        public void SampleRangeAndEachDispatchHaveAPositiveGpuTime()
        {
            var device = GpuTestDevice.Shared;
            using var counter = BindAddOne(device, out var program, out int kernel);
            device.BeginSample("BackendTiming");
            for (int i = 0; i < 3; i++) device.DispatchThreads(program, kernel, Items);
            device.EndSample("BackendTiming");
            device.Submit();

            Assert.That(device.TryGetSampleMilliseconds("BackendTiming", out double ms), Is.True);
            Assert.That(ms, Is.GreaterThan(0.0));
            var timings = device.LastDispatchTimings;
            Assert.That(timings.Select(t => t.Kernel), Is.EqualTo(new[] { "AddOne", "AddOne", "AddOne" }));
            Assert.That(timings.Select(t => t.Milliseconds), Is.All.GreaterThan(0.0));
            Assert.That(timings.Sum(t => t.Milliseconds), Is.LessThanOrEqualTo(ms * 1.01 + 0.01));
        }

        /// <summary>A range name recorded twice in one submit (FindNeighbours before delta-SPH's rate and after the sort)
        /// reports both ranges: the bench sums the passes' times into a sub-step's GPU time.</summary>
        [Test]
        public void ANameTimedTwiceInOneSubmitReportsTheSum()
        {
            var device = GpuTestDevice.Shared;
            using var counter = BindAddOne(device, out var program, out int kernel);
            device.BeginSample("BackendTwice");
            for (int i = 0; i < 3; i++) device.DispatchThreads(program, kernel, Items);
            device.EndSample("BackendTwice");
            device.BeginSample("BackendTwice");
            device.DispatchThreads(program, kernel, 1);
            device.EndSample("BackendTwice");
            device.Submit();

            Assert.That(device.TryGetSampleMilliseconds("BackendTwice", out double ms), Is.True);
            var timings = device.LastDispatchTimings;
            Assert.That(timings.Count, Is.EqualTo(4));
            Assert.That(ms, Is.GreaterThanOrEqualTo(timings.Sum(t => t.Milliseconds) * 0.99 - 0.01), "the first range's three dispatches count");
        }

        [Test]
        public void AccumulatedTimingsCoverEverySubmit()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendBuffers");
            int kernel = program.FindKernel("CountUp");
            using (var counter = device.CreateBuffer("Counter", 1, sizeof(uint)))
            {
                device.SetBuffer(program, kernel, device.PropertyId("_Counter"), counter);
                device.TakeDispatchTimings();
                device.AccumulateDispatchTimings = true;
                try
                {
                    for (int i = 0; i < 2; i++) device.Dispatch(program, kernel, 1, 1, 1);
                    device.Submit();
                    for (int i = 0; i < 3; i++) device.Dispatch(program, kernel, 1, 1, 1);
                    device.Submit();
                    Assert.That(device.TakeDispatchTimings().Select(t => t.Kernel), Is.EqualTo(Enumerable.Repeat("CountUp", 5)));
                    Assert.That(device.TakeDispatchTimings(), Is.Empty);
                    Assert.That(device.LastDispatchTimings.Count, Is.EqualTo(3), "the last submit alone");
                }
                finally
                {
                    device.AccumulateDispatchTimings = false;
                }
            }
        }

        [Test]
        public void UnknownSampleHasNoTime()
        {
            Assert.That(GpuTestDevice.Shared.TryGetSampleMilliseconds("NeverSampled", out _), Is.False);
        }

        [Test]
        public void EndSampleWithoutBeginIsNamed()
        {
            Assert.That(() => GpuTestDevice.Shared.EndSample("NeverBegun"),
                Throws.TypeOf<ComputeException>().With.Message.Contains("NeverBegun"));
        }
    }
}
