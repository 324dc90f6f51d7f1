using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Scenes;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Tests.Runner
{
    /// <summary>
    /// Unity plays a scene whose camera script carries a field it no longer declares, or whose prop lost its script; the
    /// reader refused every such scene for the integrity check's problem, so a user's own scene ran in Unity and not
    /// here. A problem on what the fluid is read from still refuses it (<see cref="FluidDocuments"/>); the rest are a
    /// warning naming each line.
    /// </summary>
    public sealed class UnreadObjectTests
    {
        const string Scene = "OilAndWater";
        const string CameraScript = "--- !u!114 &1414005203"; // OrbitCamera, on the Main Camera
        const string Readout = "--- !u!114 &482617472"; // FluidReadout, on the Fluid's own GameObject
        const string OilBox = "--- !u!114 &287989891";
        const string OilObject = "--- !u!1 &305626396";
        const string Light = "--- !u!1 &1603977669";
        const string UnknownGuid = "0123456789abcdef0123456789abcdef";

        /// <summary>The scene, or <paramref name="text"/>, edited in the document that starts with <paramref name="header"/>
        /// (<see cref="RunnerPaths.EditDocument"/>).</summary>
        static string Edited(string header, string find, string replace, out int line, string? text = null) =>
            RunnerPaths.EditDocument(text ?? File.ReadAllText(RunnerPaths.Scene(Scene)), header + "\n", find, replace, out line);

        static string Write(string text)
        {
            string path = Path.Combine(RunnerPaths.ScratchFolder("unread-objects"), Scene + ".unity");
            File.WriteAllText(path, text);
            return path;
        }

        static string ScriptOf(string header) =>
            File.ReadAllText(RunnerPaths.Scene(Scene)).Split(header + "\n")[1].Split("guid: ")[1].Substring(0, 32);

        [Test]
        public void AStaleFieldOnTheCameraScriptIsAWarningAndTheSceneRuns()
        {
            string path = Write(Edited(CameraScript, "  maxPitch: 85\n", "  maxPitch: 85\n  oldYaw: 3\n", out int line));
            var stdout = new StringWriter();
            var stderr = new StringWriter();

            int code = Deadline.Within(60, () => Program.Run(new[] { "simulate", path, "--steps", "1", "--cpu-particles-scale", "0.1",
                "--out", RunnerPaths.ScratchFolder("unread-objects-out") }, stdout, stderr), "simulate with a stale camera field");

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stderr.ToString());
            Assert.That(stderr.ToString(), Does.Contain($"simulate: warning: {path}: the integrity check finds 1 problem(s) on objects the fluid is not read from; " +
                "Unity plays the scene with them (dropping what it cannot read), and so does this run:\n"));
            Assert.That(stderr.ToString(), Does.Contain($"  {path}:{line + 1}: MonoBehaviour &1414005203 (line 219) sets 'oldYaw', which "));
            Assert.That(stdout.ToString(), Does.Contain("done (WCSPH)"));
        }

        /// <summary>Bench and study open the scene as simulate does and print the same warning under their own name.</summary>
        [TestCase("bench", "--particles-scales", "0.1", "--warmup", "0", "--warmup-seconds", "0", "--steps", "1", "--skip-savings")]
        [TestCase("study", "--solvers", "wcsph", "--stiffness-factors", "1", "--particles-scales", "0.1", "--cfl", "0.3", "--seconds", "0.01")]
        public void BenchAndStudyWarnOfAStaleCameraFieldAndRun(string command, params string[] options)
        {
            string path = Write(Edited(CameraScript, "  maxPitch: 85\n", "  maxPitch: 85\n  oldYaw: 3\n", out int line));
            var stderr = new StringWriter();
            var args = new[] { command, path }.Concat(options).Concat(new[] { "--out", RunnerPaths.ScratchFolder("unread-objects-" + command) }).ToArray();

            int code = Deadline.Within(120, () => Program.Run(args, new StringWriter(), stderr), command + " with a stale camera field");

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stderr.ToString());
            Assert.That(stderr.ToString(), Does.Contain($"{command}: warning: {path}: the integrity check finds 1 problem(s) on objects the fluid is not read from; "));
            Assert.That(stderr.ToString(), Does.Contain($"  {path}:{line + 1}: MonoBehaviour &1414005203 (line 219) sets 'oldYaw', which "));
        }

        [TestCase(CameraScript)]
        [TestCase(Readout)]
        public void AMissingScriptOnAnotherObjectIsAWarning(string header)
        {
            string path = Write(Edited(header, "guid: " + ScriptOf(header), "guid: " + UnknownGuid, out int line));

            var scene = SceneLoader.Open(path, RunnerPaths.Project);

            Assert.That(scene.UnreadProblems, Does.Contain($"{path}:{line}: &{header.Split('&')[1]} MonoBehaviour.m_Script references guid {UnknownGuid}, which no .meta in the project has"));
            Assert.That(scene.Read().Description.SpawnBoxes.Count, Is.EqualTo(2), "the fluid is read as shipped");
        }

        [Test]
        public void TheShippedScenesHaveNoUnreadProblems()
        {
            foreach (string name in RunnerPaths.ShippedScenes)
                Assert.That(SceneLoader.Open(RunnerPaths.Scene(name), RunnerPaths.Project).UnreadProblems, Is.Null, name);
        }

        /// <summary>A SpawnBox whose script reference broke is dropped by Unity without a word: a MonoBehaviour whose script
        /// is missing and that carries a fluid component's field is read from, and refused.</summary>
        [Test]
        public void AMissingScriptThatCarriesAFluidComponentsFieldIsRefused()
        {
            string box = Write(Edited(OilBox, $"m_Script: {{fileID: 11500000, guid: {ScriptOf(OilBox)}, type: 3}}", "m_Script: {fileID: 0}", out int boxLine));
            Assert.That(() => SceneLoader.Open(box, RunnerPaths.Project), Throws.TypeOf<SceneException>().With.Message.Contains(
                $"{box}:{boxLine}: MonoBehaviour &287989891 (line {boxLine - 9}) has no m_Script (Missing Script)"), "m_Script is its document's tenth line");

            string camera = Edited(CameraScript, "guid: " + ScriptOf(CameraScript), "guid: " + UnknownGuid, out int cameraLine);
            string radius = Write(Edited(CameraScript, "  maxPitch: 85\n", "  maxPitch: 85\n  radius: 0.5\n", out _, camera));
            Assert.That(() => SceneLoader.Open(radius, RunnerPaths.Project), Throws.TypeOf<SceneException>().With.Message.Contains(
                $"{radius}:{cameraLine}: &1414005203 MonoBehaviour.m_Script references guid {UnknownGuid}"), "a SphereObstacle's field");
        }

        /// <summary>The GameObjects and Transforms from a fluid component up to the scene's root are read from (a parent
        /// places the box, its m_IsActive counts); the light is, once the Oil box hangs under it.</summary>
        [Test]
        public void AProblemOnTheWayUpFromAFluidComponentIsRefused()
        {
            const string tag = "  m_TagString: Untagged\n";
            const string undeclared = "  m_TagString: NoSuchTag\n";

            string onTheBox = Write(Edited(OilObject, tag, undeclared, out int boxLine));
            Assert.That(() => SceneLoader.Open(onTheBox, RunnerPaths.Project), Throws.TypeOf<SceneException>().With.Message.Contains(
                $"{onTheBox}:{boxLine}: ").And.Message.Contains("has tag 'NoSuchTag'"));

            string light = Edited(Light, tag, undeclared, out int lightLine);
            string alone = Write(light);
            Assert.That(SceneLoader.Open(alone, RunnerPaths.Project).UnreadProblems, Does.Contain($"{alone}:{lightLine}: ").And.Contain("has tag 'NoSuchTag'"));

            // The Oil box under the light: no root of its own, the light's child, its Transform's parent the light's.
            string parented = Edited("--- !u!1660057539 &9223372036854775807", "  - {fileID: 518734963}\n", "", out _, light);
            parented = Edited("--- !u!4 &721158848", "  m_Children: []\n", "  m_Children:\n  - {fileID: 518734963}\n", out _, parented);
            parented = Write(Edited("--- !u!4 &518734963", "  m_Father: {fileID: 0}\n", "  m_Father: {fileID: 721158848}\n", out _, parented));
            Assert.That(() => SceneLoader.Open(parented, RunnerPaths.Project), Throws.TypeOf<SceneException>().With.Message.Contains(
                $"{parented}:{lightLine}: ").And.Message.Contains("has tag 'NoSuchTag'").And.Message.Contains("(1 problem(s))"));
        }

        [Test]
        public void AWarningListsTenProblemsAndCountsTheRest()
        {
            string text = File.ReadAllText(RunnerPaths.Scene(Scene));
            text = Edited(CameraScript, "  maxPitch: 85\n", "  maxPitch: 85\n" + string.Concat(Enumerable.Range(0, 12).Select(i => $"  old{i}: {i}\n")), out _, text);
            string path = Write(text);

            string? warning = SceneLoader.Open(path, RunnerPaths.Project).UnreadProblems;

            Assert.That(warning, Does.Contain("finds 12 problem(s)"));
            Assert.That(warning, Does.Contain("sets 'old9'").And.Not.Contain("sets 'old10'"));
            Assert.That(warning, Does.EndWith("\n  ... and 2 more"));
        }

        /// <summary>Unity writes every serialized field of a component into the scene: the fields a missing script is
        /// matched against are exactly those the shipped scenes' fluid components carry.</summary>
        [Test]
        public void TheFluidComponentsFieldsAreThoseTheShippedScenesCarry()
        {
            var unityKeys = new HashSet<string> { "m_ObjectHideFlags", "m_CorrespondingSourceObject", "m_PrefabInstance", "m_PrefabAsset",
                "m_GameObject", "m_Enabled", "m_EditorHideFlags", "m_Script", "m_Name", "m_EditorClassIdentifier" };
            foreach (string component in RuntimeScripts.Components)
            {
                string guid = RunnerPaths.Project.ScriptGuid(component);
                var carried = RunnerPaths.ShippedScenes
                    .SelectMany(name => UnityYamlFile.Load(RunnerPaths.Scene(name)).Documents)
                    .Where(d => d.ScriptGuid == guid)
                    .Select(d => d.Root.Keys.Where(k => !unityKeys.Contains(k)).ToList())
                    .ToList();
                Assert.That(carried, Is.Not.Empty, component);
                foreach (var keys in carried)
                    Assert.That(keys, Is.EqualTo(RuntimeScripts.Fields[component]), component);
            }
        }
    }
}
