using System;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using NUnit.Framework;
using SphFluid.Headless.Scenes;
using SphFluid.UnityFiles.Assets;

namespace SphFluid.Tests.Runner
{
    /// <summary>
    /// The scene reader reads the project around the scene (each asset's .meta, the scripts the scene uses) and opened
    /// every such file as it came: a pipe in place of one blocked the run for good, before a line was printed. A file of
    /// length 0 is now read as empty without being opened. Each test waits a bounded time, so that a regression fails
    /// instead of hanging the suite.
    /// </summary>
    public sealed class ProjectPipeTests
    {
        static readonly TimeSpan Patience = TimeSpan.FromSeconds(60);

        /// <summary>Opens the copy's OilAndWater on another thread; fails if it has not ended within <see cref="Patience"/>.</summary>
        static Task<SceneLoader.CheckedScene> OpenWithin(string root)
        {
            var open = Task.Run(() => SceneLoader.Open(Path.Combine(root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity"), new UnityProject(root)));
            Assert.That(Task.WaitAny(new Task[] { open }, Patience), Is.EqualTo(0), $"the read had not ended after {Patience.TotalSeconds} s");
            return open;
        }

        [Test]
        public void APipeInPlaceOfAnAssetsMetaDoesNotBlockTheRead()
        {
            string root = RunnerPaths.ProjectCopy("pipe");
            string asset = Path.Combine(root, "Assets", "FluidDemo", "Notes.txt");
            File.WriteAllText(asset, "notes\n");
            RunnerPaths.Pipe(asset + ".meta");

            var scene = OpenWithin(root).Result.Read();

            Assert.That(scene.Description.Phases().Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water", "Oil" }));
        }

        /// <summary>The scene's scripts are read to check that each declares its class: a pipe reads as an empty script,
        /// which declares none. The camera's OrbitCamera is no fluid component, so the problem is a warning naming it.</summary>
        [Test]
        public void APipeInPlaceOfAScriptTheSceneUsesIsReportedNotWaitedOn()
        {
            string root = RunnerPaths.ProjectCopy("pipe");
            RunnerPaths.Pipe(Path.Combine(root, "Assets", "FluidDemo", "Scripts", "OrbitCamera.cs"));

            var scene = OpenWithin(root).Result;

            Assert.That(scene.UnreadProblems, Does.Contain("OrbitCamera"));
        }
    }
}
