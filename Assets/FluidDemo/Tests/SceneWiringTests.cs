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
    /// <summary>Every scene of the build opens with exactly one fully wired Fluid and a valid fluid scene.</summary>
    public sealed class SceneWiringTests
    {
        static readonly string[][] Shaders =
        {
            new[] { "solverShader", "FluidSolver" },
            new[] { "diagnosticsShader", "FluidDiagnostics" },
            new[] { "sortShader", "ParticleSort" },
            new[] { "prefixSumShader", "PrefixSum" },
        };

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
        public void SceneHasOneWiredSimulatorAndAValidFluid(string path)
        {
            Scene scene = EditorSceneManager.OpenScene(path, OpenSceneMode.Single);
            Assert.That(scene.IsValid(), Is.True, $"{path} does not open");

            Fluid[] simulators = Object.FindObjectsByType<Fluid>(FindObjectsInactive.Include, FindObjectsSortMode.None);
            Assert.That(simulators.Length, Is.EqualTo(1), $"{path}: Fluid components");
            Fluid simulator = simulators[0];

            var serialized = new SerializedObject(simulator);
            foreach (string[] shader in Shaders)
            {
                Object value = serialized.FindProperty(shader[0]).objectReferenceValue;
                Assert.That(value, Is.Not.Null, $"{path}: Fluid.{shader[0]} is not assigned");
                Assert.That(value.name, Is.EqualTo(shader[1]), $"{path}: Fluid.{shader[0]}");
            }
            Object material = serialized.FindProperty("particleMaterial").objectReferenceValue;
            Assert.That(material, Is.Not.Null, $"{path}: Fluid.particleMaterial is not assigned");
            Object universal = serialized.FindProperty("universalParticleShader").objectReferenceValue;
            Assert.That(universal, Is.Not.Null, $"{path}: Fluid.universalParticleShader is not assigned (the particles would not draw in URP)");
            Assert.That(universal.name, Is.EqualTo("SphFluid/ParticlesUniversal"), $"{path}: Fluid.universalParticleShader");

            var messages = new List<string>();
            foreach (ValidationError e in simulator.DescribeScene().Validate()) messages.Add(e.Message);
            Assert.That(messages, Is.Empty, $"{path}: the fluid scene is invalid");
        }
    }
}
