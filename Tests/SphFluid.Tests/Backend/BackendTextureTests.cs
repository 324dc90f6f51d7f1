using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>Texture2D/3D and RWTexture2D/3D kernels of BackendUnitySource.compute, run beside its buffer kernels:
    /// results against the CPU, the checks that name a wrong texture, and texture lifetime.</summary>
    public sealed class BackendTextureTests
    {
        [Test]
        public void A3DTextureWrittenByOneKernelIsReadByAnotherAndByTheHost()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnitySource");
            int fill = program.FindKernel("FillVolume"), read = program.FindKernel("ReadVolume");
            using (var volume = device.CreateTexture3D("Volume", 4, 4, 4, VulkanTextureFormat.R32G32B32A32_SFloat))
            using (var values = device.CreateBuffer("Values", 64, sizeof(float)))
            {
                device.SetFloat(program, device.PropertyId("gain"), 0.5f);
                device.SetTexture(program, fill, device.PropertyId("_Volume"), volume);
                device.Dispatch(program, fill, 1, 1, 1);
                device.SetTexture(program, read, device.PropertyId("_Source"), volume);
                device.SetBuffer(program, read, device.PropertyId("_Values"), values);
                device.Dispatch(program, read, 1, 1, 1);
                var texels = new Vector4[64];
                volume.GetData(texels);
                var sums = new float[64];
                values.GetData(sums);
                for (int z = 0; z < 4; z++)
                    for (int y = 0; y < 4; y++)
                        for (int x = 0; x < 4; x++)
                        {
                            int i = x + 4 * y + 16 * z;
                            Assert.That(texels[i], Is.EqualTo(new Vector4(x, y, z, 0.5f)), "texel " + x + "," + y + "," + z);
                            Assert.That(sums[i], Is.EqualTo(x + y + z + 0.5f), "ReadVolume at texel " + x + "," + y + "," + z);
                        }
            }
        }

        [Test]
        public void A2DTextureUploadedByTheHostIsOverwrittenByItsKernel()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnitySource");
            int kernel = program.FindKernel("FillPlane");
            using (var plane = device.CreateTexture2D("Plane", 16, 8, VulkanTextureFormat.R32_SFloat))
            {
                plane.SetData(Enumerable.Repeat(-1f, 16 * 8).ToArray());
                var before = new float[16 * 8];
                plane.GetData(before);
                Assert.That(before, Is.All.EqualTo(-1f), "the upload arrived");
                device.SetFloat(program, device.PropertyId("gain"), 2f);
                device.SetTexture(program, kernel, device.PropertyId("_Plane"), plane);
                device.Dispatch(program, kernel, 2, 1, 1);
                var after = new float[16 * 8];
                plane.GetData(after);
                for (int y = 0; y < 8; y++)
                    for (int x = 0; x < 16; x++)
                        Assert.That(after[x + 16 * y], Is.EqualTo(2f * (x + 10 * y)), "texel " + x + "," + y);
            }
        }

        [Test]
        public void ATextureOfTheWrongShapeOrFormatAndAnUnboundTextureAreNamed()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnitySource");
            int fill = program.FindKernel("FillVolume");
            using (var flat = device.CreateTexture2D("Flat", 4, 4, VulkanTextureFormat.R32G32B32A32_SFloat))
            using (var scalar = device.CreateTexture3D("ScalarVolume", 4, 4, 4, VulkanTextureFormat.R32_SFloat))
            {
                Assert.That(() => device.Dispatch(program, program.FindKernel("FillPlane"), 1, 1, 1),
                    Throws.TypeOf<ComputeException>().With.Message.Contains("'_Plane' (RWTexture2D<float>) was never bound"));
                Assert.That(() => device.SetTexture(program, fill, device.PropertyId("_Volume"), flat),
                    Throws.TypeOf<ComputeException>().With.Message.Contains("Flat").And.Message.Contains("RWTexture3D<float4>").And.Message.Contains("3D texture of R32G32B32A32_SFloat"));
                Assert.That(() => device.SetTexture(program, fill, device.PropertyId("_Volume"), scalar),
                    Throws.TypeOf<ComputeException>().With.Message.Contains("ScalarVolume").And.Message.Contains("R32_SFloat"));
            }
            Assert.That(() => device.CreateTexture2D("Huge", 0, 4, VulkanTextureFormat.R32_SFloat),
                Throws.TypeOf<ComputeException>().With.Message.Contains("Huge").And.Message.Contains("width 0"));
        }

        [Test]
        public void TextureDisposedWhileItsDispatchIsRecordedLivesUntilTheGpuIsDone()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnitySource");
            int kernel = program.FindKernel("FillPlane");
            var plane = device.CreateTexture2D("ShortLivedPlane", 8, 8, VulkanTextureFormat.R32_SFloat);
            device.SetTexture(program, kernel, device.PropertyId("_Plane"), plane);
            device.Dispatch(program, kernel, 1, 1, 1);
            plane.Dispose();
            Assert.That(() => plane.Dispose(), Throws.Nothing);
            Assert.That(() => device.Submit(), Throws.Nothing);
            Assert.That(() => device.Dispatch(program, kernel, 1, 1, 1),
                Throws.TypeOf<ObjectDisposedException>().With.Message.Contains("ShortLivedPlane"));
            Assert.That(() => plane.GetData(new float[64]), Throws.TypeOf<ObjectDisposedException>().With.Message.Contains("ShortLivedPlane"));
        }
    }
}
