using System.IO;
using System.Linq;
using NUnit.Framework;
using StbImageSharp;

namespace SphFluid.Tests.Runner
{
    /// <summary>Checks a chart the runner wrote: the PNG decodes (an independent decoder) to a picture with more than a
    /// few colours, and the SVG carries the title and axis labels as text.</summary>
    public static class WrittenChart
    {
        public static void Check(string folder, string stem, params string[] texts)
        {
            string png = Path.Combine(folder, stem + ".png"), svg = Path.Combine(folder, stem + ".svg");
            Assert.That(File.Exists(png), Is.True, png);
            Assert.That(File.Exists(svg), Is.True, svg);
            var image = ImageResult.FromMemory(File.ReadAllBytes(png), ColorComponents.RedGreenBlue);
            Assert.That(image.Width, Is.GreaterThanOrEqualTo(400), stem + ".png width");
            Assert.That(image.Height, Is.GreaterThanOrEqualTo(300), stem + ".png height");
            int colours = Enumerable.Range(0, image.Width * image.Height)
                .Select(i => (image.Data[3 * i] << 16) | (image.Data[3 * i + 1] << 8) | image.Data[3 * i + 2]).Distinct().Count();
            Assert.That(colours, Is.GreaterThan(20), stem + ".png is a drawn chart, not a blank image");
            string text = File.ReadAllText(svg);
            Assert.That(text, Does.StartWith("<?xml").Or.StartWith("<svg"), stem + ".svg is SVG");
            foreach (string expected in texts) Assert.That(text, Does.Contain(expected), stem + ".svg text");
        }
    }
}
