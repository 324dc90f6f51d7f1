using System.Linq;
using System.Numerics;
using System.Runtime.InteropServices;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>
    /// Structured buffers are laid out as Unity (D3D) lays them out, so a C# struct with packed Vector3
    /// members and a buffer of Vector3 are read at their own 44- and 12-byte strides, and the kernels agree
    /// with the same maths done here on the CPU.
    /// </summary>
    public sealed class BackendUnityPackingTests
    {
        [StructLayout(LayoutKind.Sequential)]
        struct Body
        {
            public Vector3 Position;
            public Vector3 Velocity;
            public float Mass;
            public Vector3 Force;
            public uint Id;
        }

        /// <summary>A column-major 3x3 basis (as D3D stores a float3x3 by default), then an origin.</summary>
        [StructLayout(LayoutKind.Sequential)]
        struct Frame
        {
            public Vector3 Column0;
            public Vector3 Column1;
            public Vector3 Column2;
            public Vector3 Origin;
        }

        [Test]
        public void ReflectedStridesAreUnitysPackedSizes()
        {
            var program = (VulkanProgram)GpuTestDevice.Shared.LoadProgram("BackendUnityPacking");
            Assert.That(Marshal.SizeOf<Body>(), Is.EqualTo(44));
            Assert.That(Marshal.SizeOf<Frame>(), Is.EqualTo(48));
            Assert.That(Stride(program, "StepBodies", "_Bodies"), Is.EqualTo(44));
            Assert.That(Stride(program, "ShiftPoints", "_Shifts"), Is.EqualTo(12));
            Assert.That(Stride(program, "ShiftPoints", "_Points"), Is.EqualTo(12));
            Assert.That(Stride(program, "TransformPoints", "_Frames"), Is.EqualTo(48));
        }

        [Test]
        public void PackedFloat3StructStepsAsOnTheCpu()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnityPacking");
            int kernel = program.FindKernel("StepBodies");
            const int count = 100;
            const float dt = 0.01f;
            var bodies = new Body[count];
            for (int i = 0; i < count; i++)
                bodies[i] = new Body
                {
                    Position = new Vector3(i, 2 * i, -i), Velocity = new Vector3(0.5f * i, 1, -2), Mass = 1 + 0.25f * i,
                    Force = new Vector3(-i, 3, 0.5f * i), Id = (uint)(7 * i),
                };
            using (var buffer = device.CreateBuffer("Bodies", count, Marshal.SizeOf<Body>()))
            {
                buffer.SetData(bodies);
                device.SetBuffer(program, kernel, device.PropertyId("_Bodies"), buffer);
                device.SetInt(program, device.PropertyId("_Count"), count);
                device.SetFloat(program, device.PropertyId("_TimeStep"), dt);
                device.DispatchThreads(program, kernel, count);
                var stepped = new Body[count];
                buffer.GetData(stepped);
                for (int i = 0; i < count; i++)
                {
                    var b = bodies[i];
                    var velocity = b.Velocity + b.Force / b.Mass * dt;
                    var position = b.Position + velocity * dt;
                    Assert.That(Vector3.Distance(stepped[i].Velocity, velocity), Is.LessThan(1e-5f), "velocity of body " + i);
                    Assert.That(Vector3.Distance(stepped[i].Position, position), Is.LessThan(1e-4f), "position of body " + i);
                    Assert.That(stepped[i].Mass, Is.EqualTo(b.Mass), "mass of body " + i + " (the member after velocity)");
                    Assert.That(stepped[i].Force, Is.EqualTo(b.Force), "force of body " + i);
                    Assert.That(stepped[i].Id, Is.EqualTo(2 * b.Id + 1), "id of body " + i + " (the last member)");
                }
            }
        }

        [Test]
        public void Float3BuffersUseTwelveByteElements()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnityPacking");
            int kernel = program.FindKernel("ShiftPoints");
            const int count = 77;
            var points = Enumerable.Range(0, count).Select(i => new Vector3(i, -0.5f * i, 100 + i)).ToArray();
            var shifts = Enumerable.Range(0, count).Select(i => new Vector3(1, i, -2 * i)).ToArray();
            using (var pointBuffer = device.CreateBuffer("Points", count, 12))
            using (var shiftBuffer = device.CreateBuffer("Shifts", count, 12))
            {
                pointBuffer.SetData(points);
                shiftBuffer.SetData(shifts);
                device.SetBuffer(program, kernel, device.PropertyId("_Points"), pointBuffer);
                device.SetBuffer(program, kernel, device.PropertyId("_Shifts"), shiftBuffer);
                device.SetInt(program, device.PropertyId("_Count"), count);
                device.DispatchThreads(program, kernel, count);
                var result = new Vector3[count];
                pointBuffer.GetData(result);
                for (int i = 0; i < count; i++) Assert.That(result[i], Is.EqualTo(points[i] + shifts[i]), "point " + i);
            }
        }

        [Test]
        public void Float3x3MembersAreColumnMajorAndPacked()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnityPacking");
            int kernel = program.FindKernel("TransformPoints");
            const int count = 20;
            var frames = new Frame[count];
            var points = new Vector3[count];
            for (int i = 0; i < count; i++)
            {
                frames[i] = new Frame
                {
                    Column0 = new Vector3(1 + i, 2, 3), Column1 = new Vector3(4, 5 + i, 6), Column2 = new Vector3(7, 8, 9 + i),
                    Origin = new Vector3(10 * i, -i, 0.5f),
                };
                points[i] = new Vector3(1, -2, 0.25f * i);
            }
            using (var frameBuffer = device.CreateBuffer("Frames", count, Marshal.SizeOf<Frame>()))
            using (var pointBuffer = device.CreateBuffer("Points", count, 12))
            {
                frameBuffer.SetData(frames);
                pointBuffer.SetData(points);
                device.SetBuffer(program, kernel, device.PropertyId("_Frames"), frameBuffer);
                device.SetBuffer(program, kernel, device.PropertyId("_Points"), pointBuffer);
                device.SetInt(program, device.PropertyId("_Count"), count);
                device.DispatchThreads(program, kernel, count);
                var result = new Vector3[count];
                pointBuffer.GetData(result);
                for (int i = 0; i < count; i++)
                {
                    var f = frames[i];
                    var p = points[i];
                    var expected = f.Column0 * p.X + f.Column1 * p.Y + f.Column2 * p.Z + f.Origin;
                    Assert.That(Vector3.Distance(result[i], expected), Is.LessThan(1e-4f), "point " + i + " was " + result[i] + ", expected " + expected);
                }
            }
        }

        [Test]
        public void AStructBufferWithTheStd430StrideIsRefusedNamingUnitysSize()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnityPacking");
            using (var padded = device.CreateBuffer("PaddedBodies", 4, 48))
            {
                var error = Assert.Throws<ComputeException>(() => device.SetBuffer(program, program.FindKernel("StepBodies"), device.PropertyId("_Bodies"), padded));
                Assert.That(error.Message, Does.Contain("PaddedBodies").And.Contain("48").And.Contain("44").And.Contain("StepBodies"));
            }
        }

        static int Stride(VulkanProgram program, string kernel, string buffer) =>
            program.Reflect(program.FindKernel(kernel)).Resources.Single(r => r.Name == buffer).ArrayStride;
    }
}
