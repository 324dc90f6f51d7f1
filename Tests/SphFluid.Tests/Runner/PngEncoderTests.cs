using System;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless.Output;

namespace SphFluid.Tests.Runner
{
    public sealed class PngEncoderTests
    {
        [Test]
        public void Crc32MatchesTheStandardCheckValue()
        {
            Assert.That(Crc32.Compute(System.Text.Encoding.ASCII.GetBytes("123456789")), Is.EqualTo(0xCBF43926u));
        }

        [Test]
        public void AnEncodedImageDecodesToTheSamePixels()
        {
            var image = new RgbImage(37, 23);
            var random = new Random(7);
            random.NextBytes(image.Pixels);
            image.FillDisc(18, 11, 6, new Rgb(10, 200, 30));

            byte[] png = PngEncoder.Encode(image);

            Assert.That(png.Take(8).ToArray(), Is.EqualTo(PngEncoder.Signature));
            var chunks = PngDecoder.Chunks(png);
            Assert.That(chunks.Select(c => c.Type).ToArray(), Is.EqualTo(new[] { "IHDR", "IDAT", "IEND" }));
            foreach (var c in chunks) Assert.That(c.StoredCrc, Is.EqualTo(c.ComputedCrc), c.Type + " CRC");
            Assert.That(chunks[0].Data.Skip(8).ToArray(), Is.EqualTo(new byte[] { 8, 2, 0, 0, 0 }), "8-bit truecolour, deflate, no interlace");
            byte[] pixels = PngDecoder.Pixels(chunks, out int width, out int height);
            Assert.That(width, Is.EqualTo(37));
            Assert.That(height, Is.EqualTo(23));
            Assert.That(pixels, Is.EqualTo(image.Pixels));
        }

        [Test]
        public void ASinglePixelImageIsValid()
        {
            var image = new RgbImage(1, 1);
            image.Set(0, 0, new Rgb(1, 2, 3));
            var chunks = PngDecoder.Chunks(PngEncoder.Encode(image));
            Assert.That(PngDecoder.Pixels(chunks, out _, out _), Is.EqualTo(new byte[] { 1, 2, 3 }));
        }

        [Test]
        public void SrgbEncodingOfLinearColoursRoundTripsTheInspectorValue()
        {
            float linear = SphFluid.Headless.Scenes.ColorSpace.SrgbToLinear(0.5f);
            Assert.That(Rgb.FromLinear(linear, 0f, 1f), Is.EqualTo(new Rgb(128, 0, 255)));
        }
    }
}
