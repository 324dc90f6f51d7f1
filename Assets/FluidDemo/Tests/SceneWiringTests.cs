using System.Collections.Generic;
using NUnit.Framework;
using SphFluid.Runtime;
using SphFluid.Simulation;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace SphFluid.Demo.Tests
{
    /// <summary>Every scene of the build opens with exactly one Fluid and a valid fluid scene (its shaders and material
    /// come from the package's resources asset, which FluidResourcesTests checks).</summary>
    public sealed class SceneWiringTests
    {
        public static IEnumerable<string> BuildScenes()
        {
            foreach (EditorBuildSettingsScene scene in EditorBuildSettings.scenes)
                if (scene.enabled) yield return scene.path;
        }

        [TearDown]
        public void CloseScenes() => EditorSceneManager.NewScene(NewSceneSetup.EmptyScene, NewSceneMode.Single);

        [Test]
        public void TheBuildListsScenes()
        {
            Assert.That(SphFluid.Demo.Editor.BuildScript.EnabledScenes(), Is.Not.Empty, "File > Build Settings has no enabled scene");
        }

        [TestCaseSource(nameof(BuildScenes))]
        public void SceneHasOneFluidAndItIsValid(string path)
        {
            Scene scene = EditorSceneManager.OpenScene(path, OpenSceneMode.Single);
            Assert.That(scene.IsValid(), Is.True, $"{path} does not open");

            Fluid[] simulators = Object.FindObjectsByType<Fluid>(FindObjectsInactive.Include, FindObjectsSortMode.None);
            Assert.That(simulators.Length, Is.EqualTo(1), $"{path}: Fluid components");
            Fluid simulator = simulators[0];

            var messages = new List<string>();
            foreach (ValidationError e in simulator.DescribeScene().Validate()) messages.Add(e.Message);
            Assert.That(messages, Is.Empty, $"{path}: the fluid scene is invalid");
        }
    }
}
