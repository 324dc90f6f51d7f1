using System;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SphFluid.Headless.Scenes;
using SphFluid.UnityFiles.Assets;

namespace SphFluid.Tests.Runner
{
    /// <summary>
    /// OilAndWater with its Oil box made a prefab ran as water alone: the reader reads the GameObjects a scene file holds,
    /// and a prefab instance's are in its .prefab file. Each test copies the project, makes one part of the fluid a prefab
    /// as Unity writes it (a PrefabInstance, stripped documents for what the scene refers to), and expects the refusal.
    /// </summary>
    public sealed class PrefabInstanceTests
    {
        const string Unpack = "unpack each instance in Unity (in the Hierarchy, right-click it, Prefab > Unpack Completely)";

        // OilAndWater's Oil box: its GameObject, Transform and SpawnBox.
        const long OilObject = 305626396, OilTransform = 518734963, OilSpawnBox = 287989891;

        [Test]
        public void ASpawnBoxInAPrefabIsRefusedNamingTheInstanceAndItsPrefab()
        {
            var project = new PrefabProject();
            string oil = project.AddPrefab("Oil", project.Document(OilObject) + project.Document(OilTransform) + project.Document(OilSpawnBox));
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("--- !u!1001 &700")}: " +
                "PrefabInstance 'Oil' of Assets/Prefabs/Oil.prefab holds a SpawnBox on its GameObject 'Oil'"));
            Assert.That(e.Message, Does.Contain(Unpack));
        }

        [Test]
        public void ASpawnBoxAddedToAPrefabInstanceIsRefused()
        {
            var project = new PrefabProject();
            string bare = project.AddPrefab("Bare", project.Document(OilObject).Replace($"  - component: {{fileID: {OilSpawnBox}}}\n", "") +
                project.Document(OilTransform));
            string added = project.Document(OilSpawnBox).Replace($"m_GameObject: {{fileID: {OilObject}}}", "m_GameObject: {fileID: 702}");
            project.ReplaceOilWith(PrefabProject.Instance(700, bare, "Oil", OilObject, OilTransform).Replace("m_AddedComponents: []",
                    $"m_AddedComponents:\n    - targetCorrespondingSourceObject: {{fileID: {OilObject}, guid: {bare}, type: 3}}\n" +
                    $"      insertIndex: -1\n      addedObject: {{fileID: {OilSpawnBox}}}") + added +
                PrefabProject.Stripped(1, 702, OilObject, bare, 700));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf($"--- !u!114 &{OilSpawnBox}")}: " +
                "a SpawnBox added to a GameObject of PrefabInstance 'Oil' of Assets/Prefabs/Bare.prefab"));
        }

        [Test]
        public void ASpawnBoxUnderAPrefabInstanceIsRefused()
        {
            // The Oil box stays in the scene, moved under an instance of a rig, which places it.
            var project = new PrefabProject();
            string rig = project.AddPrefab("Rig", project.Document(OilObject).Replace($"  - component: {{fileID: {OilSpawnBox}}}\n", "")
                .Replace("m_Name: Oil", "m_Name: Rig") + project.Document(OilTransform));
            project.Edit(project.Document(OilTransform), project.Document(OilTransform).Replace("m_Father: {fileID: 0}", "m_Father: {fileID: 701}"));
            project.Edit($"  - {{fileID: {OilTransform}}}\n", "  - {fileID: 701}\n");
            project.Edit("--- !u!1660057539", PrefabProject.Instance(700, rig, "Rig", OilObject, OilTransform).Replace("m_AddedGameObjects: []",
                $"m_AddedGameObjects:\n    - targetCorrespondingSourceObject: {{fileID: {OilTransform}, guid: {rig}, type: 3}}\n" +
                $"      insertIndex: -1\n      addedObject: {{fileID: {OilTransform}}}") + "--- !u!1660057539");

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf($"--- !u!114 &{OilSpawnBox}")}: " +
                "the SpawnBox of GameObject 'Oil', which lies under a GameObject of PrefabInstance 'Rig' of Assets/Prefabs/Rig.prefab that places it"));
        }

        [Test]
        public void APrefabNestedInAnotherIsLookedInto()
        {
            var project = new PrefabProject();
            string oil = project.AddPrefab("Oil", project.Document(OilObject) + project.Document(OilTransform) + project.Document(OilSpawnBox));
            // The rig's own root, with the oil prefab's instance as its one child.
            string rig = project.AddPrefab("Rig",
                project.Document(OilObject).Replace($"  - component: {{fileID: {OilSpawnBox}}}\n", "").Replace("m_Name: Oil", "m_Name: Rig")
                    .Replace($"&{OilObject}", "&11").Replace($"{{fileID: {OilTransform}}}", "{fileID: 12}") +
                project.Document(OilTransform).Replace($"&{OilTransform}", "&12").Replace($"{{fileID: {OilObject}}}", "{fileID: 11}")
                    .Replace("m_Children: []", "m_Children:\n  - {fileID: 701}") +
                PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform).Replace("m_TransformParent: {fileID: 0}", "m_TransformParent: {fileID: 12}"));
            project.ReplaceOilWith(PrefabProject.Instance(800, rig, "Rig", 11, 12));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("--- !u!1001 &800")}: PrefabInstance 'Rig' of " +
                "Assets/Prefabs/Rig.prefab holds a SpawnBox on its GameObject 'Oil' (in Assets/Prefabs/Oil.prefab, nested in it)"));
        }

        /// <summary>Renaming a GameObject inside an instance writes an m_Name override too, after the root's: the instance is
        /// named by the override of its prefab's root GameObject, not by the last one.</summary>
        [Test]
        public void AnInstanceIsNamedByItsRootsNameNotAChildsRename()
        {
            var project = new PrefabProject();
            string oil = project.AddPrefab("Oil", project.Document(OilObject) + project.Document(OilTransform) + project.Document(OilSpawnBox));
            const long OtherObject = 4242;
            string childRename = $"    - target: {{fileID: {OtherObject}, guid: {oil}, type: 3}}\n      propertyPath: m_Name\n" +
                "      value: Handle\n      objectReference: {fileID: 0}\n    m_RemovedComponents: []";
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil Left", OilObject, OilTransform).Replace("    m_RemovedComponents: []", childRename));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("--- !u!1001 &700")}: " +
                "PrefabInstance 'Oil Left' of Assets/Prefabs/Oil.prefab holds a SpawnBox on its GameObject 'Oil'"));
        }

        /// <summary>A prefab file that cannot be read (emptied here) may hold the fluid's components: refused, not guessed.</summary>
        [Test]
        public void AnUnreadablePrefabIsRefusedForWhatItMayHold()
        {
            var project = new PrefabProject();
            string oil = project.AddPrefab("Oil", project.Document(OilObject) + project.Document(OilTransform) + project.Document(OilSpawnBox));
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform));
            File.WriteAllText(Path.Combine(project.Project.Root, "Assets", "Prefabs", "Oil.prefab"), "");

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("--- !u!1001 &700")}: PrefabInstance 'Oil' of " +
                "Assets/Prefabs/Oil.prefab: its prefab cannot be read ("));
            Assert.That(e.Message, Does.Contain("is empty or not a regular file"));
            Assert.That(e.Message, Does.Contain("so whether it holds the fluid's components cannot be told"));
        }

        /// <summary>A prefab that holds none of the fluid's components (a prop, a light) is not the reader's business.</summary>
        [Test]
        public void APrefabWithoutTheFluidsComponentsIsReadPast()
        {
            var project = new PrefabProject();
            string prop = project.AddPrefab("Prop", project.Document(OilObject).Replace($"  - component: {{fileID: {OilSpawnBox}}}\n", "")
                .Replace("m_Name: Oil", "m_Name: Prop") + project.Document(OilTransform));
            project.Edit("--- !u!1660057539", PrefabProject.Instance(700, prop, "Prop", OilObject, OilTransform) + "--- !u!1660057539");
            project.Edit("  m_Roots:\n", "  m_Roots:\n  - {fileID: 701}\n");

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(scene.Description.Phases().Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water", "Oil" }));
        }

        /// <summary>A copy of the repository's Unity project in a scratch folder, whose OilAndWater scene a test edits.</summary>
        sealed class PrefabProject
        {
            readonly string _root = RunnerPaths.ProjectCopy("prefab-project");
            bool _prefabFolder;

            public PrefabProject() => ScenePath = Path.Combine(_root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity");

            public string ScenePath { get; }

            public UnityProject Project => new UnityProject(_root);

            /// <summary>One document of the scene, header line included.</summary>
            public string Document(long fileId) =>
                Regex.Match(File.ReadAllText(ScenePath), $@"(?ms)^--- !u!\d+ &{fileId}\n.*?(?=^--- |\z)").Value is { Length: > 0 } d
                    ? d : throw new InvalidOperationException($"the scene has no document &{fileId}");

            public int LineOf(string text) => Array.IndexOf(File.ReadAllLines(ScenePath), text) + 1;

            public void Edit(string find, string replace)
            {
                string text = File.ReadAllText(ScenePath);
                if (!text.Contains(find)) throw new InvalidOperationException($"the scene has no '{find}'");
                File.WriteAllText(ScenePath, text.Replace(find, replace));
            }

            /// <summary>The Oil box's three documents give way to <paramref name="documents"/>, whose stripped Transform
            /// &amp;(instance + 1) takes the box's place among the scene's roots.</summary>
            public void ReplaceOilWith(string documents)
            {
                string instance = Regex.Match(documents, @"--- !u!1001 &(\d+)").Groups[1].Value;
                Edit(Document(OilTransform), "");
                Edit(Document(OilSpawnBox), "");
                Edit(Document(OilObject), documents);
                Edit($"  - {{fileID: {OilTransform}}}\n", $"  - {{fileID: {long.Parse(instance) + 1}}}\n");
            }

            /// <summary>Writes Assets/Prefabs/<paramref name="name"/>.prefab and its .meta; returns its guid.</summary>
            public string AddPrefab(string name, string documents)
            {
                string folder = Path.Combine(_root, "Assets", "Prefabs");
                if (!_prefabFolder)
                {
                    Directory.CreateDirectory(folder);
                    File.WriteAllText(folder + ".meta", $"fileFormatVersion: 2\nguid: {NewGuid()}\nfolderAsset: yes\nDefaultImporter:\n" +
                        "  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n");
                    _prefabFolder = true;
                }
                string guid = NewGuid();
                File.WriteAllText(Path.Combine(folder, name + ".prefab"), "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n" + documents);
                File.WriteAllText(Path.Combine(folder, name + ".prefab.meta"), $"fileFormatVersion: 2\nguid: {guid}\nPrefabImporter:\n" +
                    "  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n");
                return guid;
            }

            /// <summary>A PrefabInstance &amp;<paramref name="id"/> of the prefab, named <paramref name="name"/>, and the
            /// stripped Transform &amp;(id + 1) of its root, as Unity writes them.</summary>
            public static string Instance(long id, string prefabGuid, string name, long rootObject, long rootTransform) =>
                $"--- !u!1001 &{id}\nPrefabInstance:\n  m_ObjectHideFlags: 0\n  serializedVersion: 2\n  m_Modification:\n" +
                "    serializedVersion: 3\n    m_TransformParent: {fileID: 0}\n    m_Modifications:\n" +
                $"    - target: {{fileID: {rootObject}, guid: {prefabGuid}, type: 3}}\n      propertyPath: m_Name\n      value: {name}\n" +
                "      objectReference: {fileID: 0}\n    m_RemovedComponents: []\n    m_RemovedGameObjects: []\n" +
                "    m_AddedGameObjects: []\n    m_AddedComponents: []\n" +
                $"  m_SourcePrefab: {{fileID: 100100000, guid: {prefabGuid}, type: 3}}\n" +
                Stripped(4, id + 1, rootTransform, prefabGuid, id);

            public static string Stripped(int classId, long id, long source, string prefabGuid, long instance) =>
                $"--- !u!{classId} &{id} stripped\n{(classId == 1 ? "GameObject" : "Transform")}:\n" +
                $"  m_CorrespondingSourceObject: {{fileID: {source}, guid: {prefabGuid}, type: 3}}\n" +
                $"  m_PrefabInstance: {{fileID: {instance}}}\n  m_PrefabAsset: {{fileID: 0}}\n";

            static string NewGuid() => Guid.NewGuid().ToString("N");
        }
    }
}
