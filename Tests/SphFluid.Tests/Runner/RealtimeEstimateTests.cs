using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;

namespace SphFluid.Tests.Runner
{
    /// <summary>
    /// Headless/tools/realtime-estimate.sh, which the README cites for what a DFSPH sub-step at 1M particles costs on the
    /// H200 whatever its solve does: the figures it prints from the committed profile, and its errors for bad input.
    /// </summary>
    public class RealtimeEstimateTests
    {
        const string Profile = "Headless/figures/gpu-h200-realtime.txt";

        static (int exitCode, string output, string error) Estimate(params string[] arguments) =>
            RepositoryScript.Run(Path.Combine("Headless", "tools", "realtime-estimate.sh"), arguments);

        [Test]
        public void TheOneMillionSliceCostsSeventeenGpuSecondsASimulatedSecond()
        {
            var (exitCode, output, error) = Estimate(Profile, "1.3889", "7.3", "6.2");
            Assert.That(exitCode, Is.EqualTo(0), error);
            Assert.That(output, Does.Contain("fixed a sub-step: 5.765 ms (FindNeighbours 3.350, NonPressureForces 1.177, DensityFactor 0.861,"));
            Assert.That(output, Does.Contain("warm starts: 1.089 ms"));
            Assert.That(output, Does.Contain("per simulated second: 720.0 sub-steps, 17.27 s GPU (4.94 s fixed and warm starts, 12.33 s solves)"));
        }

        [Test]
        public void TheLongestStepWithTheFewestCorrectionsIsStillSlowerThanRealTime()
        {
            var (exitCode, output, error) = Estimate(Profile, "5", "2", "2");
            Assert.That(exitCode, Is.EqualTo(0), error);
            Assert.That(output, Does.Contain("12.837 ms GPU"));
            Assert.That(output, Does.Contain("200.0 sub-steps, 2.57 s GPU (1.37 s fixed and warm starts, 1.20 s solves); real-time factor at most 0.389x"));
        }

        /// <summary>A table the bench prints today carries the dispatches that ran, and a correction is costed by them: a
        /// DFSPH bench of a small scene on lavapipe, whose ApplyStiffness the estimate must cost at its milliseconds over
        /// the dispatches that ran, not over every dispatch recorded.</summary>
        [Test]
        public void ATableWithTheRanColumnCostsTheDispatchesThatRan()
        {
            var stdout = new StringWriter();
            var bench = new BenchRun(BenchOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--solver", "dfsph", "--steps", "3", "--warmup", "2",
                "--skip-savings", "--out", RunnerPaths.ScratchFolder("estimate-bench") }), stdout, new StringWriter())
            {
                Device = GpuTestDevice.Shared,
            };
            Assert.That(bench.Execute(), Is.EqualTo(0));
            string table = Path.Combine(RunnerPaths.ScratchFolder("estimate-table"), "bench.txt");
            File.WriteAllText(table, stdout.ToString());
            var apply = bench.Rows[^1].Kernels.Single(k => k.Kernel == "ApplyStiffness");
            Assert.That(apply.Ran, Is.LessThan(apply.Dispatches), "the budget records rounds the solves did not need");

            var (exitCode, output, error) = Estimate(table, "5", "2", "2");
            Assert.That(exitCode, Is.EqualTo(0), error);
            Assert.That(output, Does.Contain("each kernel's cost over the dispatches that ran groups"));
            // The table's rounding: ms to three places, ran to one.
            var row = Regex.Match(stdout.ToString(), @"^\| ApplyStiffness \| \d+ \| ([0-9.]+) \| ([0-9.]+) \|", RegexOptions.Multiline);
            Assert.That(row.Success, Is.True, "the bench's ApplyStiffness row");
            double perRun = double.Parse(row.Groups[2].Value, CultureInfo.InvariantCulture) / double.Parse(row.Groups[1].Value, CultureInfo.InvariantCulture);
            Assert.That(output, Does.Contain($"warm starts: {2 * perRun:F3} ms (2 x ApplyStiffness {perRun:F3})"));
        }

        /// <summary>A log of gpu-figures.sh whose scenes stage printed a DFSPH table at 271k particles before the 1M bench:
        /// the estimate reads the 1M table, which is what it is about.</summary>
        [Test]
        public void ALogIsReadAtItsMostParticles()
        {
            var (exitCode, output, error) = Estimate("Headless/figures/gpu-h200-half-support-cells.txt", "5", "2", "2");
            Assert.That(exitCode, Is.EqualTo(0), error);
            Assert.That(output, Does.Contain("DFSPH at 1000482 particles"));
            Assert.That(output, Does.Contain("sub-step of 5 ms at 2 + 2 corrections: 10.072 ms GPU = 3.215 fixed + 1.027 warm starts"));
        }

        [TestCase(new[] { Profile, "5", "2" }, "usage: realtime-estimate.sh FILE SUBSTEP_MS DENSITY_ITERATIONS DIVERGENCE_ITERATIONS")]
        [TestCase(new[] { "Headless/figures/none.txt", "5", "2", "2" }, "FILE 'Headless/figures/none.txt' is not a file")]
        [TestCase(new[] { Profile, "0", "2", "2" }, "SUBSTEP_MS must be a number of milliseconds above 0 (was '0')")]
        [TestCase(new[] { Profile, "5", "1.5", "2" }, "DENSITY_ITERATIONS must be a number of corrections a sub-step, 2 or more")]
        [TestCase(new[] { Profile, "5", "2", "x" }, "DIVERGENCE_ITERATIONS must be a number of corrections a sub-step, 2 or more")]
        [TestCase(new[] { "Headless/figures/gpu-h200-pareto.txt", "5", "2", "2" }, "holds no DFSPH per-kernel table")]
        public void BadInputNamesTheArgumentAndItsRange(string[] arguments, string message)
        {
            var (exitCode, output, error) = Estimate(arguments);
            Assert.That(exitCode, Is.EqualTo(2));
            Assert.That(output, Is.Empty);
            Assert.That(error, Does.Contain(message));
        }
    }
}
