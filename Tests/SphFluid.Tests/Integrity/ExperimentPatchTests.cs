using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace SphFluid.Tests.Integrity
{
    /// <summary>
    /// The variants measured and left out (Headless/experiments, run by Headless/tools/experiment.sh): the README,
    /// Headless/docs and the comments quote their figures, so each must still say how to make them and still apply to
    /// the commit it names.
    /// </summary>
    public sealed class ExperimentPatchTests
    {
        static string RepoRoot => GpuTestDevice.RepoRoot;

        static IEnumerable<string> Patches() =>
            Directory.GetFiles(Path.Combine(RepoRoot, "Headless", "experiments"), "*.patch")
                .Select(path => Path.GetFileNameWithoutExtension(path)!)
                .OrderBy(name => name, StringComparer.Ordinal);

        static string PatchPath(string name) => Path.Combine(RepoRoot, "Headless", "experiments", name + ".patch");

        static string? Field(string patch, string name) =>
            File.ReadLines(patch).TakeWhile(line => !line.StartsWith("diff --git ", StringComparison.Ordinal))
                .Where(line => line.StartsWith(name + ": ", StringComparison.Ordinal))
                .Select(line => line.Substring(name.Length + 2).Trim())
                .FirstOrDefault();

        [Test]
        public void There_are_experiments() => Assert.That(Patches().Count(), Is.GreaterThan(0));

        [TestCaseSource(nameof(Patches))]
        public void Each_says_what_it_changed_where_it_was_measured_and_what_prints_its_figures(string name)
        {
            string patch = PatchPath(name);
            Assert.That(Field(patch, "Experiment"), Is.Not.Null.And.Not.Empty, "Experiment:");
            Assert.That(Field(patch, "Base"), Does.Match("^[0-9a-f]{40}$"), "Base: a full commit hash");
            Assert.That(Field(patch, "Run"), Is.Not.Null.And.Not.Empty, "Run:");
            string? show = Field(patch, "Show");
            Assert.That(show, Is.Not.Null.And.Not.Empty, "Show:");
            Assert.That(() => new Regex(show!), Throws.Nothing, "Show: a regular expression");
            Assert.That(File.ReadAllText(patch), Does.Contain("\ndiff --git "), "a diff follows the header");
        }

        /// <summary>Checked against the Base commit's tree in a scratch index, so nothing in the checkout is touched; a clone
        /// without that history cannot check it.</summary>
        [TestCaseSource(nameof(Patches))]
        public void Each_applies_to_the_commit_it_names(string name)
        {
            string patch = PatchPath(name);
            string baseCommit = Field(patch, "Base") ?? "";
            Assume.That(Git(null, "cat-file", "-e", baseCommit + "^{commit}").Code, Is.EqualTo(0),
                $"{baseCommit} is not in this clone's history");
            string index = Path.Combine(Path.GetTempPath(), "sphfluid-experiment-" + Guid.NewGuid().ToString("N"));
            try
            {
                var read = Git(index, "read-tree", baseCommit);
                Assert.That(read.Code, Is.EqualTo(0), read.Output);
                var check = Git(index, "apply", "--cached", "--check", patch);
                Assert.That(check.Code, Is.EqualTo(0), $"{name}.patch does not apply to {baseCommit}: {check.Output}");
            }
            finally
            {
                File.Delete(index);
            }
        }

        /// <summary>The experiments Headless/gpu-kit.sh packs when EXPERIMENTS is not set: it applies each to HEAD, so one
        /// that no longer applies stops the kit on the day a GPU is lent (cached-pair-gradients did, once the neighbour
        /// search took lanes).</summary>
        static IEnumerable<string> KitDefaults()
        {
            string kit = File.ReadAllText(Path.Combine(RepoRoot, "Headless", "gpu-kit.sh"));
            var defaults = Regex.Match(kit, @"\$\{EXPERIMENTS-([^}]*)\}");
            Assert.That(defaults.Success, Is.True, "gpu-kit.sh's ${EXPERIMENTS-...} default");
            return defaults.Groups[1].Value.Split(' ', StringSplitOptions.RemoveEmptyEntries).Select(entry => entry.Split(':')[0]);
        }

        [Test]
        public void The_gpu_kits_default_experiments_apply_to_head()
        {
            var names = KitDefaults().ToList();
            Assert.That(names, Is.Not.Empty);
            string index = Path.Combine(Path.GetTempPath(), "sphfluid-experiment-" + Guid.NewGuid().ToString("N"));
            try
            {
                var read = Git(index, "read-tree", "HEAD");
                Assert.That(read.Code, Is.EqualTo(0), read.Output);
                foreach (string name in names)
                {
                    Assert.That(File.Exists(PatchPath(name)), Is.True, $"gpu-kit.sh's default names {name}, but {name}.patch is missing");
                    var check = Git(index, "apply", "--cached", "--check", PatchPath(name));
                    Assert.That(check.Code, Is.EqualTo(0), $"gpu-kit.sh's default experiment {name}.patch does not apply to HEAD: {check.Output}");
                }
            }
            finally
            {
                File.Delete(index);
            }
        }

        static (int Code, string Output) Git(string? indexFile, params string[] arguments)
        {
            var start = new ProcessStartInfo("git") { WorkingDirectory = RepoRoot, RedirectStandardOutput = true, RedirectStandardError = true };
            foreach (string argument in arguments) start.ArgumentList.Add(argument);
            if (indexFile != null) start.Environment["GIT_INDEX_FILE"] = indexFile;
            using var git = Process.Start(start)!;
            var error = git.StandardError.ReadToEndAsync();
            string output = git.StandardOutput.ReadToEnd();
            git.WaitForExit();
            return (git.ExitCode, output + error.Result);
        }
    }
}
