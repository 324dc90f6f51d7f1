using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace SphFluid.Tests.Integrity
{
    /// <summary>
    /// A small, valid Unity project written to a temp folder: one runtime asmdef with a MonoBehaviour, a compute shader,
    /// a material-free scene that uses both (with a parent/child pair), manifest and ProjectSettings. Each broken-tree
    /// test damages one thing and expects exactly that finding.
    /// </summary>
    public sealed class SyntheticProject : IDisposable
    {
        public const string ScenePath = "Assets/Game/Scenes/Main.unity";
        public const string ScriptPath = "Assets/Game/Runtime/FluidEmitter.cs";
        public const string ShaderPath = "Assets/Game/Shaders/Splash.compute";
        public const string RuntimeAsmdefPath = "Assets/Game/Runtime/Game.Runtime.asmdef";
        public const string EditorAsmdefPath = "Assets/Game/Editor/Game.Editor.asmdef";
        public const string EditorScriptPath = "Assets/Game/Editor/EmitterTool.cs";

        readonly Dictionary<string, string> _guids = new Dictionary<string, string>();

        public SyntheticProject()
        {
            Root = Path.Combine(Path.GetTempPath(), "sph-integrity-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(Root);
            WriteProject();
        }

        public string Root { get; }

        public string GuidOf(string assetPath) => _guids[assetPath];

        public string Abs(string relativePath) => Path.Combine(Root, relativePath);

        public string Read(string relativePath) => File.ReadAllText(Abs(relativePath));

        public void Write(string relativePath, string text)
        {
            var abs = Abs(relativePath);
            Directory.CreateDirectory(Path.GetDirectoryName(abs) ?? Root);
            File.WriteAllText(abs, text.Replace("\r\n", "\n"));
        }

        public void Replace(string relativePath, string from, string to)
        {
            var text = Read(relativePath);
            if (!text.Contains(from)) throw new InvalidOperationException($"'{from}' not in {relativePath}");
            Write(relativePath, text.Replace(from, to));
        }

        public void Delete(string relativePath) => File.Delete(Abs(relativePath));

        /// <summary>Adds an asset with a fresh .meta (folders included), as write-metas.py would.</summary>
        public void AddAsset(string relativePath, string text, string importer)
        {
            Write(relativePath, text);
            WriteMeta(relativePath, importer);
        }

        public void Dispose()
        {
            try { Directory.Delete(Root, true); }
            catch (IOException) { }
        }

        static string NewGuid() => Guid.NewGuid().ToString("N");

        const string Tail = "  userData: \n  assetBundleName: \n  assetBundleVariant: \n";
        public const string FolderImporter = "folderAsset: yes\nDefaultImporter:\n  externalObjects: {}\n" + Tail;
        public const string MonoImporter = "MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n  executionOrder: 0\n  icon: {instanceID: 0}\n" + Tail;
        public const string AsmdefImporter = "AssemblyDefinitionImporter:\n  externalObjects: {}\n" + Tail;
        public const string ComputeImporter = "ComputeShaderImporter:\n  externalObjects: {}\n  preprocessorOverride: 0\n" + Tail;
        public const string DefaultImporter = "DefaultImporter:\n  externalObjects: {}\n" + Tail;

        void WriteMeta(string relativePath, string importer)
        {
            var guid = NewGuid();
            _guids[relativePath] = guid;
            Write(relativePath + ".meta", "fileFormatVersion: 2\nguid: " + guid + "\n" + importer);
            // GetDirectoryName is null only for a root, which a project-relative path never is.
            var parent = (Path.GetDirectoryName(relativePath) ?? "").Replace('\\', '/');
            if (parent != "Assets" && !File.Exists(Abs(parent + ".meta"))) WriteMeta(parent, FolderImporter);
        }

        void WriteProject()
        {
            Write("Packages/manifest.json",
                "{\n  \"dependencies\": {\n    \"com.unity.inputsystem\": \"1.7.0\",\n    \"com.unity.mathematics\": \"1.2.6\",\n" +
                "    \"com.unity.test-framework\": \"1.1.33\",\n    \"com.unity.ugui\": \"1.0.0\",\n    \"com.unity.modules.physics\": \"1.0.0\"\n  }\n}\n");
            Write("ProjectSettings/ProjectVersion.txt", "m_EditorVersion: 2022.3.62f2\n");
            Write("ProjectSettings/ProjectSettings.asset", Settings(129, "PlayerSettings", "  productName: Synthetic\n  activeInputHandler: 1\n"));
            Write("ProjectSettings/EditorSettings.asset", Settings(159, "EditorSettings", "  serializedVersion: 12\n  m_SerializationMode: 2\n"));

            Directory.CreateDirectory(Abs("Assets/Game/Runtime"));
            AddAsset(RuntimeAsmdefPath, "{\n    \"name\": \"Game.Runtime\",\n    \"references\": [\n        \"Unity.Mathematics\",\n        \"Unity.InputSystem\"\n    ]\n}\n", AsmdefImporter);
            AddAsset(ScriptPath,
                "using UnityEngine;\n\nnamespace Game\n{\n    // class Decoy : MonoBehaviour in a comment must not count\n" +
                "    public sealed class FluidEmitter : MonoBehaviour\n    {\n        [SerializeField] ComputeShader splash;\n        public float rate = 2f;\n    }\n}\n",
                MonoImporter);
            AddAsset(ShaderPath, "#pragma kernel Splash\n[numthreads(64,1,1)]\nvoid Splash(uint3 id : SV_DispatchThreadID) {}\n", ComputeImporter);
            AddAsset(EditorAsmdefPath,
                "{\n    \"name\": \"Game.Editor\",\n    \"references\": [\n        \"Game.Runtime\"\n    ],\n    \"includePlatforms\": [\n        \"Editor\"\n    ]\n}\n",
                AsmdefImporter);
            AddAsset(EditorScriptPath, "using UnityEngine;\n\npublic sealed class EmitterTool : MonoBehaviour\n{\n}\n", MonoImporter);
            Write(ScenePath, "");
            WriteMeta(ScenePath, DefaultImporter);
            Write(ScenePath, Scene(GuidOf(ScriptPath), GuidOf(ShaderPath)));
            Write("ProjectSettings/EditorBuildSettings.asset", Settings(1045, "EditorBuildSettings",
                "  serializedVersion: 2\n  m_Scenes:\n  - enabled: 1\n    path: " + ScenePath + "\n    guid: " + GuidOf(ScenePath) + "\n  m_configObjects: {}\n"));
        }

        static string Settings(int classId, string type, string body) =>
            "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!" + classId + " &1\n" + type + ":\n  m_ObjectHideFlags: 0\n" + body;

        static string Scene(string scriptGuid, string shaderGuid) =>
            "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n" +
            "--- !u!29 &1\nOcclusionCullingSettings:\n  m_ObjectHideFlags: 0\n  serializedVersion: 2\n" +
            "--- !u!104 &2\nRenderSettings:\n  m_ObjectHideFlags: 0\n  serializedVersion: 9\n" +
            "  m_SkyboxMaterial: {fileID: 10304, guid: 0000000000000000f000000000000000, type: 0}\n" +
            "--- !u!157 &3\nLightmapSettings:\n  m_ObjectHideFlags: 0\n  serializedVersion: 12\n" +
            "--- !u!196 &4\nNavMeshSettings:\n  serializedVersion: 2\n  m_ObjectHideFlags: 0\n" +
            "--- !u!1 &100\nGameObject:\n  m_ObjectHideFlags: 0\n  serializedVersion: 6\n  m_Component:\n" +
            "  - component: {fileID: 101}\n  - component: {fileID: 102}\n  m_Layer: 0\n  m_Name: Container\n  m_IsActive: 1\n" +
            "--- !u!4 &101\nTransform:\n  m_GameObject: {fileID: 100}\n  serializedVersion: 2\n" +
            "  m_LocalRotation: {x: 0, y: 0, z: 0, w: 1}\n  m_LocalPosition: {x: 0, y: 1, z: 0}\n  m_LocalScale: {x: 1, y: 1, z: 1}\n" +
            "  m_Children:\n  - {fileID: 201}\n  m_Father: {fileID: 0}\n" +
            "--- !u!114 &102\nMonoBehaviour:\n  m_GameObject: {fileID: 100}\n  m_Enabled: 1\n  m_EditorHideFlags: 0\n" +
            "  m_Script: {fileID: 11500000, guid: " + scriptGuid + ", type: 3}\n  m_Name: \n  m_EditorClassIdentifier: \n" +
            "  splash: {fileID: 7200000, guid: " + shaderGuid + ", type: 3}\n  rate: 2\n" +
            "--- !u!1 &200\nGameObject:\n  m_ObjectHideFlags: 0\n  serializedVersion: 6\n  m_Component:\n" +
            "  - component: {fileID: 201}\n  - component: {fileID: 202}\n  m_Layer: 0\n  m_Name: Ball\n  m_IsActive: 1\n" +
            "--- !u!4 &201\nTransform:\n  m_GameObject: {fileID: 200}\n  serializedVersion: 2\n" +
            "  m_LocalRotation: {x: 0, y: 0, z: 0, w: 1}\n  m_LocalPosition: {x: 0, y: 2, z: 0}\n  m_LocalScale: {x: 1, y: 1, z: 1}\n" +
            "  m_Children: []\n  m_Father: {fileID: 101}\n" +
            "--- !u!135 &202\nSphereCollider:\n  m_GameObject: {fileID: 200}\n  m_Enabled: 1\n  m_Radius: 0.5\n" +
            "--- !u!1660057539 &9223372036854775807\nSceneRoots:\n  m_ObjectHideFlags: 0\n  m_Roots:\n  - {fileID: 101}\n";
    }
}
