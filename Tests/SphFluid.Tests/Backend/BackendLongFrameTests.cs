using NUnit.Framework;
using SphFluid.Compute;

namespace SphFluid.Tests.Backend
{
    /// <summary>
    /// A frame that records more dispatches than one command buffer takes is submitted in parts
    /// (VulkanComputeDevice.DispatchesPerSubmit): lavapipe crashed the process recording a DFSPH frame of 84 sub-steps,
    /// some 60 000 dispatches, in one. Every dispatch still runs, in order, and a timing range open across a part's
    /// submit ends without an error.
    /// </summary>
    public sealed class BackendLongFrameTests
    {
        const int Items = 64;
        const int Dispatches = 40000; // three parts

        [Test]
        public void FortyThousandDispatchesInOneFrameAllRun()
        {
            var device = GpuTestDevice.Unvalidated;
            var program = device.LoadProgram("BackendBuffers");
            int kernel = program.FindKernel("AddOne");
            using var counter = device.CreateBuffer("Counter", Items, sizeof(uint));
            counter.SetData(new uint[Items]);
            device.SetBuffer(program, kernel, device.PropertyId("_Counter"), counter);
            device.SetInt(program, device.PropertyId("_ItemCount"), Items);
            device.BeginSample("BackendLongFrame");
            for (int i = 0; i < Dispatches; i++) device.DispatchThreads(program, kernel, Items);
            Assert.That(() => device.EndSample("BackendLongFrame"), Throws.Nothing);
            device.Submit();
            var counts = new uint[Items];
            counter.GetData(counts);
            Assert.That(counts, Is.All.EqualTo((uint)Dispatches));
        }
    }
}
