using System;
using System.IO;
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

        /// <summary>A fresh empty folder under the system temp folder.</summary>
        public static string ScratchFolder(string purpose)
        {
            string dir = Path.Combine(Path.GetTempPath(), "sphfluid-runner-tests", purpose + "-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            Directory.CreateDirectory(dir);
            return dir;
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
