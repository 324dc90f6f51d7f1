using System.IO;
using NUnit.Framework;
using SphFluid.Headless.Output;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Output
{
    /// <summary>Every diagnostics column has its own header, even for phase names that fold to one prefix.</summary>
    public sealed class DiagnosticsCsvColumnTests
    {
        [Test]
        public void NamesThatFoldToOnePrefixGetNumberedPrefixes()
        {
            var phases = new[] { new PhaseDescription("Oil-1", 900f, 0.05f), new PhaseDescription("Oil 1", 850f, 0.05f), new PhaseDescription("oil_1_2", 800f, 0.05f) };
            Assert.That(DiagnosticsCsv.ColumnPrefixes(phases), Is.EqualTo(new[] { "oil_1", "oil_1_2", "oil_1_2_2" }));
        }

        [Test]
        public void TheHeaderHasNoDuplicateColumn()
        {
            var phases = new[] { new PhaseDescription("Water", 1000f, 0.001f), new PhaseDescription("Wa ter", 1000f, 0.001f), new PhaseDescription("Wa-ter", 1000f, 0.001f) };
            string path = Path.Combine(RunnerPaths.ScratchFolder("csv-columns"), "diagnostics.csv");
            using (new DiagnosticsCsv(path, phases)) { }
            string[] columns = File.ReadAllLines(path)[0].Split(',');
            Assert.That(columns, Is.Unique);
            Assert.That(columns, Has.Member("wa_ter_count").And.Member("wa_ter_2_count").And.Member("water_count"));
        }
    }
}
