using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.UnityFiles.Integrity;

namespace SphFluid.Tests.Integrity
{
    /// <summary>Each check fires on a tree broken in exactly one way, and stays quiet on the intact tree.</summary>
    public sealed class AssetIntegrityCheckTests
    {
        [Test]
        public void Intact_synthetic_project_has_no_problems()
        {
            using (var project = new SyntheticProject())
            {
                var problems = AssetIntegrity.Check(project.Root);
                Assert.That(problems.Count, Is.Zero, AssetIntegrity.Describe(problems));
            }
        }

        [Test]
        public void Asmdef_reference_by_guid_resolves_to_the_project_asmdef()
        {
            using (var project = new SyntheticProject())
            {
                project.Replace(SyntheticProject.EditorAsmdefPath, "\"Game.Runtime\"",
                    "\"GUID:" + project.GuidOf(SyntheticProject.RuntimeAsmdefPath) + "\", \"GUID:27619889b8ba8c24980f49ee34dbb44a\"");
                var problems = AssetIntegrity.Check(project.Root);
                Assert.That(problems.Count, Is.Zero, AssetIntegrity.Describe(problems));
            }
        }

        /// <summary>An embedded package as Unity would see it: a folder under Packages/ with package.json and its .meta.</summary>
        static void AddPackage(SyntheticProject project, string folder, string name, string version, string dependencies)
        {
            string json = "{\n  \"name\": \"" + name + "\",\n  \"version\": \"" + version + "\",\n  \"unity\": \"2022.3\",\n  \"dependencies\": {" + dependencies + "}\n}\n";
            project.Write($"Packages/{folder}/package.json", json);
            project.Write($"Packages/{folder}/package.json.meta", "fileFormatVersion: 2\nguid: " + Guid.NewGuid().ToString("N") + "\nTextScriptImporter:\n  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n");
        }

        const string SamplePackage = "com.game.water";
        const string SampleFolder = "Packages/com.game.water/Samples~/Pond";
        const string SampleScene = SampleFolder + "/Pond.unity";
        const string SampleAsset = SampleFolder + "/Settings/PondURP.asset";
        const string UrpAssetScript = "bf2edee5c58d82540a51f03df9d42094";

        /// <summary>
        /// An embedded package with one sample under Samples~, as Package Manager offers it: the sample folder has no
        /// .meta, everything in it has one; its scene uses the project's script, its URP asset uses URP's script, and
        /// the project's manifest does not list URP (the sample lands in projects that have it).
        /// </summary>
        static void AddPackageWithSample(SyntheticProject project, string? samplesJson = null)
        {
            samplesJson ??= "[ { \"displayName\": \"Pond\", \"description\": \"A pond.\", \"path\": \"Samples~/Pond\" } ]";
            string json = "{\n  \"name\": \"" + SamplePackage + "\",\n  \"version\": \"1.0.0\",\n  \"unity\": \"2022.3\",\n  \"samples\": " + samplesJson + "\n}\n";
            project.Write("Packages/" + SamplePackage + "/package.json", json);
            project.Write("Packages/" + SamplePackage + "/package.json.meta", "fileFormatVersion: 2\nguid: " + Guid.NewGuid().ToString("N") + "\n" + TextImporter);
            project.Write(SampleScene, project.Read(SyntheticProject.ScenePath));
            project.Write(SampleScene + ".meta", "fileFormatVersion: 2\nguid: " + Guid.NewGuid().ToString("N") + "\n" + SyntheticProject.DefaultImporter);
            project.Write(SampleFolder + "/Settings.meta", "fileFormatVersion: 2\nguid: " + Guid.NewGuid().ToString("N") + "\n" + SyntheticProject.FolderImporter);
            project.Write(SampleAsset,
                "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!114 &11400000\nMonoBehaviour:\n  m_ObjectHideFlags: 0\n  m_GameObject: {fileID: 0}\n" +
                "  m_Enabled: 1\n  m_EditorHideFlags: 0\n  m_Script: {fileID: 11500000, guid: " + UrpAssetScript + ", type: 3}\n  m_Name: PondURP\n" +
                "  m_EditorClassIdentifier: \n  k_AssetVersion: 11\n  m_RequireOpaqueTexture: 1\n");
            project.Write(SampleAsset + ".meta", "fileFormatVersion: 2\nguid: " + Guid.NewGuid().ToString("N") + "\n" + AssetImporter);
        }

        const string TextImporter = "TextScriptImporter:\n  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n";
        const string AssetImporter = "NativeFormatImporter:\n  externalObjects: {}\n  mainObjectFileID: 11400000\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n";

        [Test]
        public void A_package_sample_is_checked_like_assets_and_may_use_a_package_the_project_lacks()
        {
            using (var project = new SyntheticProject())
            {
                AddPackageWithSample(project);
                var problems = AssetIntegrity.Check(project.Root);
                Assert.That(problems.Count, Is.Zero, AssetIntegrity.Describe(problems));
            }
        }

        [Test]
        public void A_runtime_asmdef_may_reference_an_optional_package_it_names_in_version_defines()
        {
            using (var project = new SyntheticProject())
            {
                project.Replace(SyntheticProject.RuntimeAsmdefPath, "\"Unity.InputSystem\"\n    ]",
                    "\"Unity.InputSystem\",\n        \"Unity.RenderPipelines.Core.Runtime\",\n        \"Unity.RenderPipelines.Universal.Runtime\"\n    ],\n" +
                    "    \"versionDefines\": [\n        {\n            \"name\": \"com.unity.render-pipelines.universal\",\n            \"expression\": \"14.0.0\",\n" +
                    "            \"define\": \"GAME_URP\"\n        }\n    ]");
                var problems = AssetIntegrity.Check(project.Root);
                Assert.That(problems.Count, Is.Zero, AssetIntegrity.Describe(problems));
            }
        }

        const string ShaderImporter = "ShaderImporter:\n  externalObjects: {}\n  defaultTextures: []\n  nonModifiableTextures: []\n  preprocessorOverride: 0\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n";

        const string InputActionsImporter = "ScriptedImporter:\n  internalIDToNameTable: []\n  externalObjects: {}\n  serializedVersion: 2\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n" +
            "  script: {fileID: 11500000, guid: 8404be70184654265930450def6a9037, type: 3}\n  generateWrapperCode: 0\n  wrapperCodePath: \n  wrapperClassName: \n  wrapperCodeNamespace: \n";

        const string InputActions = "{\n  \"name\": \"Controls\",\n  \"maps\": [\n    {\n      \"name\": \"Fluid\",\n      \"id\": \"5c1d3a52-8a4e-4a8e-9d5e-0f6b1f0c9a01\",\n" +
            "      \"actions\": [\n        { \"name\": \"Pause\", \"type\": \"Button\", \"id\": \"5c1d3a52-8a4e-4a8e-9d5e-0f6b1f0c9a02\", \"expectedControlType\": \"Button\" }\n      ],\n" +
            "      \"bindings\": [\n        { \"name\": \"\", \"id\": \"5c1d3a52-8a4e-4a8e-9d5e-0f6b1f0c9a03\", \"path\": \"<Keyboard>/space\", \"action\": \"Pause\", \"isComposite\": false, \"isPartOfComposite\": false }\n      ]\n    }\n  ],\n  \"controlSchemes\": []\n}\n";

        [Test]
        public void Valid_input_actions_and_a_shader_used_by_a_scene_material_pass()
        {
            using (var project = new SyntheticProject())
            {
                project.AddAsset("Assets/Game/Controls.inputactions", InputActions, InputActionsImporter);
                project.AddAsset("Assets/Game/Shaders/Dots.shader", "Shader \"Game/Dots\"\n{\n    SubShader { Pass { } }\n}\n", ShaderImporter);
                project.AddAsset("Assets/Game/Dots.mat",
                    "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!21 &2100000\nMaterial:\n  serializedVersion: 8\n  m_Name: Dots\n" +
                    "  m_Shader: {fileID: 4800000, guid: " + project.GuidOf("Assets/Game/Shaders/Dots.shader") + ", type: 3}\n",
                    "NativeFormatImporter:\n  externalObjects: {}\n  mainObjectFileID: 2100000\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n");
                project.Replace(SyntheticProject.ScriptPath, "public float rate = 2f;", "public float rate = 2f;\n        [SerializeField] Material dots;\n        Shader Dots => Shader.Find(\"Game/Dots\");");
                project.Replace(SyntheticProject.ScenePath, "  rate: 2\n", "  rate: 2\n  dots: {fileID: 2100000, guid: " + project.GuidOf("Assets/Game/Dots.mat") + ", type: 2}\n");
                var problems = AssetIntegrity.Check(project.Root);
                Assert.That(problems.Count, Is.Zero, AssetIntegrity.Describe(problems));
            }
        }

        public sealed class Breakage
        {
            public Breakage(string name, Action<SyntheticProject> damage, string path, string message)
            {
                Name = name;
                Damage = damage;
                Path = path;
                Message = message;
            }

            public string Name { get; }
            public Action<SyntheticProject> Damage { get; }
            public string Path { get; }
            public string Message { get; }
            public override string ToString() => Name;
        }

        static IEnumerable<TestCaseData> Breakages()
        {
            const string scene = SyntheticProject.ScenePath;
            const string script = SyntheticProject.ScriptPath;
            yield return Case("missing meta", p => p.Delete(SyntheticProject.ShaderPath + ".meta"),
                SyntheticProject.ShaderPath, "has no .meta");
            yield return Case("missing folder meta", p => Directory.CreateDirectory(p.Abs("Assets/Game/Empty")),
                "Assets/Game/Empty", "has no .meta");
            yield return Case("orphan meta", p => File.Move(p.Abs(SyntheticProject.ShaderPath), p.Abs("Assets/Game/Shaders/Renamed.compute")),
                SyntheticProject.ShaderPath + ".meta", "orphan .meta");
            yield return Case("duplicate guid", p => p.Replace(SyntheticProject.ShaderPath + ".meta", p.GuidOf(SyntheticProject.ShaderPath), p.GuidOf(script)),
                "", "duplicate guid " );
            yield return Case("guid not lowercase hex", p => p.Replace(script + ".meta", p.GuidOf(script), p.GuidOf(script).ToUpperInvariant()),
                script + ".meta", "not 32 lowercase hex");
            yield return Case("guid too short", p => p.Replace(script + ".meta", p.GuidOf(script), p.GuidOf(script).Substring(1)),
                script + ".meta", "not 32 lowercase hex");
            yield return Case("template guid", p => p.Replace(script + ".meta", p.GuidOf(script), "9fc0d4010bbf28b4594072e72b8655ab"),
                script + ".meta", "belongs to a Unity package");
            yield return Case("wrong importer", p => p.Replace(SyntheticProject.ShaderPath + ".meta", "ComputeShaderImporter", "ShaderImporter"),
                SyntheticProject.ShaderPath + ".meta", "imported by ComputeShaderImporter");
            yield return Case("unresolved script guid", p => p.Replace(scene, p.GuidOf(script), Guid.NewGuid().ToString("N")),
                scene, "no .meta in the project has");
            yield return Case("class name differs from file name", p => p.Replace(script, "class FluidEmitter", "class FluidSpout"),
                scene, "declares no class named 'FluidEmitter'");
            yield return Case("script is not a MonoBehaviour", p => p.Replace(script, ": MonoBehaviour", ": IDisposable"),
                scene, "no MonoBehaviour/ScriptableObject");
            yield return Case("script in an Editor-only assembly", p => p.Replace(scene, p.GuidOf(script), p.GuidOf(SyntheticProject.EditorScriptPath)),
                scene, "Editor-only assembly");
            yield return Case("wrong main fileID for a compute shader", p => p.Replace(scene, "fileID: 7200000", "fileID: 4800000"),
                scene, "main object is 7200000");
            yield return Case("wrong type for a compute shader", p => p.Replace(scene, "type: 3}\n  rate", "type: 2}\n  rate"),
                scene, "takes type 3");
            yield return Case("dangling local reference", p => p.Replace(scene, "m_Father: {fileID: 101}", "m_Father: {fileID: 999}"),
                scene, "not in this file");
            yield return Case("unresolved asmdef reference", p => p.Replace(SyntheticProject.RuntimeAsmdefPath, "\"Unity.InputSystem\"", "\"Unity.Physics.Missing\""),
                SyntheticProject.RuntimeAsmdefPath, "resolves to no asmdef");
            yield return Case("unresolved asmdef GUID reference", p => p.Replace(SyntheticProject.EditorAsmdefPath, "\"Game.Runtime\"", "\"GUID:" + Guid.NewGuid().ToString("N") + "\""),
                SyntheticProject.EditorAsmdefPath, "matches no asmdef .meta");
            yield return Case("duplicate asmdef name", p => p.Replace(SyntheticProject.EditorAsmdefPath, "\"name\": \"Game.Editor\"", "\"name\": \"Game.Runtime\""),
                "", "is also used by");
            yield return Case("asmdef JSON does not parse", p => p.Replace(SyntheticProject.RuntimeAsmdefPath, "\"Unity.InputSystem\"\n", "\"Unity.InputSystem\",\n"),
                SyntheticProject.RuntimeAsmdefPath, "does not parse");
            yield return Case("runtime asmdef references the editor", p => p.Replace(SyntheticProject.RuntimeAsmdefPath, "\"Unity.InputSystem\"", "\"Game.Editor\""),
                SyntheticProject.RuntimeAsmdefPath, "references Editor-only 'Game.Editor'");
            yield return Case("scene component with broken back-reference", p => p.Replace(scene, "SphereCollider:\n  m_GameObject: {fileID: 200}", "SphereCollider:\n  m_GameObject: {fileID: 100}"),
                scene, "whose m_GameObject is");
            yield return Case("scene child not listed by its parent", p => p.Replace(scene, "m_Children:\n  - {fileID: 201}", "m_Children: []"),
                scene, "does not list it in m_Children");
            yield return Case("scene root missing from SceneRoots", p => p.Replace(scene, "m_Father: {fileID: 101}", "m_Father: {fileID: 0}"),
                scene, "missing from SceneRoots");
            yield return Case("scene object is its own parent", p => p.Replace(scene, "  - {fileID: 201}\n  m_Father: {fileID: 0}", "  - {fileID: 201}\n  m_Father: {fileID: 101}"),
                scene, "is its own parent");
            yield return Case("scene objects are each other's parent", p => p.Replace(scene, "  - {fileID: 201}\n  m_Father: {fileID: 0}", "  - {fileID: 201}\n  m_Father: {fileID: 201}"),
                scene, "form a parent cycle through Transform.m_Father");
            yield return Case("scene class id and type name disagree", p => p.Replace(scene, "--- !u!135 &202", "--- !u!65 &202"),
                scene, "is class 65 (BoxCollider)");
            yield return Case("scene duplicate anchor", p => p.Replace(scene, "--- !u!135 &202", "--- !u!135 &201"),
                scene, "anchor &201");
            yield return Case("scene YAML merge marker", p => p.Replace(scene, "  rate: 2\n", "  rate: 2\n<<<<<<< HEAD\n"),
                scene, "Unity would refuse");
            yield return Case("manifest misses a package", p => p.Replace("Packages/manifest.json", "    \"com.unity.ugui\": \"1.0.0\",\n", ""),
                "Packages/manifest.json", "does not name com.unity.ugui");
            yield return Case("manifest does not parse", p => p.Replace("Packages/manifest.json", "\"dependencies\": {", "\"dependencies\" {"),
                "Packages/manifest.json", "does not parse");
            yield return Case("embedded package named unlike its folder", p => AddPackage(p, "com.game.water", "com.game.Water", "1.0.0", ""),
                "Packages/com.game.water/package.json", "\"name\" must be a lower-case reverse-domain name");
            yield return Case("embedded package without a semantic version", p => AddPackage(p, "com.game.water", "com.game.water", "1.0", ""),
                "Packages/com.game.water/package.json", "\"version\" must be a semantic version");
            yield return Case("embedded package dependency the manifest lacks", p => AddPackage(p, "com.game.water", "com.game.water", "1.0.0", "\"com.unity.splines\": \"2.4.0\""),
                "Packages/com.game.water/package.json", "dependency 'com.unity.splines' is not in Packages/manifest.json");
            yield return Case("embedded package dependency at another version", p => AddPackage(p, "com.game.water", "com.game.water", "1.0.0", "\"com.unity.ugui\": \"2.0.0\""),
                "Packages/com.game.water/package.json", "differs from Packages/manifest.json's 1.0.0");
            yield return Case("testable that is neither dependency nor embedded", p => p.Replace("Packages/manifest.json", "\"1.0.0\"\n  }\n}", "\"1.0.0\"\n  },\n  \"testables\": [\"com.game.water\"]\n}"),
                "Packages/manifest.json", "testable 'com.game.water' is neither a dependency nor an embedded package");
            yield return Case("build settings scene guid mismatch", p => p.Replace("ProjectSettings/EditorBuildSettings.asset", p.GuidOf(scene), Guid.NewGuid().ToString("N")),
                "ProjectSettings/EditorBuildSettings.asset", "but its .meta has");
            yield return Case("build settings scene missing", p => p.Replace("ProjectSettings/EditorBuildSettings.asset", "Main.unity", "Gone.unity"),
                "ProjectSettings/EditorBuildSettings.asset", "does not exist");
            yield return Case("legacy input handler", p => p.Replace("ProjectSettings/ProjectSettings.asset", "activeInputHandler: 1", "activeInputHandler: 0"),
                "ProjectSettings/ProjectSettings.asset", "activeInputHandler must be 1");
            yield return Case("settings class id wrong", p => p.Replace("ProjectSettings/EditorSettings.asset", "--- !u!159 &1", "--- !u!129 &1"),
                "ProjectSettings/EditorSettings.asset", "must be '--- !u!159 &1'");
            yield return Case("undeclared tag", p => p.Replace(scene, "m_Name: Ball\n", "m_Name: Ball\n  m_TagString: Splashy\n"),
                scene, "tag 'Splashy'");
            yield return Case("unnamed layer", p => p.Replace(scene, "m_Layer: 0\n  m_Name: Ball", "m_Layer: 9\n  m_Name: Ball"),
                scene, "layer 9");
            yield return Case("layer that is no integer", p => p.Replace(scene, "m_Layer: 0\n  m_Name: Ball", "m_Layer: 1e30\n  m_Name: Ball"),
                scene, "m_Layer must be an integer in 0..31 (was '1e30')");
            yield return Case("layer past a 32-bit integer", p => p.Replace(scene, "m_Layer: 0\n  m_Name: Ball", "m_Layer: 2147483648\n  m_Name: Ball"),
                scene, "has layer 2147483648; layers are 0..31");
            yield return Case("active flag that is no bool", p => p.Replace(scene, "m_Name: Ball\n  m_IsActive: 1", "m_Name: Ball\n  m_IsActive: 2"),
                scene, "GameObject 'Ball' &200 m_IsActive must be 0 or 1 (was '2')");
            yield return Case("enabled flag that is no bool", p => p.Replace(scene, "m_Enabled: 1\n  m_Radius", "m_Enabled: null\n  m_Radius"),
                scene, "SphereCollider &202 m_Enabled must be 0 or 1 (was 'null')");
            yield return Case("legacy input module with Input System only", p => p.Replace(scene, p.GuidOf(script), "4f231c4fb786f3946a6b90b886c48677"),
                scene, "StandaloneInputModule");
            yield return Case("package object without its package", p =>
                {
                    p.Replace(scene, p.GuidOf(script), "76c392e42b5098c458856cdf6ecaaaa1");
                    p.Replace("Packages/manifest.json", "    \"com.unity.ugui\": \"1.0.0\",\n", "");
                },
                scene, "needs com.unity.ugui");
            yield return Case("shader found by name but never included", p =>
                {
                    p.AddAsset("Assets/Game/Shaders/Dots.shader", "Shader \"Game/Dots\"\n{\n    SubShader { Pass { } }\n}\n", ShaderImporter);
                    p.Replace(script, "public float rate = 2f;", "public float rate = 2f;\n        Shader Dots => Shader.Find(\"Game/Dots\");");
                },
                script, "Shader.Find(\"Game/Dots\")");
            yield return Case("input binding for an unknown action", p => p.AddAsset("Assets/Game/Controls.inputactions",
                    InputActions.Replace("\"action\": \"Pause\"", "\"action\": \"Freeze\""), InputActionsImporter),
                "Assets/Game/Controls.inputactions", "unknown action 'Freeze'");
            yield return Case("input actions not JSON", p => p.AddAsset("Assets/Game/Controls.inputactions", "{ \"maps\": [", InputActionsImporter),
                "Assets/Game/Controls.inputactions", "does not parse as JSON");
            yield return Case("input actions importer missing", p => p.AddAsset("Assets/Game/Controls.inputactions", InputActions, SyntheticProject.DefaultImporter),
                "Assets/Game/Controls.inputactions.meta", "imported by ScriptedImporter");
            yield return Case("scene sets a field the script does not declare", p => p.Replace(scene, "  rate: 2\n", "  rtae: 2\n"),
                scene, "sets 'rtae'");
            yield return Case("legacy Input class with Input System only", p => p.Replace(script, "public float rate = 2f;", "public float rate = 2f;\n        bool Fire => Input.GetKey(KeyCode.Space);"),
                script, "legacy Input Manager ('Input.GetKey')");
            yield return Case("sample path that is no folder", p => AddPackageWithSample(p,
                    "[ { \"displayName\": \"Pond\", \"path\": \"Samples~/Pond\" }, { \"displayName\": \"Lake\", \"path\": \"Samples~/Lake\" } ]"),
                "Packages/com.game.water/package.json", "'Samples~/Lake', which is no folder in the package");
            yield return Case("sample path outside Samples~", p => AddPackageWithSample(p,
                    "[ { \"displayName\": \"Pond\", \"path\": \"Samples~/Pond\" }, { \"displayName\": \"Lake\", \"path\": \"Lake\" } ]"),
                "Packages/com.game.water/package.json", "must be a folder under Samples~/");
            yield return Case("sample without a display name", p => AddPackageWithSample(p, "[ { \"path\": \"Samples~/Pond\" } ]"),
                "Packages/com.game.water/package.json", "has no \"displayName\"");
            yield return Case("undeclared folder under Samples~", p =>
                {
                    AddPackageWithSample(p);
                    p.Write("Packages/com.game.water/Samples~/Lake/Lake.unity", p.Read(SampleScene));
                },
                "Packages/com.game.water/Samples~/Lake", "no \"samples\" entry of package.json names it");
            yield return Case("sample file without a meta", p =>
                {
                    AddPackageWithSample(p);
                    p.Delete(SampleAsset + ".meta");
                },
                SampleAsset, "has no .meta");
            yield return Case("sample scene with an unresolved guid", p =>
                {
                    AddPackageWithSample(p);
                    p.Replace(SampleScene, p.GuidOf(script), Guid.NewGuid().ToString("N"));
                },
                SampleScene, "no .meta in the project has");
            yield return Case("sample scene with a broken back-reference", p =>
                {
                    AddPackageWithSample(p);
                    p.Replace(SampleScene, "SphereCollider:\n  m_GameObject: {fileID: 200}", "SphereCollider:\n  m_GameObject: {fileID: 100}");
                },
                SampleScene, "whose m_GameObject is");
            yield return Case("sample YAML merge marker", p =>
                {
                    AddPackageWithSample(p);
                    p.Replace(SampleAsset, "  m_RequireOpaqueTexture: 1\n", "<<<<<<< HEAD\n  m_RequireOpaqueTexture: 1\n");
                },
                SampleAsset, "Unity would refuse");
            yield return Case("meta beside Samples~", p =>
                {
                    AddPackageWithSample(p);
                    p.Write("Packages/com.game.water/Samples~.meta", "fileFormatVersion: 2\nguid: " + Guid.NewGuid().ToString("N") + "\n" + SyntheticProject.FolderImporter);
                },
                "Packages/com.game.water/Samples~.meta", "takes no .meta");
            yield return Case("URP object used by an asset outside a sample without URP", p =>
                    p.AddAsset("Assets/Game/PondURP.asset", "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!114 &11400000\nMonoBehaviour:\n" +
                        "  m_Script: {fileID: 11500000, guid: " + UrpAssetScript + ", type: 3}\n  m_Name: PondURP\n", AssetImporter),
                "Assets/Game/PondURP.asset", "needs com.unity.render-pipelines.universal");
            yield return Case("URP assembly without URP or a version define", p =>
                    p.Replace(SyntheticProject.RuntimeAsmdefPath, "\"Unity.InputSystem\"\n", "\"Unity.InputSystem\",\n        \"Unity.RenderPipelines.Universal.Runtime\"\n"),
                SyntheticProject.RuntimeAsmdefPath, "needs package com.unity.render-pipelines.universal");
            yield return Case("version define that is no symbol", p =>
                    p.Replace(SyntheticProject.RuntimeAsmdefPath, "    ]\n}", "    ],\n    \"versionDefines\": [ { \"name\": \"com.unity.render-pipelines.universal\", \"expression\": \"14.0.0\", \"define\": \"GAME-URP\" } ]\n}"),
                SyntheticProject.RuntimeAsmdefPath, "defines 'GAME-URP', which is no C# symbol");
            yield return Case("version define with a malformed range", p =>
                    p.Replace(SyntheticProject.RuntimeAsmdefPath, "    ]\n}", "    ],\n    \"versionDefines\": [ { \"name\": \"com.unity.render-pipelines.universal\", \"expression\": \"[14.0\", \"define\": \"GAME_URP\" } ]\n}"),
                SyntheticProject.RuntimeAsmdefPath, "no version or version range");
            yield return Case("project asset claiming a URP guid", p => p.Replace(script + ".meta", p.GuidOf(script), UrpAssetScript),
                script + ".meta", "belongs to a Unity package");
            yield return Case("bin folder under Assets", p => Directory.CreateDirectory(p.Abs("Assets/Game/Runtime/bin")),
                "Assets/Game/Runtime/bin", "build output folder");
            yield return Case("csproj under Assets", p => p.AddAsset("Assets/Game/Runtime/Game.csproj", "<Project />", SyntheticProject.DefaultImporter),
                "Assets/Game/Runtime/Game.csproj", ".NET project files");
        }

        static TestCaseData Case(string name, Action<SyntheticProject> damage, string path, string message) =>
            new TestCaseData(new Breakage(name, damage, path, message)).SetName("Fires_on_" + name.Replace(' ', '_').Replace("'", ""));

        [TestCaseSource(nameof(Breakages))]
        public void Fires_on(Breakage breakage)
        {
            using (var project = new SyntheticProject())
            {
                breakage.Damage(project);
                var problems = AssetIntegrity.Check(project.Root);
                var matching = problems.Where(p => p.Message.Contains(breakage.Message) && (breakage.Path.Length == 0 || p.Path == breakage.Path)).ToList();
                Assert.That(matching, Is.Not.Empty,
                    $"expected '{breakage.Message}' on '{breakage.Path}'; got {AssetIntegrity.Describe(problems)}");
            }
        }
    }
}
