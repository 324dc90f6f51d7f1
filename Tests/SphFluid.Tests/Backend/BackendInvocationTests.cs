using System.Linq;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>The device counts each dispatch's compute invocations: zero for an indirect dispatch whose arguments hold no
    /// groups, which is how a test tells a solve round that ran from one kept in reserve without reading its timing.</summary>
    public sealed class BackendInvocationTests
    {
        const int Items = 1000;
        const int GroupSize = 64; // AddOne's numthreads

        /// <summary>The shared device; the test is ignored where it cannot count.</summary>
        static VulkanComputeDevice CountingDevice()
        {
            var device = GpuTestDevice.Shared;
            if (!device.CanCountInvocations) Assert.Ignore($"{device.DeviceName} has no pipelineStatisticsQuery");
            return device;
        }

        [Test]
        public void EachDispatchCountsItsGroupsThreads_AnIndirectOneOfNoGroupsNone()
        {
            var device = CountingDevice();
            var program = device.LoadProgram("BackendBuffers");
            int kernel = program.FindKernel("AddOne");
            using var counter = device.CreateBuffer("Counter", Items, sizeof(uint));
            using var arguments = device.CreateBuffer("Arguments", 6, sizeof(uint));
            arguments.SetData(new uint[] { 3, 1, 1, 0, 1, 1 });
            device.SetBuffer(program, kernel, device.PropertyId("_Counter"), counter);
            device.SetInt(program, device.PropertyId("_ItemCount"), Items);
            device.CountInvocations = true;
            try
            {
                device.DispatchThreads(program, kernel, Items);
                device.DispatchIndirect(program, kernel, arguments, 0);
                device.DispatchIndirect(program, kernel, arguments, 12);
                device.Submit();
            }
            finally
            {
                device.CountInvocations = false;
            }
            var counts = device.LastDispatchInvocations;
            Assert.That(counts.Select(c => c.Kernel), Is.EqualTo(Enumerable.Repeat("AddOne", 3)));
            Assert.That(counts.Select(c => c.Invocations), Is.EqualTo(new ulong[] { 16 * GroupSize, 3 * GroupSize, 0 }));
        }

        [Test]
        public void ASubmitThatCountedNoneLeavesTheLastCounts()
        {
            var device = CountingDevice();
            var program = device.LoadProgram("BackendBuffers");
            int kernel = program.FindKernel("CountUp");
            using var counter = device.CreateBuffer("Counter", 1, sizeof(uint));
            device.SetBuffer(program, kernel, device.PropertyId("_Counter"), counter);
            device.CountInvocations = true;
            try
            {
                device.Dispatch(program, kernel, 2, 1, 1);
                device.Submit();
            }
            finally
            {
                device.CountInvocations = false;
            }
            device.Dispatch(program, kernel, 5, 1, 1);
            device.Submit();
            Assert.That(device.LastDispatchInvocations, Is.EqualTo(new[] { ("CountUp", 2UL) }));
        }
    }
}
