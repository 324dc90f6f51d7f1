using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;

namespace SphFluid.Tests.Runner
{
    /// <summary>The 60 Hz sizing of bench (issue #8, item 5): the particle count whose frame spends the GPU budget,
    /// interpolated between measured counts.</summary>
    public sealed class FrameSizingTests
    {
        /// <summary>Each shipped scene spawns no more particles than the H200 figures allow it on a GPU with a sixteenth of
        /// that card's memory bandwidth (the README's bandwidth bound, 16.7 times slower per particle), read from the
        /// committed bench output, so a scene cannot outgrow the measurement it was sized by. WCSPH only: DFSPH is not a
        /// 60 Hz solver at these sizes.</summary>
        [Test]
        public void EveryShippedSceneFitsItsBandwidthBound()
        {
            var bounds = BandwidthBounds(Path.Combine(GpuTestDevice.RepoRoot, "Headless", "figures", "gpu-h200-half-support-cells.txt"));

            foreach (string name in RunnerPaths.ShippedScenes.Where(n => n != "PlayModeTest"))
            {
                Assert.That(bounds.ContainsKey(name), Is.True, $"{name} has a bandwidth bound in gpu-h200-half-support-cells.txt");
                int count = SpawnLayout.TotalCount(SceneLoader.Load(RunnerPaths.Scene(name), RunnerPaths.Project).Description);
                Assert.That(count, Is.LessThanOrEqualTo(bounds[name]), name);
            }
        }

        static Dictionary<string, int> BandwidthBounds(string benchOutput)
        {
            var bounds = new Dictionary<string, int>();
            string? scene = null;
            foreach (string line in File.ReadLines(benchOutput))
            {
                var command = Regex.Match(line, @"^\$ (?:sphfluid-gpu/app/)?sphfluid bench Assets/FluidDemo/Scenes/(\w+)\.unity");
                if (command.Success) scene = line.Contains("--solver dfsph") ? null : command.Groups[1].Value;
                var bound = Regex.Match(line, @"^- on a GPU 16\.7 times slower per particle: about ([\d,]+) particles");
                if (bound.Success && scene != null)
                    bounds[scene] = int.Parse(bound.Groups[1].Value, NumberStyles.AllowThousands, CultureInfo.InvariantCulture);
            }
            return bounds;
        }

        [Test]
        public void APowerLawIsInterpolatedExactly()
        {
            // Frame time growing as N^(4/3) (N times the sub-steps, which grow as N^(1/3)): 2 ms at 1000, 2 * 8^(4/3) = 32 ms at 8000.
            var rows = new[] { (1000, 2.0), (8000, 32.0), (64000, 512.0) };

            var fit = FrameSizing.Largest(rows, 8.0);

            Assert.That(fit.BelowRange, Is.False);
            Assert.That(fit.AboveRange, Is.False);
            Assert.That(fit.Particles, Is.EqualTo(1000 * Math.Pow(4, 0.75)).Within(1e-6));
            Assert.That(fit.ToString(), Is.EqualTo("about 2,800 particles"));
        }

        [Test]
        public void ABudgetOutsideTheMeasuredCountsSaysSo()
        {
            var rows = new[] { (4000, 3.0), (16000, 15.0) };

            Assert.That(FrameSizing.Largest(rows, 1.0).ToString(), Is.EqualTo("fewer than 4,000 particles (the fewest measured)"));
            Assert.That(FrameSizing.Largest(rows, 100.0).ToString(), Is.EqualTo("more than 16,000 particles (the most measured)"));
        }

        [Test]
        public void ARowBeyondTheFirstOverBudgetIsNotConsulted()
        {
            // 16000 is over budget; a noisy 32000 that reads under it must not move the fit past 16000.
            var rows = new[] { (32000, 5.0), (4000, 2.0), (16000, 12.0) };

            var fit = FrameSizing.Largest(rows, 8.0);

            Assert.That(fit.Particles, Is.GreaterThan(4000).And.LessThan(16000));
        }

        [Test]
        public void ASubstepSplitsIntoAFixedPartAndAPartPerParticle()
        {
            // 0.1 ms of dispatches plus 2 microseconds per 1000 particles, exactly.
            var rows = new[] { (4000, 0.108), (16000, 0.132), (64000, 0.228) };

            var cost = FrameSizing.SplitCost(rows);

            Assert.That(cost.FixedMs, Is.EqualTo(0.1).Within(1e-9));
            Assert.That(cost.MsPerParticle, Is.EqualTo(2e-6).Within(1e-12));
            Assert.That(cost.SubstepMs(1000), Is.EqualTo(0.102).Within(1e-9));
        }

        [Test]
        public void ASplitNeverGoesBelowZero()
        {
            // Time falling with the count (noise) has no positive per-particle part; time that grows faster than the
            // count would need a negative fixed part. Neither is returned.
            Assert.That(FrameSizing.SplitCost(new[] { (1000, 0.2), (2000, 0.1) }).MsPerParticle, Is.EqualTo(0));
            var steep = FrameSizing.SplitCost(new[] { (1000, 0.1), (2000, 0.4) });
            Assert.That(steep.FixedMs, Is.EqualTo(0));
            Assert.That(steep.MsPerParticle, Is.GreaterThan(0));
            Assert.That(FrameSizing.SplitCost(new[] { (1000, 0.5) }).SubstepMs(1000), Is.EqualTo(0.5).Within(1e-12));
        }

        [Test]
        public void TheDefaultBudgetIsHalfASixtiethOfASecond()
        {
            Assert.That(FrameSizing.DefaultBudgetMs, Is.EqualTo(8.333).Within(0.001));
        }
    }
}
