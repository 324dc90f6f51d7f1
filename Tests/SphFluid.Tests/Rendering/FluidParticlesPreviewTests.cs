using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Runtime.InteropServices;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Simulation;

namespace SphFluid.Tests.Rendering
{
    /// <summary>
    /// A small headless picture of water and oil drawn with the particle shader's own impostor and optics
    /// includes (Shaders/FluidParticlesPreview.compute) and the shader's default material values: the two
    /// liquids must read as different colours, water blue-green and oil amber. The PNG is attached to the
    /// test result for eyes.
    /// </summary>
    public sealed class FluidParticlesPreviewTests
    {
        const int Width = 256, Height = 160;

        /// <summary>The phase optics suggested to the scenes (api-rendering.md): water blue-green, oil amber.</summary>
        static PhaseProperties Water() => new PhaseProperties { RestDensity = 1000f, Color = new Vector4(0.25f, 0.65f, 0.75f, 0.8f), FresnelF0 = 0.02f, Absorption = 8f };
        static PhaseProperties Oil() => new PhaseProperties { RestDensity = 900f, Color = new Vector4(0.95f, 0.65f, 0.15f, 0.9f), FresnelF0 = 0.035f, Absorption = 15f };

        static Particle[] TwoBlocks(float spacing)
        {
            var particles = new System.Collections.Generic.List<Particle>();
            for (uint phase = 0; phase < 2; phase++)
            {
                float x0 = phase == 0 ? -0.3f : 0.06f;
                for (int i = 0; i < 12; i++)
                    for (int j = 0; j < 6; j++)
                        for (int k = 0; k < 6; k++)
                            particles.Add(new Particle(new Vector3(x0 + i * spacing, -0.09f + j * spacing, -0.06f + k * spacing), Vector3.Zero, phase, (uint)particles.Count));
            }
            return particles.ToArray();
        }

        [Test]
        public void Water_and_oil_render_as_different_liquids()
        {
            var device = GpuTestDevice.Shared;
            var shader = ShaderLabSource.Load(Path.Combine(GpuTestDevice.RepoRoot, "Packages/com.sphfluid.fluid/Shaders/FluidParticles.shader"));
            float Default(string name) => float.Parse(shader.Properties.Single(p => p.Name == name).Default, CultureInfo.InvariantCulture);

            var particles = TwoBlocks(0.02f);
            var phases = new[] { Water(), Oil() };
            var program = device.LoadProgram("FluidParticlesPreview");
            int kernel = program.FindKernel("RenderPreview");
            var pixels = new Vector4[Width * Height];

            var eye = new Vector3(0f, 0.2f, 0.55f);
            var forward = Vector3.Normalize(new Vector3(0f, -0.02f, 0f) - eye);
            var right = Vector3.Normalize(Vector3.Cross(forward, Vector3.UnitY));
            var up = Vector3.Cross(right, forward);
            using (var particleBuffer = device.CreateBuffer("PreviewParticles", particles.Length, Marshal.SizeOf<Particle>()))
            using (var phaseBuffer = device.CreateBuffer("PreviewPhases", phases.Length, Marshal.SizeOf<PhaseProperties>()))
            using (var pixelBuffer = device.CreateBuffer("PreviewPixels", pixels.Length, 16))
            {
                particleBuffer.SetData(particles);
                phaseBuffer.SetData(phases);
                device.SetBuffer(program, kernel, device.PropertyId("_Particles"), particleBuffer);
                device.SetBuffer(program, kernel, device.PropertyId("_Phases"), phaseBuffer);
                device.SetBuffer(program, kernel, device.PropertyId("_Pixels"), pixelBuffer);
                device.SetInt(program, device.PropertyId("_ParticleCount"), particles.Length);
                device.SetInt(program, device.PropertyId("_Width"), Width);
                device.SetInt(program, device.PropertyId("_Height"), Height);
                device.SetVector(program, device.PropertyId("_Eye"), new Vector4(eye, MathF.Tan(0.5f * 40f * MathF.PI / 180f)));
                device.SetVector(program, device.PropertyId("_Right"), new Vector4(right, 0f));
                device.SetVector(program, device.PropertyId("_Up"), new Vector4(up, 0f));
                device.SetVector(program, device.PropertyId("_Forward"), new Vector4(forward, 0f));
                device.SetVector(program, device.PropertyId("_LightDirection"), new Vector4(Vector3.Normalize(new Vector3(0.4f, 0.8f, 0.3f)), 0f));
                device.SetVector(program, device.PropertyId("_LightColor"), new Vector4(1f, 0.96f, 0.9f, 1f));
                foreach (string name in new[] { "_ParticleRadius", "_RefractionStrength", "_ReflectionStrength", "_ThicknessScale", "_ScatterStrength", "_SpecularStrength", "_SpecularPower" })
                    device.SetFloat(program, device.PropertyId(name), Default(name));
                device.DispatchThreads(program, kernel, pixels.Length);
                pixelBuffer.GetData(pixels);
            }

            string png = Path.Combine(TestContext.CurrentContext.WorkDirectory, "Rendering", "FluidParticlesPreview.png");
            PreviewPng.Write(png, pixels, Width, Height);
            TestContext.AddTestAttachment(png, "water (left) and oil (right) with the shader's default material");

            Assert.That(pixels.All(p => float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z)), Is.True, "non-finite colour");
            var water = pixels.Where(p => p.W == 1f).ToList();
            var oil = pixels.Where(p => p.W == 2f).ToList();
            Assert.That(water.Count, Is.GreaterThan(pixels.Length / 20), "water covers too little of the image");
            Assert.That(oil.Count, Is.GreaterThan(pixels.Length / 20), "oil covers too little of the image");
            Vector4 waterMean = water.Aggregate(Vector4.Zero, (a, p) => a + p) / water.Count;
            Vector4 oilMean = oil.Aggregate(Vector4.Zero, (a, p) => a + p) / oil.Count;
            string means = "water mean " + waterMean + ", oil mean " + oilMean + " (" + png + ")";
            Assert.That(waterMean.Z > waterMean.X && waterMean.Y > waterMean.X, Is.True, "water should read blue-green: " + means);
            Assert.That(oilMean.X > oilMean.Z && oilMean.Y > oilMean.Z, Is.True, "oil should read amber: " + means);
        }
    }
}
