using System;
using System.Numerics;
using System.Runtime.InteropServices;
using NUnit.Framework;
using SphFluid.Compute;

namespace SphFluid.Tests.Backend
{
    /// <summary>Binding by name, the stride check, unbound buffers, lifetime and read-back.</summary>
    public sealed class BackendBufferTests
    {
        /// <summary>Matches the HLSL Item: float3 + one scalar = one 16-byte group.</summary>
        [StructLayout(LayoutKind.Sequential)]
        struct Item
        {
            public Vector3 Position;
            public uint Tag;
        }

        /// <summary>The same data without the scalar: 12 bytes, which the 16-byte HLSL struct must refuse.</summary>
        [StructLayout(LayoutKind.Sequential)]
        struct PositionOnly
        {
            public Vector3 Position;
        }

        [Test]
        public void StructBufferRoundTripsThroughAKernel()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendBuffers");
            int kernel = program.FindKernel("CopyItems");
            const int count = 100;
            var items = new Item[count];
            for (int i = 0; i < count; i++) items[i] = new Item { Position = new Vector3(i, -i, 0.5f * i), Tag = (uint)(3 * i) };
            using (var input = device.CreateBuffer("Items", count, Marshal.SizeOf<Item>()))
            using (var output = device.CreateBuffer("Copied", count, 16))
            {
                input.SetData(items);
                device.SetBuffer(program, kernel, device.PropertyId("_Items"), input);
                device.SetBuffer(program, kernel, device.PropertyId("_Copied"), output);
                device.SetInt(program, device.PropertyId("_ItemCount"), count);
                device.DispatchThreads(program, kernel, count);
                var copied = new Vector4[count];
                output.GetData(copied);
                for (int i = 0; i < count; i++)
                    Assert.That(copied[i], Is.EqualTo(new Vector4(i, -i, 0.5f * i, 3 * i)), "item " + i);
            }
        }

        [Test]
        public void StrideMismatchNamesBufferKernelAndBothSizes()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendBuffers");
            int kernel = program.FindKernel("CopyItems");
            Assert.That(Marshal.SizeOf<PositionOnly>(), Is.EqualTo(12));
            using (var wrong = device.CreateBuffer("PositionsOnly", 10, Marshal.SizeOf<PositionOnly>()))
            {
                var error = Assert.Throws<ComputeException>(() => device.SetBuffer(program, kernel, device.PropertyId("_Items"), wrong));
                Assert.That(error.Message, Does.Contain("PositionsOnly").And.Contain("CopyItems").And.Contain("12").And.Contain("16"));
            }
        }

        [Test]
        public void ThreadGroupSizeComesFromTheKernel()
        {
            var program = GpuTestDevice.Shared.LoadProgram("BackendBuffers");
            program.GetKernelThreadGroupSizes(program.FindKernel("CopyItems"), out uint x, out uint y, out uint z);
            Assert.That(new[] { x, y, z }, Is.EqualTo(new[] { 64u, 1u, 1u }));
        }

        [Test]
        public void BufferDeclaredOnlyByAnotherKernelMayBeSet()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendBuffers");
            using (var items = device.CreateBuffer("Items", 4, 16))
            {
                Assert.That(() => device.SetBuffer(program, program.FindKernel("CountUp"), device.PropertyId("_Items"), items), Throws.Nothing);
            }
        }

        [Test]
        public void UnknownBufferNameIsNamed()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendBuffers");
            using (var buffer = device.CreateBuffer("Stray", 4, 4))
            {
                Assert.That(() => device.SetBuffer(program, program.FindKernel("CountUp"), device.PropertyId("_NoSuchBuffer"), buffer),
                    Throws.TypeOf<ComputeException>().With.Message.Contains("_NoSuchBuffer"));
            }
        }

        [Test]
        public void DispatchWithAnUnboundBufferIsRefusedBeforeTheDriver()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendBuffers");
            int kernel = program.FindKernel("CopyItems");
            using (var output = device.CreateBuffer("Copied", 4, 16))
            {
                device.SetBuffer(program, kernel, device.PropertyId("_Copied"), output);
                long before = device.DispatchCount;
                var error = Assert.Throws<ComputeException>(() => device.Dispatch(program, kernel, 1, 1, 1));
                Assert.That(error.Message, Does.Contain("_Items").And.Contain("CopyItems"));
                Assert.That(device.DispatchCount, Is.EqualTo(before), "nothing was recorded");
            }
        }

        [Test]
        public void ThousandsOfDependentDispatchesInOneSubmitAllCount()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendBuffers");
            int kernel = program.FindKernel("AddOne");
            const int dispatches = 3000, count = 64;
            using (var counter = device.CreateBuffer("Counter", count, sizeof(uint)))
            {
                device.SetBuffer(program, kernel, device.PropertyId("_Counter"), counter);
                device.SetInt(program, device.PropertyId("_ItemCount"), count);
                for (int i = 0; i < dispatches; i++) device.DispatchThreads(program, kernel, count);
                device.Submit();
                var result = new uint[count];
                counter.GetData(result);
                Assert.That(result, Is.All.EqualTo((uint)dispatches));
            }
        }

        [Test]
        public void PartialSetDataWritesOnlyItsRange()
        {
            var device = GpuTestDevice.Shared;
            using (var buffer = device.CreateBuffer("Partial", 8, sizeof(uint)))
            {
                buffer.SetData(new uint[] { 1, 2, 3, 4, 5, 6, 7, 8 });
                buffer.SetData(new uint[] { 90, 91, 92, 93 }, 1, 5, 2);
                var result = new uint[8];
                buffer.GetData(result);
                Assert.That(result, Is.EqualTo(new uint[] { 1, 2, 3, 4, 5, 91, 92, 8 }));
            }
        }

        [Test]
        public void NewBuffersStartZeroed()
        {
            var device = GpuTestDevice.Shared;
            using (var buffer = device.CreateBuffer("Fresh", 16, 16))
            {
                var result = new uint[64];
                buffer.GetData(result);
                Assert.That(result, Is.All.EqualTo(0u));
            }
        }

        [Test]
        public void ReadbackRequestDeliversTheBuffer()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendBuffers");
            int kernel = program.FindKernel("AddOne");
            using (var counter = device.CreateBuffer("Counter", 4, sizeof(uint)))
            {
                counter.SetData(new uint[] { 10, 20, 30, 40 });
                device.SetBuffer(program, kernel, device.PropertyId("_Counter"), counter);
                device.SetInt(program, device.PropertyId("_ItemCount"), 4);
                device.Dispatch(program, kernel, 1, 1, 1);
                var request = device.RequestReadback(counter);
                Assert.That(request.IsDone, Is.True);
                Assert.That(request.HasError, Is.False);
                var result = new uint[4];
                request.GetData(result);
                Assert.That(result, Is.EqualTo(new uint[] { 11, 21, 31, 41 }));
            }
        }

        [Test]
        public void DisposedBufferIsNamedAndDisposingTwiceIsHarmless()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendBuffers");
            var buffer = device.CreateBuffer("ShortLived", 4, sizeof(uint));
            buffer.Dispose();
            Assert.That(() => buffer.Dispose(), Throws.Nothing);
            Assert.That(() => buffer.SetData(new uint[4]), Throws.TypeOf<ObjectDisposedException>().With.Message.Contains("ShortLived"));
            Assert.That(() => buffer.GetData(new uint[4]), Throws.TypeOf<ObjectDisposedException>().With.Message.Contains("ShortLived"));
            Assert.That(() => device.SetBuffer(program, program.FindKernel("CountUp"), device.PropertyId("_Counter"), buffer),
                Throws.TypeOf<ObjectDisposedException>().With.Message.Contains("ShortLived"));
        }

        [Test]
        public void BufferDisposedWhileItsDispatchIsRecordedLivesUntilTheGpuIsDone()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendBuffers");
            int kernel = program.FindKernel("CountUp");
            var counter = device.CreateBuffer("Counter", 1, sizeof(uint));
            device.SetBuffer(program, kernel, device.PropertyId("_Counter"), counter);
            device.Dispatch(program, kernel, 1, 1, 1);
            counter.Dispose();
            Assert.That(() => device.Submit(), Throws.Nothing);
            Assert.That(() => device.Dispatch(program, kernel, 1, 1, 1),
                Throws.TypeOf<ObjectDisposedException>().With.Message.Contains("Counter"));
        }
    }
}
