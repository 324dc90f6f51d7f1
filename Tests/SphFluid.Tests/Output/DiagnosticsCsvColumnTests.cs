using System;
using System.IO;
using System.Linq;
using System.Text;
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
            Assert.That(DiagnosticsCsv.ColumnPrefixes(phases.Select(p => p.Name)), Is.EqualTo(new[] { "oil_1", "oil_1_2", "oil_1_2_2" }));
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

        /// <summary>Takes <see cref="Room"/> bytes and fails part-way through the write that passes them, as a full disk
        /// does.</summary>
        sealed class FullDisk : MemoryStream
        {
            public long Room { get; init; }

            public override void Write(byte[] buffer, int offset, int count)
            {
                long fits = Math.Max(0, Room - Length);
                base.Write(buffer, offset, (int)Math.Min(count, fits));
                if (fits < count) throw new IOException("No space left on device");
            }
        }

        static readonly PhaseDescription[] Water = { new PhaseDescription("Water", 1000f, 0.001f) };

        static DiagnosticsRow Row(double time) => new(time, 1, StepReport.None,
            new DiagnosticsReport(1.0, 0.01, 0.2f, 0, 0, new[] { new PhaseDiagnostics("Water", 60, 0.01f, 0.05f) }, 0.5), null!);

        /// <summary>A full disk left diagnostics.csv ending mid-row; now the log ends on the last whole row, and the error
        /// names the file.</summary>
        [Test]
        public void ARowAFullDiskCutsShortIsRemoved_TheLogEndsOnAWholeRow()
        {
            var probe = new MemoryStream();
            using (var csv = new DiagnosticsCsv(probe, "probe.csv", Water)) csv.Append(Row(0));
            byte[] whole = probe.ToArray();
            int headerEnd = Array.IndexOf(whole, (byte)'\n') + 1;
            var disk = new FullDisk { Room = whole.Length + 20 }; // the header, the first row and 20 bytes of the second

            var csvOnDisk = new DiagnosticsCsv(disk, "out/diagnostics.csv", Water);
            csvOnDisk.Append(Row(0));
            var e = Assert.Throws<IOException>(() => csvOnDisk.Append(Row(0.5))).OrFail("the failure");
            csvOnDisk.Dispose();

            Assert.That(e.Message, Is.EqualTo("cannot append to out/diagnostics.csv: No space left on device; the part of the row written was removed"));
            Assert.That(disk.ToArray(), Is.EqualTo(whole), "the header and the first row, whole");
            Assert.That(headerEnd, Is.GreaterThan(0).And.LessThan(whole.Length));

            var full = new FullDisk { Room = headerEnd - 5 };
            e = Assert.Throws<IOException>(() => new DiagnosticsCsv(full, "out/diagnostics.csv", Water)).OrFail("the header's failure");
            Assert.That(e.Message, Does.StartWith("cannot append to out/diagnostics.csv: No space left on device"));
            Assert.That(full.ToArray(), Is.Empty, "no part of the header");
            Assert.That(Encoding.UTF8.GetString(whole, 0, headerEnd), Does.StartWith("time_s,frame,"));
        }
    }
}
