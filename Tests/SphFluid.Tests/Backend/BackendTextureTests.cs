using System;
using System.IO;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>Texture2D/3D, RWTexture2D/3D and SamplerState kernels of BackendUnitySource.compute, run beside its
    /// buffer kernels: results against the CPU, the checks that name a wrong texture or sampler, and texture lifetime.</summary>
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

        /// <summary>Texel (x, y, z) of the sampled volume holds x + 10 y + 100 z, a linear function, so linear
        /// filtering between texel centres returns the function itself; the coordinates put the sample points at
        /// quarter texels, exact under any filtering precision Vulkan allows.</summary>
        [TestCase(TextureWrap.Clamp, 185.5f)]
        [TestCase(TextureWrap.Repeat, 183.25f)]
        public void SamplingUsesTheTexturesOwnSettingsAndInlineSamplerNames(TextureWrap wrap, float linearBeyondTheEdge)
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnitySource");
            int kernel = program.FindKernel("SampleVolume");
            var texels = new Vector4[64];
            for (int z = 0; z < 4; z++)
                for (int y = 0; y < 4; y++)
                    for (int x = 0; x < 4; x++)
                        texels[x + 4 * y + 16 * z] = new Vector4(x + 10 * y + 100 * z, 0, 0, 1);
            // Texel coordinates uvw * 4 - 0.5: (1.5, 1.5, 1.5), (1.25, 2.25, 0.75), and (3.75, 0.75, 1.75) past the +x edge.
            var coords = new[] { new Vector3(0.5f, 0.5f, 0.5f), new Vector3(0.4375f, 0.6875f, 0.3125f), new Vector3(1.0625f, 0.3125f, 0.5625f) };
            using (var volume = device.CreateTexture3D("Source", 4, 4, 4, VulkanTextureFormat.R32G32B32A32_SFloat))
            using (var coordBuffer = device.CreateBuffer("Coords", coords.Length, 12))
            using (var values = device.CreateBuffer("Values", 2 * coords.Length, sizeof(float)))
            {
                volume.Filter = TextureFilter.Linear;
                volume.Wrap = wrap;
                volume.SetData(texels);
                coordBuffer.SetData(coords);
                device.SetTexture(program, kernel, device.PropertyId("_Source"), volume);
                device.SetBuffer(program, kernel, device.PropertyId("_Coords"), coordBuffer);
                device.SetBuffer(program, kernel, device.PropertyId("_Values"), values);
                device.SetInt(program, device.PropertyId("numItems"), coords.Length);
                device.Dispatch(program, kernel, 1, 1, 1);
                var result = new float[2 * coords.Length];
                values.GetData(result);
                Assert.That(result[0], Is.EqualTo(166.5f).Within(1e-3f), "linear at the centre");
                Assert.That(result[1], Is.EqualTo(222f), "point at the centre: texel (2, 2, 2)");
                Assert.That(result[2], Is.EqualTo(98.75f).Within(1e-3f), "linear between texels");
                Assert.That(result[3], Is.EqualTo(121f), "point between texels: texel (1, 2, 1)");
                Assert.That(result[4], Is.EqualTo(linearBeyondTheEdge).Within(1e-3f), "linear past the edge, " + wrap);
                Assert.That(result[5], Is.EqualTo(213f), "point-clamp past the edge: texel (3, 1, 2)");
            }
        }

        [Test]
        public void InlineSamplerNamesAreReadAsUnityReadsThem()
        {
            Assert.That(SamplerSettings.FromInlineName("sampler_linear_clamp"), Is.EqualTo(new SamplerSettings(TextureFilter.Linear, TextureWrap.Clamp)));
            Assert.That(SamplerSettings.FromInlineName("my_Trilinear_MirrorOnce_sampler"), Is.EqualTo(new SamplerSettings(TextureFilter.Linear, TextureWrap.MirrorOnce)));
            Assert.That(SamplerSettings.FromInlineName("PointRepeat"), Is.EqualTo(new SamplerSettings(TextureFilter.Point, TextureWrap.Repeat)));
            Assert.That(SamplerSettings.FromInlineName("sampler_MainTex"), Is.Null);
            Assert.That(() => SamplerSettings.FromInlineName("sampler_linear_clampu_repeatv"),
                Throws.ArgumentException.With.Message.Contains("per axis"));
        }

        [Test]
        public void ASamplerThatIsNeitherInlineNorNamedAfterATextureIsRefusedAtDispatch()
        {
            string dir = Path.Combine(Path.GetTempPath(), "sphfluid-sampler-" + TestContext.CurrentContext.Test.ID);
            Directory.CreateDirectory(dir);
            try
            {
                string path = Path.Combine(dir, "LooseSampler.compute");
                File.WriteAllText(path, "#pragma kernel Main\nTexture2D<float4> _Image;\nSamplerState smoothSampler;\nRWStructuredBuffer<float4> _Out;\n" +
                                        "[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID) { _Out[0] = _Image.SampleLevel(smoothSampler, float2(0.5, 0.5), 0.0); }\n");
                var device = GpuTestDevice.Shared;
                var program = device.LoadProgram(path);
                int kernel = program.FindKernel("Main");
                using (var image = device.CreateTexture2D("Image", 2, 2, VulkanTextureFormat.R32G32B32A32_SFloat))
                using (var output = device.CreateBuffer("Out", 1, 16))
                {
                    device.SetTexture(program, kernel, device.PropertyId("_Image"), image);
                    device.SetBuffer(program, kernel, device.PropertyId("_Out"), output);
                    Assert.That(() => device.Dispatch(program, kernel, 1, 1, 1),
                        Throws.TypeOf<ComputeException>().With.Message.Contains("'smoothSampler'").And.Message.Contains("sampler_linear_clamp"));
                }
            }
            finally
            {
                Directory.Delete(dir, true);
            }
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
