using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Compute;

namespace SphFluid.Tests.Backend
{
    /// <summary>Every global type lands where HLSL reads it (std140 offsets, matrix orientation).</summary>
    public sealed class BackendGlobalTests
    {
        static Matrix4x4 Asymmetric()
        {
            // M{r}{c} = 10 r + c: every element differs from its transpose.
            return new Matrix4x4(11, 12, 13, 14, 21, 22, 23, 24, 31, 32, 33, 34, 41, 42, 43, 44);
        }

        [Test]
        public void EveryGlobalTypeReachesTheKernel()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendGlobals");
            int kernel = program.FindKernel("EchoGlobals");
            using (var echo = device.CreateBuffer("Echo", 32, sizeof(uint)))
            {
                device.SetBuffer(program, kernel, device.PropertyId("_Echo"), echo);
                device.SetInt(program, device.PropertyId("_Int"), -7);
                device.SetInt(program, device.PropertyId("_Uint"), unchecked((int)0xDEADBEEFu));
                device.SetFloat(program, device.PropertyId("_Float"), 1.5f);
                device.SetVector(program, device.PropertyId("_Float2"), new Vector4(2.5f, 3.5f, 99f, 99f));
                device.SetVector(program, device.PropertyId("_Float3"), new Vector4(4.5f, 5.5f, 6.5f, 99f));
                device.SetVector(program, device.PropertyId("_Float4"), new Vector4(7.5f, 8.5f, 9.5f, 10.5f));
                device.SetFloat(program, device.PropertyId("_AfterFloat4"), 11.5f);
                device.SetInts(program, device.PropertyId("_UintThree"), 12, 13, 14);
                device.SetMatrix(program, device.PropertyId("_Matrix"), Asymmetric());
                device.Dispatch(program, kernel, 1, 1, 1);
                device.Submit();
                var words = new uint[32];
                echo.GetData(words);

                Assert.That((int)words[0], Is.EqualTo(-7), "int");
                Assert.That(words[1], Is.EqualTo(0xDEADBEEFu), "uint");
                Assert.That(BitConverter.UInt32BitsToSingle(words[2]), Is.EqualTo(1.5f), "float");
                Assert.That(AsFloats(words, 3, 2), Is.EqualTo(new[] { 2.5f, 3.5f }), "float2");
                Assert.That(AsFloats(words, 5, 3), Is.EqualTo(new[] { 4.5f, 5.5f, 6.5f }), "float3");
                Assert.That(AsFloats(words, 8, 4), Is.EqualTo(new[] { 7.5f, 8.5f, 9.5f, 10.5f }), "float4");
                Assert.That(BitConverter.UInt32BitsToSingle(words[12]), Is.EqualTo(11.5f), "float after float4");
                Assert.That(new[] { words[13], words[14], words[15] }, Is.EqualTo(new[] { 12u, 13u, 14u }), "uint3");
                for (int r = 0; r < 4; r++)
                    for (int c = 0; c < 4; c++)
                        Assert.That(BitConverter.UInt32BitsToSingle(words[16 + 4 * r + c]), Is.EqualTo(10f * (r + 1) + (c + 1)),
                            "HLSL _Matrix[" + r + "][" + c + "] must be managed M" + (r + 1) + (c + 1));
            }
        }

        [Test]
        public void MatrixTransformsColumnVectorsWithTranslationInTheLastColumn()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendGlobals");
            int kernel = program.FindKernel("TransformPoint");
            // Scale x by 2, then translate by (10, 20, 30): translation in M14, M24, M34 as in Unity.
            var m = new Matrix4x4(2, 0, 0, 10, 0, 1, 0, 20, 0, 0, 1, 30, 0, 0, 0, 1);
            using (var output = device.CreateBuffer("Transformed", 1, 16))
            {
                device.SetBuffer(program, kernel, device.PropertyId("_Transformed"), output);
                device.SetMatrix(program, device.PropertyId("_Matrix"), m);
                device.SetVector(program, device.PropertyId("_Point"), new Vector4(1, 2, 3, 0));
                device.Dispatch(program, kernel, 1, 1, 1);
                var result = new Vector4[1];
                output.GetData(result);
                Assert.That(result[0], Is.EqualTo(new Vector4(12, 22, 33, 1)));
            }
        }

        [Test]
        public void EachDispatchKeepsTheValuesSetBeforeIt()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendSmoke");
            int kernel = program.FindKernel("Fill");
            using (var first = device.CreateBuffer("First", 4, sizeof(float)))
            using (var second = device.CreateBuffer("Second", 4, sizeof(float)))
            {
                device.SetInt(program, device.PropertyId("_Count"), 4);
                device.SetBuffer(program, kernel, device.PropertyId("_Output"), first);
                device.SetFloat(program, device.PropertyId("_Scale"), 2f);
                device.Dispatch(program, kernel, 1, 1, 1);
                device.SetBuffer(program, kernel, device.PropertyId("_Output"), second);
                device.SetFloat(program, device.PropertyId("_Scale"), 3f);
                device.Dispatch(program, kernel, 1, 1, 1);
                device.Submit();
                var a = new float[4];
                var b = new float[4];
                first.GetData(a);
                second.GetData(b);
                Assert.That(a, Is.EqualTo(new[] { 1f, 3f, 5f, 7f }));
                Assert.That(b, Is.EqualTo(new[] { 1f, 4f, 7f, 10f }));
            }
        }

        static float[] AsFloats(uint[] words, int start, int count)
        {
            var result = new float[count];
            for (int i = 0; i < count; i++) result[i] = BitConverter.UInt32BitsToSingle(words[start + i]);
            return result;
        }
    }
}
