using System.Numerics;
using System.Runtime.InteropServices;
using NUnit.Framework;
using SphFluid.Compute;

namespace SphFluid.Tests.Backend
{
    /// <summary>Constant buffers as the solver uses them (FluidConstants): bound once by cbuffer name, uploaded by
    /// recorded updates that run in order with the dispatches, matrices row_major in System.Numerics order.</summary>
    public sealed class BackendConstantBufferTests
    {
        [StructLayout(LayoutKind.Sequential)]
        struct RowConstants
        {
            public Matrix4x4 Transform;
            public Vector3 Point;
            public uint Row;
        }

        const int Bytes = 80;

        [Test]
        public void EachDispatchReadsTheUploadRecordedBeforeIt()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendConstants");
            int kernel = program.FindKernel("WriteRow");
            using (var constants = device.CreateConstantBuffer("RowConstants", Bytes))
            using (var rows = device.CreateBuffer("Rows", 2, 16))
            {
                device.SetConstantBuffer(program, device.PropertyId("RowConstants"), constants);
                device.SetBuffer(program, kernel, device.PropertyId("_Rows"), rows);
                // Scale x by 2, then translate by (10, 20, 30): translation in M14, M24, M34, as IComputeDevice.SetMatrix.
                var values = new[] { new RowConstants { Transform = new Matrix4x4(2, 0, 0, 10, 0, 1, 0, 20, 0, 0, 1, 30, 0, 0, 0, 1), Point = new Vector3(1, 2, 3), Row = 0 } };
                device.UpdateBuffer(constants, values);
                device.Dispatch(program, kernel, 1, 1, 1);
                values[0].Point = new Vector3(-1, -2, -3);
                values[0].Row = 1;
                device.UpdateBuffer(constants, values);
                device.Dispatch(program, kernel, 1, 1, 1);
                values[0].Row = 0; // changed after the last upload was recorded: no dispatch reads it
                device.Submit();

                var result = new Vector4[2];
                rows.GetData(result);
                Assert.That(result[0], Is.EqualTo(new Vector4(12, 22, 33, 1)));
                Assert.That(result[1], Is.EqualTo(new Vector4(8, 18, 27, 1)));
            }
        }

        [Test]
        public void AConstantBufferIsNotAStructuredBuffer()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendConstants");
            int kernel = program.FindKernel("WriteRow");
            using (var constants = device.CreateConstantBuffer("RowConstants", Bytes))
            using (var rows = device.CreateBuffer("Rows", 2, 16))
            {
                Assert.That(() => device.SetBuffer(program, kernel, device.PropertyId("_Rows"), constants),
                    Throws.InstanceOf<ComputeException>().With.Message.Contains("SetConstantBuffer"));
                Assert.That(() => device.SetConstantBuffer(program, device.PropertyId("RowConstants"), rows),
                    Throws.InstanceOf<ComputeException>().With.Message.Contains("CreateConstantBuffer"));
            }
        }

        [Test]
        public void ACbufferNeverBoundRefusesTheDispatch()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendConstants");
            int kernel = program.FindKernel("WriteRow");
            using (var rows = device.CreateBuffer("Rows", 2, 16))
            {
                device.SetBuffer(program, kernel, device.PropertyId("_Rows"), rows);
                Assert.That(() => device.Dispatch(program, kernel, 1, 1, 1),
                    Throws.InstanceOf<ComputeException>().With.Message.Contains("cbuffer 'RowConstants' was never bound"));
            }
        }

        [Test]
        public void SizesOutsideTheRulesAreRefused()
        {
            var device = GpuTestDevice.Shared;
            Assert.That(() => device.CreateConstantBuffer("Odd", 20), Throws.InstanceOf<System.ArgumentOutOfRangeException>().With.Message.Contains("multiple of 16"));
            using (var constants = device.CreateConstantBuffer("Small", 16))
                Assert.That(() => device.UpdateBuffer(constants, new Vector4[2]),
                    Throws.InstanceOf<System.ArgumentOutOfRangeException>().With.Message.Contains("do not fit"));
        }
    }
}
