using System;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using NUnit.Framework;
using SphFluid.UnityFiles.Assets;

namespace SphFluid.Tests.Runner
{
    /// <summary>The shipped scenes and a scratch folder for the runner tests.</summary>
    static class RunnerPaths
    {
        public static readonly string[] ShippedScenes = { "OilAndWater", "DamBreak", "Splash", "RotatingContainer", "SphereWake", "RestingTank", "PlayModeTest" };

        public static string Scene(string name) => Path.Combine(GpuTestDevice.RepoRoot, "Assets", "FluidDemo", "Scenes", name + ".unity");

        static UnityProject? _project;

        public static UnityProject Project => _project ?? (_project = new UnityProject(GpuTestDevice.RepoRoot));

        // This test process's scratch folders, all in one folder of their own that the suite's teardown removes: they were
        // left in the system temp folder, 1 500 of them (69 MB) after a few dozen runs of the suite.
        static readonly string ScratchRoot = Path.Combine(Path.GetTempPath(), "sphfluid-runner-tests", "run-" + Guid.NewGuid().ToString("N").Substring(0, 8));

        /// <summary>A fresh empty folder under the system temp folder, removed with the others after the last test.</summary>
        public static string ScratchFolder(string purpose)
        {
            string dir = Path.Combine(ScratchRoot, purpose + "-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            Directory.CreateDirectory(dir);
            return dir;
        }

        [DllImport("libc", SetLastError = true)]
        static extern int mkfifo(string path, uint mode);

        /// <summary>A named pipe at <paramref name="path"/>, in place of any file there: whoever opens it blocks until a writer
        /// comes, so it is how the tests show that a file is judged before it is opened. The test is ignored where there is
        /// no mkfifo.</summary>
        public static void Pipe(string path)
        {
            File.Delete(path);
            if (!RuntimeInformation.IsOSPlatform(OSPlatform.Linux) || mkfifo(path, Convert.ToUInt32("600", 8)) != 0)
                Assert.Ignore("mkfifo is not available here");
        }

        /// <summary>Removes every scratch folder of this test process (the links among them, not what they lead to), and
        /// their parent where no other test process still has its own there; what cannot be removed is named on the
        /// progress output.</summary>
        public static void RemoveScratch()
        {
            try
            {
                if (Directory.Exists(ScratchRoot)) Directory.Delete(ScratchRoot, recursive: true);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                NUnit.Framework.TestContext.Progress.WriteLine($"the runner tests' scratch folder {ScratchRoot} was not removed: {e.Message}");
                return;
            }
            try
            {
                Directory.Delete(Path.GetDirectoryName(ScratchRoot)!, recursive: false);
            }
            catch (IOException)
            {
                // Another test process's scratch folders, or one left by a suite that stopped early: kept.
            }
        }

        /// <summary>A copy of the repository's Unity project (its Assets, Packages and ProjectSettings) in a scratch folder,
        /// for a test that changes the project around a scene; returns the copy's root.</summary>
        public static string ProjectCopy(string purpose)
        {
            string root = ScratchFolder(purpose);
            foreach (string folder in new[] { "Assets", "Packages", "ProjectSettings" })
                foreach (string file in Directory.EnumerateFiles(Path.Combine(Project.Root, folder), "*", SearchOption.AllDirectories))
                {
                    string copy = Path.Combine(root, Path.GetRelativePath(Project.Root, file));
                    Directory.CreateDirectory(Path.GetDirectoryName(copy)!);
                    File.Copy(file, copy);
                }
            return root;
        }

        /// <summary><paramref name="text"/> (a scene's) with <paramref name="find"/> replaced inside the one document that
        /// starts with <paramref name="header"/>, its last line included; <paramref name="line"/> is the 1-based line of the
        /// edit. Fails the test when the document does not hold <paramref name="find"/>.</summary>
        public static string EditDocument(string text, string header, string find, string replace, out int line)
        {
            int start = text.IndexOf(header, StringComparison.Ordinal);
            Assert.That(start, Is.GreaterThanOrEqualTo(0), $"no document '{header}'");
            int end = text.IndexOf("\n--- ", start + 1, StringComparison.Ordinal);
            end = end < 0 ? text.Length : end + 1; // the file's last document, else up to the next header's line
            int at = text.IndexOf(find, start, end - start, StringComparison.Ordinal);
            Assert.That(at, Is.GreaterThan(0), $"no '{find}' in '{header}'");
            line = text.Take(at).Count(c => c == '\n') + 1;
            return text.Substring(0, at) + replace + text.Substring(at + find.Length);
        }

        /// <summary>A copy of a shipped scene with one piece of text replaced, written to a scratch folder.</summary>
        public static string EditedScene(string name, string find, string replace) => EditedScene(name, (find, replace));

        /// <summary>A copy of a shipped scene with several pieces of text replaced, written to a scratch folder.</summary>
        public static string EditedScene(string name, params (string Find, string Replace)[] edits)
        {
            string text = File.ReadAllText(Scene(name));
            foreach (var (find, replace) in edits)
            {
                if (!text.Contains(find)) throw new InvalidOperationException($"{name}.unity has no '{find}' to replace");
                text = text.Replace(find, replace);
            }
            string path = Path.Combine(ScratchFolder("scene"), name + ".unity");
            File.WriteAllText(path, text);
            return path;
        }
    }
}
