using System.Linq;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>A scene's double-quoted "\e[2J" reached the terminal as an escape sequence, in the phase's diagnostics
    /// lines and in the errors that quote a value; names and quotes are now refused or shown escaped.</summary>
    public sealed class PrintableTextTests
    {
        [Test]
        public void ControlAndBidiCharactersAreShownAsEscapes()
        {
            Assert.That(PrintableText.Escape("Oil\u001B[2J\r\a"), Is.EqualTo("Oil\\u001B[2J\\u000D\\u0007"));
            Assert.That(PrintableText.Escape("\u009Bx\u202Elio"), Is.EqualTo("\\u009Bx\\u202Elio"), "C1's CSI and a right-to-left override");
            Assert.That(PrintableText.Escape("a\nb\tc"), Is.EqualTo("a\\u000Ab\\u0009c"));
            Assert.That(PrintableText.Escape("a\nb\tc", keepLineBreaks: true), Is.EqualTo("a\nb\\u0009c"));
        }

        [Test]
        public void PrintableTextIsLeftAsItIs()
        {
            foreach (string text in new[] { "", "Water", "Öl | \"x\" & <y>", "水", "naïve café" })
            {
                Assert.That(PrintableText.Escape(text), Is.SameAs(text));
                Assert.That(PrintableText.FirstUnprintable(text), Is.EqualTo(-1));
            }
        }

        [Test]
        public void APhaseNameWithAControlCharacterIsRefusedNamingTheCharacter()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes[0].Phase.Name = "Wa\u001B[31mter";
            var errors = scene.Validate();
            Assert.That(errors.Select(e => e.Field).ToArray(), Is.EqualTo(new[] { "SpawnBoxes[0].Phase.Name" }));
            Assert.That(errors[0].Message, Is.EqualTo(
                "SpawnBox 'Water': Name must be printable text, without control characters (was 'Wa\\u001B[31mter', U+001B at character 3)"));
        }
    }
}
