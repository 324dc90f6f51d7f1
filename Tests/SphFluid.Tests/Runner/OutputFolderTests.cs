using System;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Output;
using SphFluid.Headless.Runs;

namespace SphFluid.Tests.Runner
{
    /// <summary>The runner writes and deletes only the files it wrote itself (health issue: --out deleted every PNG).</summary>
    public sealed class OutputFolderTests
    {
        static int Simulate(string outDir, string seconds, out string stdout, out string stderr)
        {
            var o = new StringWriter();
            var e = new StringWriter();
            var options = SimulateOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--seconds", seconds, "--frames-every", "0.0166", "--out", outDir, "--quiet" });
            int code;
            try
            {
                code = new SimulateRun(options, o, e) { Device = GpuTestDevice.Shared, InteractiveProgress = false }.Execute();
            }
            catch (UsageException x)
            {
                e.WriteLine(x.Message);
                code = ExitCodes.BadArguments;
            }
            stdout = o.ToString();
            stderr = e.ToString();
            return code;
        }

        [Test]
        public void AUsersFilesInTheOutputFolderAreLeftAlone()
        {
            string dir = RunnerPaths.ScratchFolder("user-files");
            File.WriteAllText(Path.Combine(dir, "holiday.png"), "not a run's picture");
            File.WriteAllText(Path.Combine(dir, "notes.txt"), "mine");

            int code = Simulate(dir, "0.02", out string stdout, out string stderr);

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stdout + stderr);
            Assert.That(File.ReadAllText(Path.Combine(dir, "holiday.png")), Is.EqualTo("not a run's picture"));
            Assert.That(File.ReadAllText(Path.Combine(dir, "notes.txt")), Is.EqualTo("mine"));
            Assert.That(File.Exists(Path.Combine(dir, "frame_0000.png")), Is.True);
        }

        [Test]
        public void AFileWithARunnerNameThatNoRunWroteIsNeverOverwritten()
        {
            string dir = RunnerPaths.ScratchFolder("foreign-frame");
            File.WriteAllText(Path.Combine(dir, "frame_0000.png"), "someone else's");

            int code = Simulate(dir, "0.02", out _, out string stderr);

            Assert.That(code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(stderr, Does.Contain("--out '" + dir + "' already holds frame_0000.png that sphfluid did not write"));
            Assert.That(File.ReadAllText(Path.Combine(dir, "frame_0000.png")), Is.EqualTo("someone else's"));
            Assert.That(Directory.GetFiles(dir).Select(Path.GetFileName), Is.EquivalentTo(new[] { "frame_0000.png" }), "nothing written either");
        }

        [Test]
        public void ASecondRunRemovesTheStaleOutputsOfTheFirst()
        {
            string dir = RunnerPaths.ScratchFolder("rerun");
            Assert.That(Simulate(dir, "0.06", out _, out _), Is.EqualTo(ExitCodes.Ok));
            Assert.That(File.Exists(Path.Combine(dir, "frame_0003.png")), Is.True, "the first run wrote four frames");
            File.WriteAllText(Path.Combine(dir, "summary.txt"), "result: ok (stale)");

            Assert.That(Simulate(dir, "0.02", out _, out _), Is.EqualTo(ExitCodes.Ok));

            Assert.That(File.Exists(Path.Combine(dir, "frame_0003.png")), Is.False, "a shorter rerun leaves no frame of the old run");
            Assert.That(File.ReadAllText(Path.Combine(dir, "summary.txt")), Does.Not.Contain("stale"));
            Assert.That(File.ReadAllLines(Path.Combine(dir, OutputFolder.ManifestName)), Does.Contain("frame_0001.png").And.Not.Contain("frame_0003.png"));
        }

        [Test]
        public void AManifestCannotBeUsedToDeleteOtherFiles()
        {
            string dir = RunnerPaths.ScratchFolder("manifest");
            File.WriteAllText(Path.Combine(dir, "keep.png"), "mine");
            File.WriteAllText(Path.Combine(dir, OutputFolder.ManifestName), "keep.png\n../keep.png\nsummary.txt\n");

            OutputFolder.Claim(dir, "--out", "simulate").Dispose();

            Assert.That(File.Exists(Path.Combine(dir, "keep.png")), Is.True);
        }

        /// <summary>The manifest is the one file the run writes whatever the folder holds: as a link it would have had the run
        /// empty and then append to the file it names.</summary>
        [Test]
        public void AManifestThatIsALinkIsRefused_AndWhatItNamesIsLeftAlone()
        {
            string dir = RunnerPaths.ScratchFolder("manifest-link");
            string victim = Path.Combine(RunnerPaths.ScratchFolder("manifest-link-target"), "notes.txt");
            File.WriteAllText(victim, "mine");
            File.CreateSymbolicLink(Path.Combine(dir, OutputFolder.ManifestName), victim);

            var e = Assert.Throws<UsageException>(() => OutputFolder.Claim(dir, "--out", "simulate"));

            Assert.That(e!.Message, Is.EqualTo($"simulate: --out '{dir}' holds a .sphfluid-outputs that is a link or a folder, not the plain file " +
                "sphfluid writes; choose an empty or new folder (nothing was changed)"));
            Assert.That(File.ReadAllText(victim), Is.EqualTo("mine"));
        }

        [Test]
        public void AManifestThatIsAFolderIsRefused()
        {
            string dir = RunnerPaths.ScratchFolder("manifest-folder");
            Directory.CreateDirectory(Path.Combine(dir, OutputFolder.ManifestName));

            Assert.That(() => OutputFolder.Claim(dir, "--out", "simulate"), Throws.TypeOf<UsageException>().With.Message.Contains("is a link or a folder"));
        }

        [TestCase("")]
        [TestCase("   ")]
        public void AnEmptyOutputPathIsABadArgument(string path)
        {
            var e = Assert.Throws<UsageException>(() => OutputFolder.Claim(path, "--out", "simulate"));
            Assert.That(e.Message, Is.EqualTo("simulate: --out needs a folder path (was empty)"));
        }

        [Test]
        public void AnOutputPathThatIsAFileIsABadArgument()
        {
            string file = Path.Combine(RunnerPaths.ScratchFolder("file"), "out");
            File.WriteAllText(file, "x");
            var e = Assert.Throws<UsageException>(() => OutputFolder.Claim(file, "--out", "simulate"));
            Assert.That(e.Message, Does.Contain("is a file, not a folder"));
            Assert.That(File.ReadAllText(file), Is.EqualTo("x"));
        }

        /// <summary>A path under a file was refused with "Could not find a part of the path"; the message now names the file.</summary>
        [Test]
        public void AnOutputPathUnderAFileNamesTheFile()
        {
            string file = Path.Combine(RunnerPaths.ScratchFolder("under-file"), "scene.unity");
            File.WriteAllText(file, "x");
            string path = Path.Combine(file, "out", "deeper");
            var e = Assert.Throws<UsageException>(() => OutputFolder.Claim(path, "--out", "simulate"));
            Assert.That(e.Message, Is.EqualTo($"simulate: --out '{path}' lies under '{file}', which is a file, not a folder"));
            Assert.That(File.ReadAllText(file), Is.EqualTo("x"));
        }

        /// <summary>A folder of /proc answers a new file with "Could not find file", which read as if the folder were missing.</summary>
        [Test]
        public void AFolderInWhichNoFileCanBeMadeIsNamedSo()
        {
            if (!Directory.Exists("/proc/self")) Assert.Ignore("no /proc here");
            var e = Assert.Throws<UsageException>(() => OutputFolder.Claim("/proc/self", "--out", "simulate"));
            Assert.That(e.Message, Does.StartWith($"simulate: --out '/proc/self' is a folder in which no file can be made (making {OutputFolder.ManifestName} there failed: "));
            Assert.That(e.Message, Does.EndWith("'); give a folder on a disk (nothing was changed)"), "the system's message, without its full stop");
        }

        /// <summary>A link that loops (ln -s loop loop) was refused as "a file, not a folder"; it is a link.</summary>
        [Test]
        public void AnOutputPathThatIsALinkToNoFolderIsRefusedAsALink()
        {
            string dir = RunnerPaths.ScratchFolder("link-loop");
            string loop = Path.Combine(dir, "loop");
            File.CreateSymbolicLink(loop, "loop");
            string file = Path.Combine(dir, "file");
            File.WriteAllText(file, "x");
            string toFile = Path.Combine(dir, "to-file");
            File.CreateSymbolicLink(toFile, file);

            var e = Assert.Throws<UsageException>(() => OutputFolder.Claim(loop, "--out", "simulate"));
            Assert.That(e.Message, Is.EqualTo($"simulate: --out '{loop}' is a symbolic link to 'loop' that does not lead to a folder; give a folder or a new path (nothing was changed)"));
            e = Assert.Throws<UsageException>(() => OutputFolder.Claim(toFile, "--out", "simulate"));
            Assert.That(e.Message, Does.Contain($"'{toFile}' is a symbolic link to '{file}' that does not lead to a folder"));
            Assert.That(File.ReadAllText(file), Is.EqualTo("x"));
            Assert.That(Directory.EnumerateFileSystemEntries(dir).Count(), Is.EqualTo(3), "nothing was written beside them");
        }

        [Test]
        public void AFolderUnderARunnersFileNameIsRefusedBeforeTheRun()
        {
            string dir = RunnerPaths.ScratchFolder("folder-as-frame");
            Directory.CreateDirectory(Path.Combine(dir, "frame_0000.png"));
            File.WriteAllText(Path.Combine(dir, "notes.txt"), "mine");

            int code = Simulate(dir, "0.05", out _, out string stderr);

            Assert.That(code, Is.EqualTo(ExitCodes.BadArguments), stderr);
            Assert.That(stderr, Does.Contain($"--out '{dir}' holds a folder named frame_0000.png, where sphfluid writes a file; choose an empty or new folder (nothing was changed)"));
            Assert.That(Directory.EnumerateFileSystemEntries(dir).Select(Path.GetFileName).OrderBy(n => n), Is.EqualTo(new[] { "frame_0000.png", "notes.txt" }),
                "no diagnostics, no manifest: the run never started");
        }

        /// <summary>Two runs given one folder at once (two runs of one scene started together share its default --out) would each
        /// delete what the other wrote and leave a manifest that lists one run's files: the second is refused while the
        /// first holds the folder, and takes it once the first is done.</summary>
        [Test]
        public void AFolderARunHoldsIsRefusedToASecondUntilTheFirstEnds()
        {
            string dir = RunnerPaths.ScratchFolder("held");
            var first = OutputFolder.Claim(dir, "--out", "simulate");
            first.WriteText("summary.txt", "the first run's");

            var e = Assert.Throws<UsageException>(() => OutputFolder.Claim(dir, "--out", "bench"));
            Assert.That(e.Message, Is.EqualTo($"bench: --out '{dir}' is in use by another sphfluid run (it holds {OutputFolder.ManifestName} open); " +
                "give another folder, or wait for that run to end (nothing was changed)"));
            Assert.That(File.ReadAllText(Path.Combine(dir, "summary.txt")), Is.EqualTo("the first run's"));

            first.Dispose();
            using var second = OutputFolder.Claim(dir, "--out", "bench");
            Assert.That(File.Exists(Path.Combine(dir, "summary.txt")), Is.False, "the first run's outputs are the second's to replace");
        }

        /// <summary>A run that stopped before its first output (no Vulkan device, a refused environment variable) left the
        /// folders its --out named and an empty manifest behind. It now leaves only what was there before it.</summary>
        [Test]
        public void ARunThatWroteNothingLeavesNothingItMade()
        {
            string scratch = RunnerPaths.ScratchFolder("wrote-nothing");
            string made = Path.Combine(scratch, "a", "b");
            OutputFolder.Claim(made + Path.DirectorySeparatorChar, "--out", "simulate").Dispose();
            Assert.That(Directory.GetFileSystemEntries(scratch), Is.Empty, "the folders a and a/b the claim made, and its manifest");

            OutputFolder.Claim(scratch, "--out", "simulate").Dispose();
            Assert.That(Directory.Exists(scratch), Is.True, "a folder that was there before stays");
            Assert.That(Directory.GetFileSystemEntries(scratch), Is.Empty);

            using (var run = OutputFolder.Claim(made, "--out", "simulate")) run.WriteText("summary.txt", "written");
            Assert.That(Directory.GetFiles(made).Select(Path.GetFileName), Is.EquivalentTo(new[] { OutputFolder.ManifestName, "summary.txt" }));
            OutputFolder.Claim(made, "--out", "simulate").Dispose();
            Assert.That(Directory.GetFiles(made).Select(Path.GetFileName), Is.EquivalentTo(new[] { OutputFolder.ManifestName }),
                "a run that wrote nothing removes the earlier run's outputs, as any run does, and keeps the manifest it found");
        }

        /// <summary>A folder path a few characters short of the system's limit can be made, but not the manifest in it: the
        /// claim failed with the folders it had made for the path left behind (21 of them for a path of 4 085 characters).</summary>
        [Test]
        public void AClaimThatFailsAfterMakingItsFoldersLeavesNoneOfThem()
        {
            if (!OperatingSystem.IsLinux()) Assert.Ignore("the limit is Linux's PATH_MAX of 4 096 bytes");
            string scratch = RunnerPaths.ScratchFolder("path-limit");
            string path = scratch;
            while (4085 - path.Length > 202) path = Path.Combine(path, new string('d', 200));
            path = Path.Combine(path, new string('d', 4085 - path.Length - 1)); // at least one character: 2 to 202 remained
            Assert.That(path.Length, Is.EqualTo(4085));
            Assert.That(Path.Combine(path, OutputFolder.ManifestName).Length, Is.GreaterThan(4095), "the manifest's path is past the limit");

            var e = Assert.Throws<UsageException>(() => OutputFolder.Claim(path, "--out", "simulate"));
            Assert.That(e.Message, Does.StartWith($"simulate: --out '{path}' cannot be used as the output folder: "));
            Assert.That(Directory.GetFileSystemEntries(scratch), Is.Empty, "every folder the claim made for the path is removed");
        }

        [Test]
        public void AWriteThatFailsLeavesNoPartOfItsFile()
        {
            string dir = RunnerPaths.ScratchFolder("failed-write");
            var output = OutputFolder.Claim(dir, "--out", "test");
            string path = Path.Combine(dir, "frame_0000.png");

            // As a full disk fails a write part-way.
            var failure = Assert.Throws<IOException>(() => output.Write("frame_0000.png", file =>
            {
                file.Write(new byte[4096]);
                file.Flush();
                throw new IOException("No space left on device");
            })).OrFail("the failure");

            Assert.That(failure.Message, Is.EqualTo($"cannot write {path}: No space left on device; the part written was removed"));
            Assert.That(File.Exists(path), Is.False, "no truncated file is left to pass for an output");
            output.Dispose();
            Assert.That(File.ReadAllLines(Path.Combine(dir, OutputFolder.ManifestName)), Does.Contain("frame_0000.png"), "the name stays claimed");
        }

        /// <summary>Standard output that removes the run's folder once the run has printed its line for 0.05 s, as a user
        /// cleaning up, or a disk going away, would mid-run.</summary>
        sealed class FolderTakenAway : StringWriter
        {
            readonly string _dir;
            bool _taken;
            public FolderTakenAway(string dir) => _dir = dir;
            public override void Write(string? value)
            {
                base.Write(value);
                if (!_taken && ToString().Contains("t= 0.050 s"))
                {
                    _taken = true;
                    Directory.Delete(_dir, true);
                }
            }
            public override void WriteLine(string? value)
            {
                Write(value);
                Write(CoreNewLine);
            }
        }

        /// <summary>
        /// The command line's file-error exit, end to end: the folder goes mid-run, so the next file the run writes (a
        /// frame) cannot be made. The command stops with exit 1 and says which file it could not write, instead of an unexpected
        /// failure or a run that reports success without its outputs. (A full disk takes the same path; the writers'
        /// own cut-back on a full disk is <see cref="AWriteThatFailsLeavesNoPartOfItsFile"/> and DiagnosticsCsvColumnTests.)
        /// </summary>
        [Test]
        public void AFolderTakenAwayMidRunIsAFileErrorNamingTheFile()
        {
            string dir = Path.Combine(RunnerPaths.ScratchFolder("taken-away"), "out");
            var stdout = new FolderTakenAway(dir);
            var stderr = new StringWriter();

            int code = Program.Run(new[] { "simulate", RunnerPaths.Scene("PlayModeTest"), "--seconds", "0.2", "--frames-every", "0.05",
                "--diagnostics-every", "0.05", "--out", dir }, stdout, stderr);

            Assert.That(code, Is.EqualTo(ExitCodes.Failure), stdout.ToString() + stderr);
            Assert.That(stderr.ToString(), Does.Contain("sphfluid: file error, the command stopped: cannot write " + dir + Path.DirectorySeparatorChar + "frame_")
                .And.Contain("Could not find a part of the path").And.Not.Contain("the part written"), "nothing was made, so nothing is said to be left");
            Assert.That(stdout.ToString(), Does.Not.Contain("t= 0.100 s"), "the run stopped at the first write it could not make");
            Assert.That(stdout.ToString(), Does.Not.Contain("done ("), "no report of a finished run");
        }
    }
}
