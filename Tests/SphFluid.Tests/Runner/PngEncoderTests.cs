using System;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless.Output;
using StbImageSharp;

namespace SphFluid.Tests.Runner
{
    public sealed class PngEncoderTests
    {
        [Test]
        public void AnEncodedImageDecodesToTheSamePixels()
        {
            var image = new RgbImage(37, 23);
            var random = new Random(7);
            random.NextBytes(image.Pixels);
            image.FillDisc(18, 11, 6, new Rgb(10, 200, 30));

            byte[] png = PngEncoder.Encode(image);

            Assert.That(png.Take(8).ToArray(), Is.EqualTo(PngEncoder.Signature));
            var chunks = PngChunks.Read(png);
            Assert.That(chunks.Select(c => c.Type).ToArray(), Is.EqualTo(new[] { "IHDR", "IDAT", "IEND" }));
            foreach (var c in chunks) Assert.That(c.StoredCrc, Is.EqualTo(c.ComputedCrc), c.Type + " CRC");
            Assert.That(chunks[0].Data.Skip(8).ToArray(), Is.EqualTo(new byte[] { 8, 2, 0, 0, 0 }), "8-bit truecolour, deflate, no interlace");
            var decoded = ImageResult.FromMemory(png, ColorComponents.RedGreenBlue);
            Assert.That(decoded.Width, Is.EqualTo(37));
            Assert.That(decoded.Height, Is.EqualTo(23));
            Assert.That(decoded.SourceComp, Is.EqualTo(ColorComponents.RedGreenBlue), "stored as RGB, no alpha");
            Assert.That(decoded.Data, Is.EqualTo(image.Pixels));
        }

        [Test]
        public void ASinglePixelImageIsValid()
        {
            var image = new RgbImage(1, 1);
            image.Set(0, 0, new Rgb(1, 2, 3));
            var decoded = ImageResult.FromMemory(PngEncoder.Encode(image), ColorComponents.RedGreenBlue);
            Assert.That(decoded.Width, Is.EqualTo(1));
            Assert.That(decoded.Height, Is.EqualTo(1));
            Assert.That(decoded.Data, Is.EqualTo(new byte[] { 1, 2, 3 }));
        }

        [Test]
        public void AFlippedPixelByteBreaksTheStoredCrc()
        {
            var image = new RgbImage(8, 8);
            image.Fill(new Rgb(40, 80, 120));
            byte[] png = PngEncoder.Encode(image);
            png[8 + 25 + 8 + 2] ^= 0x01; // a byte inside IDAT's data: signature, whole IHDR, IDAT's length and type

            var idat = PngChunks.Read(png)[1];
            Assert.That(idat.Type, Is.EqualTo("IDAT"));
            Assert.That(idat.ComputedCrc, Is.Not.EqualTo(idat.StoredCrc));
        }

        [Test]
        public void SrgbEncodingOfLinearColoursRoundTripsTheInspectorValue()
        {
            float linear = SphFluid.Headless.Scenes.ColorSpace.SrgbToLinear(0.5f);
            Assert.That(Rgb.FromLinear(linear, 0f, 1f), Is.EqualTo(new Rgb(128, 0, 255)));
        }
    }
}
