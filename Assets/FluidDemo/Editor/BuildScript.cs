using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEditor.Build.Reporting;
using UnityEngine;

namespace SphFluid.Demo.Editor
{
    /// <summary>
    /// Builds the Windows 64-bit player of the scenes enabled in the build settings.
    /// Command line (no -nographics needed; -quit is fine here, unlike -runTests):
    /// <c>Unity -batchmode -quit -projectPath . -buildTarget Win64 -executeMethod SphFluid.Demo.Editor.BuildScript.BuildWindows64 [-outputPath Builds/Win64/SphFluid.exe] -logFile -</c>
    /// </summary>
    public static class BuildScript
    {
        public const string DefaultOutput = "Builds/Win64/SphFluid.exe";

        [MenuItem("SPH Fluid/Build Windows Player")]
        public static void BuildWindowsFromMenu() => Build(DefaultOutput);

        /// <summary>Entry point of <c>-executeMethod</c>: exits the editor with 0 on success, 1 on failure, in batch mode.</summary>
        public static void BuildWindows64()
        {
            bool ok = Build(ArgumentValue("-outputPath") ?? DefaultOutput);
            if (Application.isBatchMode) EditorApplication.Exit(ok ? 0 : 1);
        }

        /// <summary>The scenes a build includes: those enabled in EditorBuildSettings, in order.</summary>
        public static string[] EnabledScenes()
        {
            var scenes = new List<string>();
            foreach (EditorBuildSettingsScene scene in EditorBuildSettings.scenes)
                if (scene.enabled) scenes.Add(scene.path);
            return scenes.ToArray();
        }

        static bool Build(string output)
        {
            string[] scenes = EnabledScenes();
            if (scenes.Length == 0)
            {
                Debug.LogError("BuildScript: no scene is enabled in File > Build Settings; nothing to build");
                return false;
            }
            var options = new BuildPlayerOptions
            {
                scenes = scenes,
                locationPathName = output,
                target = BuildTarget.StandaloneWindows64,
                targetGroup = BuildTargetGroup.Standalone,
                options = BuildOptions.None,
            };
            BuildReport report = BuildPipeline.BuildPlayer(options);
            BuildSummary summary = report.summary;
            bool ok = summary.result == BuildResult.Succeeded;
            string line = $"BuildScript: {summary.result} building {scenes.Length} scene(s) to {output}: {summary.totalErrors} error(s), {summary.totalSize} bytes, {summary.totalTime.TotalSeconds:F0} s";
            if (ok) Debug.Log(line);
            else Debug.LogError(line);
            return ok;
        }

        static string ArgumentValue(string name)
        {
            string[] args = Environment.GetCommandLineArgs();
            int i = Array.IndexOf(args, name);
            return i >= 0 && i + 1 < args.Length ? args[i + 1] : null;
        }
    }
}
