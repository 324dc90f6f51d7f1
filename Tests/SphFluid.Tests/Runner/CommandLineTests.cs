using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SphFluid.Headless;
using SphFluid.Headless.Cli;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Runner
{
    public sealed class CommandLineTests
    {
        static int Run(out string stdout, out string stderr, params string[] args)
        {
            var o = new StringWriter();
            var e = new StringWriter();
            int code = Program.Run(args, o, e);
            stdout = o.ToString();
            stderr = e.ToString();
            return code;
        }

        [Test]
        public void NegativeSecondsIsABadArgumentNamingItsRange()
        {
            int code = Run(out _, out string err, "simulate", RunnerPaths.Scene("PlayModeTest"), "--seconds", "-1");
            Assert.That(code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain("--seconds must be in [0.0001, 3600] s (was -1)"));
        }

        [Test]
        public void AnUnknownFlagIsNamed()
        {
            int code = Run(out _, out string err, "simulate", RunnerPaths.Scene("PlayModeTest"), "--fast");
            Assert.That(code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain("unknown option --fast"));
            Assert.That(err, Does.Not.Contain("did you mean"), "--fast is near no option of simulate");
        }

        /// <summary>After "--" every token is an argument: a scene file whose name starts with a dash can be given there, and
        /// an option written after it is named as the argument it became, not as an unknown option.</summary>
        [Test]
        public void ASceneNamedWithADashGoesAfterTheDoubleDash()
        {
            foreach (string command in new[] { "simulate", "bench", "study" })
            {
                Assert.That(Run(out _, out string refused, command, "-take2.unity"), Is.EqualTo(ExitCodes.BadArguments));
                Assert.That(refused, Does.Contain($"{command}: unknown option -take2.unity; a scene file whose name starts with '-' goes after '--'"));

                Assert.That(Run(out _, out string late, command, "--", "-take2.unity", "--out", "x"), Is.EqualTo(ExitCodes.BadArguments));
                Assert.That(late, Does.Contain($"{command}: unexpected argument '--out' after '--'"));
            }
            Assert.That(SimulateOptions.Parse(new[] { "--seconds", "0.5", "--", "-take2.unity" }).ScenePath, Is.EqualTo("-take2.unity"));
            Assert.That(BenchOptions.Parse(new[] { "--", "--take2.unity" }).ScenePath, Is.EqualTo("--take2.unity"));
        }

        /// <summary>The commands spell alike options apart (simulate takes one --particles-scale and --solver, bench and
        /// study lists): the refusal names the spelling this command has, after the scene or before it.</summary>
        [TestCase("study", "--solver", "dfsph", "study: unknown option --solver; did you mean --solvers?")]
        [TestCase("study", "--particles-scale", "2", "study: unknown option --particles-scale; did you mean --particles-scales?")]
        [TestCase("bench", "--particles-scale", "2", "bench: unknown option --particles-scale; did you mean --particles-scales?")]
        [TestCase("simulate", "--particles-scales", "2", "simulate: unknown option --particles-scales; did you mean --particles-scale?")]
        [TestCase("simulate", "--SECONDS", "1", "simulate: unknown option --SECONDS; did you mean --seconds?")]
        public void AnUnknownOptionNamesTheNearestSpelling(string command, string option, string value, string message)
        {
            foreach (string[] args in new[]
            {
                new[] { command, RunnerPaths.Scene("PlayModeTest"), option, value },
                new[] { command, option, value, RunnerPaths.Scene("PlayModeTest") },
            })
            {
                int code = Run(out _, out string err, args);
                Assert.That(code, Is.EqualTo(ExitCodes.BadArguments), string.Join(" ", args));
                Assert.That(err, Does.Contain(message), string.Join(" ", args));
            }
        }

        [TestCase("--steps", "0", "--steps must be in [1, 1000000] (was 0)")]
        [TestCase("--seconds", "1e-6", "--seconds must be in [0.0001, 3600] s (was 1E-06)")]
        [TestCase("--frames-every", "abc", "--frames-every must be a number in [0.0001, 3600] s (was 'abc')")]
        [TestCase("--particles-scale", "5000", "--particles-scale must be in [0.01, 4096] (was 5000)")]
        [TestCase("--cpu-particles-scale", "2", "--cpu-particles-scale must be in [0.01, 1] (was 2)")]
        [TestCase("--out", null, "option --out needs a value")]
        public void OutOfRangeValuesAreRefusedWithTheirRange(string option, string? value, string message)
        {
            var args = value == null
                ? new[] { "simulate", RunnerPaths.Scene("PlayModeTest"), option }
                : new[] { "simulate", RunnerPaths.Scene("PlayModeTest"), option, value };
            int code = Run(out _, out string err, args);
            Assert.That(code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain(message));
        }

        /// <summary>Every option that takes a value, written last without one, is refused by name: the options with a
        /// default (--seconds, --particles-scale, bench's --steps) once ran on that default instead. The scene does not
        /// exist, so an option the parse let through fails on the scene (exit 3) and never runs a simulation.</summary>
        [TestCase("simulate")]
        [TestCase("bench")]
        [TestCase("study")]
        public void EveryValueOptionWithoutItsValueIsRefused(string command)
        {
            Run(out string help, out _, command, "--help");
            var options = new List<string>();
            foreach (Match m in Regex.Matches(help, @"^\s+(--[a-z-]+) <", RegexOptions.Multiline))
                options.Add(m.Groups[1].Value);
            Assert.That(options, Has.Member("--out"), help);
            foreach (string option in options)
            {
                int code = Run(out _, out string err, command, "no-such-scene.unity", option);
                Assert.That(code, Is.EqualTo(ExitCodes.BadArguments), $"{command} {option}: {err}");
                Assert.That(err, Does.Contain($"option {option} needs a value"), $"{command} {option}");
            }
        }

        [Test]
        public void SecondsAndStepsTogetherAreRefused()
        {
            int code = Run(out _, out string err, "simulate", "x.unity", "--seconds", "1", "--steps", "3");
            Assert.That(code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain("either --seconds or --steps"));
        }

        [Test]
        public void BenchRefusesTooFewParticlesAndAMissingScene()
        {
            Assert.That(Run(out _, out string err, "bench", RunnerPaths.Scene("PlayModeTest"), "--particles", "10"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain("--particles must be in [64, 16777216] (was 10)"));
            Assert.That(Run(out _, out err, "bench"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain("the scene file argument is missing"));
        }

        [Test]
        public void BenchTakesParticleScalesOrCountsButNotBoth()
        {
            var options = BenchOptions.Parse(new[] { "x.unity", "--particles-scales", "1", "4", "--slower-gpus", "3", "16.7", "--frame-budget", "4" });
            Assert.That(options.ParticleScales, Is.EqualTo(new[] { 1.0, 4.0 }));
            Assert.That(options.SlowerGpus, Is.EqualTo(new[] { 3.0, 16.7 }));
            Assert.That(options.FrameBudgetMs, Is.EqualTo(4.0));
            Assert.That(BenchOptions.Parse(new[] { "x.unity" }).SlowerGpus, Is.Empty);

            Assert.That(Run(out _, out string err, "bench", "x.unity", "--particles", "1000", "--particles-scales", "2"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain("bench: give either --particles or --particles-scales, not both"));
            Assert.That(Run(out _, out err, "bench", "x.unity", "--slower-gpus", "0.5"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain("--slower-gpus must be in [1, 1000]"));
            Assert.That(Run(out _, out err, "bench", "x.unity", "--particles-scales", "5000"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain("--particles-scales must be in [0.01, 4096]"));
        }

        [TestCase("bench", "--particles-scales", "1", "1.0", "--particles-scales lists 1.0 twice")]
        [TestCase("bench", "--particles", "4000,4000", "", "--particles lists 4000 twice")]
        [TestCase("study", "--cfl", "0.3", "0.2,0.3", "--cfl lists 0.3 twice")]
        [TestCase("study", "--solver-iterations", "jacobi", "Jacobi", "--solver-iterations lists Jacobi twice")]
        public void AListOptionRefusesAValueGivenTwice(string command, string option, string first, string second, string message)
        {
            // Each value is a configuration run: given twice, it ran twice and the study's table held the row twice.
            var args = new List<string> { command, "x.unity", option, first };
            if (second.Length > 0) args.Add(second);
            Assert.That(Run(out _, out string err, args.ToArray()), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain($"{command}: {message}; give each value once"));
        }

        [Test]
        public void ARepeatedListOptionAddsItsValues()
        {
            var options = StudyOptions.Parse(new[] { "x.unity", "--cfl", "0.3", "--cfl", "0.2" });
            Assert.That(options.CflNumbers, Is.EqualTo(new[] { 0.3, 0.2 }));
        }

        [Test]
        public void AnUnknownCommandAndNoArgumentsAreBadArguments()
        {
            Assert.That(Run(out _, out string err, "render"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.StartWith("sphfluid has no command 'render' (commands: simulate, bench, study; see sphfluid --help)"));
            Assert.That(Run(out _, out err, "--seconds", "1"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.StartWith("sphfluid has no option --seconds of its own; a command's options follow the command"));
            Assert.That(Run(out _, out err, "--seconds", "1", "simulate", "x.unity"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.StartWith("sphfluid has no option --seconds of its own"), "simulate has --seconds: it stood before the command");
            Assert.That(Run(out _, out err, "--", "simulate", "x.unity"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.StartWith("sphfluid has no command before '--', which makes every later token an argument, 'simulate' too; " +
                "write the command first (sphfluid simulate [options] -- scene.unity)"));
            Assert.That(Run(out _, out err, "--", "render"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.StartWith("sphfluid has no command 'render'"), "not a command's name: the same answer as without '--'");
            Assert.That(Run(out _, out _), Is.EqualTo(ExitCodes.BadArguments));
        }

        [Test]
        public void HelpIsPrintedForEachCommand()
        {
            Assert.That(Run(out string top, out _, "--help"), Is.EqualTo(ExitCodes.Ok));
            Assert.That(top, Does.Contain("sphfluid simulate"));
            Assert.That(Run(out string simulate, out _, "simulate", "--help"), Is.EqualTo(ExitCodes.Ok));
            Assert.That(simulate, Does.Contain("--frames-every"));
            Assert.That(Run(out string bench, out _, "bench", "--help"), Is.EqualTo(ExitCodes.Ok));
            Assert.That(bench, Does.Contain("--particles"));
        }

        [Test]
        public void AMissingSceneFileIsASceneError()
        {
            int code = Run(out _, out string err, "simulate", "/nonexistent/Nothing.unity");
            Assert.That(code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(err, Does.Contain("Nothing.unity: no such scene file"));
        }

        [Test]
        public void ABadSceneValueGivesExitCodeThree()
        {
            string path = RunnerPaths.EditedScene("PlayModeTest", "RestDensity: 1000", "RestDensity: -3");
            int code = Run(out _, out string err, "simulate", path, "--seconds", "0.01");
            Assert.That(code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(err, Does.Contain("SpawnBox.spawn.Phase.RestDensity"));
        }

        /// <summary>An option of one value given twice was refused in the library's words, "Option '--out' expects a single
        /// argument but 2 were provided", which do not say which were given; a list option may still be repeated.</summary>
        [Test]
        public void AnOptionOfOneValueGivenTwiceNamesTheValues()
        {
            var study = Assert.Throws<UsageException>(() => StudyOptions.Parse(new[] { "x.unity", "--out", "a", "--out", "b" }));
            Assert.That(study.Message, Is.EqualTo("study: --out was given 2 times ('a', 'b'); give it once"));
            var simulate = Assert.Throws<UsageException>(() => SimulateOptions.Parse(new[] { "x.unity", "--seconds", "1", "--seconds=2", "--seconds", "3" }));
            Assert.That(simulate.Message, Is.EqualTo("simulate: --seconds was given 3 times ('1', '2', '3'); give it once"));
            Assert.That(BenchOptions.Parse(new[] { "x.unity", "--particles", "1000", "--particles", "2000" }).Particles, Is.EqualTo(new[] { 1000, 2000 }));
        }

        /// <summary>A help request holds no options: reading them beside a mistake threw the library's
        /// InvalidOperationException, where the program shows the help.</summary>
        [Test]
        public void ParsingAHelpRequestForItsOptionsIsRefusedByName()
        {
            foreach (var args in new[] { new[] { "x.unity", "--help" }, new[] { "x.unity", "--seconds", "-1", "--help" }, new[] { "--help", "--bogus" } })
            {
                var error = Assert.Throws<UsageException>(() => SimulateOptions.Parse(args), string.Join(" ", args));
                Assert.That(error.Message, Is.EqualTo("simulate: --help asks for the help text, which has no options to read (see sphfluid simulate --help)"));
            }
            Assert.That(Run(out string help, out _, "simulate", "--seconds", "-1", "--help"), Is.EqualTo(ExitCodes.Ok));
            Assert.That(help, Does.Contain("simulate the scene's fluid"));
        }

        [Test]
        public void OptionsAcceptTheEqualsFormAndFlagsRefuseAValue()
        {
            var options = SimulateOptions.Parse(new[] { "x.unity", "--seconds=2.5", "--top-view" });
            Assert.That(options.Seconds, Is.EqualTo(2.5));
            Assert.That(options.TopView, Is.True);
            Assert.That(options.FrameCount, Is.EqualTo(150));
            var error = Assert.Throws<UsageException>(() => SimulateOptions.Parse(new[] { "x.unity", "--top-view=yes" }));
            Assert.That(error.Message, Does.Contain("option --top-view takes no value"));
            Assert.That(BenchOptions.Parse(new[] { "x.unity", "--particles", "1000,2000", "4000" }).Particles, Is.EqualTo(new[] { 1000, 2000, 4000 }));
            // The help switch is the root's; given a value it showed the help as if it had none.
            Assert.That(Run(out _, out string help, "bench", "--help=all"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(help, Does.Contain("bench: option --help takes no value (was 'all')"));
            Assert.That(Run(out _, out string rootHelp, "--help=all"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(rootHelp, Does.Contain("sphfluid refuses a value for --help, which takes none (was 'all')"));
            // Past "--" a token that reads as a switch with a value is an argument (here, the scene file's name).
            Assert.That(SimulateOptions.Parse(new[] { "--", "--top-view=1.unity" }).ScenePath, Is.EqualTo("--top-view=1.unity"));
        }

        [Test]
        public void ADeviceNameNoAdapterHasIsABadArgument()
        {
            int code = Run(out _, out string err, "simulate", RunnerPaths.Scene("PlayModeTest"), "--seconds", "0.01", "--device", "NoSuchAdapter");
            if (code == ExitCodes.Failure && err.Contains("no Vulkan device")) Assert.Ignore("No Vulkan driver here: " + err);
            Assert.That(code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Match(@"simulate: --device 'NoSuchAdapter' matches no Vulkan adapter \(adapters: [^)]+"));
            Assert.That(err, Does.Not.Contain("SPHFLUID_VULKAN_DEVICE"), "the argument named it, not the environment");
        }

        /// <summary>Named by the environment, a name no adapter has was answered with "install Mesa's lavapipe", on a
        /// machine that had it: the message now names the variable and the adapters there are.</summary>
        [Test]
        public void AnEnvironmentDeviceNameNoAdapterHasNamesTheVariableAndTheAdapters()
        {
            string? before = Environment.GetEnvironmentVariable("SPHFLUID_VULKAN_DEVICE");
            int code;
            string err;
            try
            {
                Environment.SetEnvironmentVariable("SPHFLUID_VULKAN_DEVICE", "NoSuchAdapter");
                code = Run(out _, out err, "simulate", RunnerPaths.Scene("PlayModeTest"), "--seconds", "0.01", "--out", RunnerPaths.ScratchFolder("no-adapter"));
            }
            finally
            {
                Environment.SetEnvironmentVariable("SPHFLUID_VULKAN_DEVICE", before);
            }
            if (!err.Contains("adapters: ")) Assert.Ignore("No Vulkan driver here: " + err);
            Assert.That(code, Is.EqualTo(ExitCodes.Failure));
            Assert.That(err, Does.Match(@"^sphfluid: no Vulkan device: SPHFLUID_VULKAN_DEVICE 'NoSuchAdapter' matches no Vulkan adapter \(adapters: [^;]+; unset it, or pass --device\)$"));
        }

        /// <summary>SPHFLUID_VULKAN_MAP_BUFFERS took every value but "0" for on, so "off" or "false" ran the mapped path a
        /// discrete-GPU rehearsal meant to avoid, without a word. Now only 0, 1, empty or unset are taken; anything else is a
        /// bad invocation that names the variable, what each value does and what it held, and nothing runs.</summary>
        [Test]
        public void AMapBuffersSwitchOtherThan0Or1IsRefusedByName()
        {
            string? before = Environment.GetEnvironmentVariable(VulkanComputeOptions.MapBuffersVariable);
            string folder = RunnerPaths.ScratchFolder("map-buffers-switch");
            int code;
            string err;
            try
            {
                Environment.SetEnvironmentVariable(VulkanComputeOptions.MapBuffersVariable, "off");
                code = Run(out _, out err, "simulate", RunnerPaths.Scene("PlayModeTest"), "--seconds", "0.01", "--out", folder);
                Assert.That(() => new VulkanComputeOptions(), Throws.ArgumentException);
                Environment.SetEnvironmentVariable(VulkanComputeOptions.MapBuffersVariable, "0");
                Assert.That(new VulkanComputeOptions().MapDeviceBuffers, Is.False);
                Environment.SetEnvironmentVariable(VulkanComputeOptions.MapBuffersVariable, "1");
                Assert.That(new VulkanComputeOptions().MapDeviceBuffers, Is.True);
            }
            finally
            {
                Environment.SetEnvironmentVariable(VulkanComputeOptions.MapBuffersVariable, before);
            }
            Assert.That(code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Is.EqualTo("sphfluid simulate: SPHFLUID_VULKAN_MAP_BUFFERS must be 0 (stage every buffer through host copies, " +
                "as a discrete GPU does) or 1 (map device-local memory where the device has it), or unset (was 'off')" + Environment.NewLine));
            Assert.That(Directory.Exists(folder) ? Directory.GetFileSystemEntries(folder) : Array.Empty<string>(), Is.Empty, "nothing was written");
        }

        /// <summary>A blank adapter name or folder is refused at parsing: the blank --device ran on the best adapter as if
        /// the option had been left out.</summary>
        [Test]
        public void ABlankDeviceOrFolderIsRefusedByName()
        {
            var empty = Assert.Throws<UsageException>(() => SimulateOptions.Parse(new[] { "x.unity", "--device", "" }));
            Assert.That(empty.Message, Is.EqualTo("simulate: option --device needs a NAME (was empty)"));
            var blank = Assert.Throws<UsageException>(() => BenchOptions.Parse(new[] { "x.unity", "--device", " " }));
            Assert.That(blank.Message, Is.EqualTo("bench: option --device needs a NAME (was blank)"));
            var folder = Assert.Throws<UsageException>(() => StudyOptions.Parse(new[] { "x.unity", "--out", "" }));
            Assert.That(folder.Message, Is.EqualTo("study: option --out needs a DIR (was empty)"));
        }

        [Test]
        public void LavapipeNamesMesasCpuAdapterWhoseNameIsLlvmpipe()
        {
            Assert.That(VulkanComputeDevice.NameMatches("llvmpipe (LLVM 15.0.6, 256 bits)", "lavapipe"), Is.True);
            Assert.That(VulkanComputeDevice.NameMatches("llvmpipe (LLVM 15.0.6, 256 bits)", "LLVMpipe"), Is.True);
            Assert.That(VulkanComputeDevice.NameMatches("NVIDIA H100 80GB HBM3", "lavapipe"), Is.False);
            Assert.That(VulkanComputeDevice.NameMatches("NVIDIA H100 80GB HBM3", "h100"), Is.True);

            int code = Run(out _, out string err, "simulate", RunnerPaths.Scene("PlayModeTest"), "--steps", "1", "--device", "lavapipe",
                "--out", RunnerPaths.ScratchFolder("lavapipe"), "--quiet");
            if (code == ExitCodes.BadArguments && err.Contains("matches no Vulkan adapter")) Assert.Ignore("No lavapipe here: " + err);
            Assert.That(code, Is.EqualTo(ExitCodes.Ok), err);
        }
    }
}
