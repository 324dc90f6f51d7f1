using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.UnityFiles.Assets;

namespace SphFluid.Tests.Runner
{
    /// <summary>
    /// OilAndWater with its Oil box made a prefab ran as water alone: the reader read the GameObjects a scene file holds,
    /// and a prefab instance's are in its .prefab file. Each test copies the project and makes one part of the fluid a
    /// prefab as Unity writes it (a PrefabInstance with its overrides, stripped stand-ins for what the scene refers to),
    /// then expects the instance built as Unity builds it, or, for one it cannot build, the refusal.
    /// </summary>
    public sealed class PrefabInstanceTests
    {
        const string Unpack = "Unpack each such instance in Unity (in the Hierarchy, right-click it, Prefab > Unpack Completely)";

        // OilAndWater's Oil box: its GameObject, Transform and SpawnBox, at (0.15, 0.1, 0), 0.3 x 0.2 x 0.12 m, 900 kg/m^3.
        const long OilObject = 305626396, OilTransform = 518734963, OilSpawnBox = 287989891;

        static FluidBlock Oil(LoadedScene scene) => scene.Description.SpawnBoxes.Single(b => b.Phase.Name == "Oil");

        [Test]
        public void ASpawnBoxInAPrefabIsBuiltWithTheInstancesOverrides()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform,
                PrefabProject.Override(OilTransform, oil, "m_LocalPosition.y", "0.05"),
                PrefabProject.Override(OilTransform, oil, "m_LocalScale.y", "0.1"),
                PrefabProject.Override(OilSpawnBox, oil, "spawn.Phase.RestDensity", "850")));

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(scene.Description.Phases().Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water", "Oil" }));
            Assert.That(Oil(scene).Center.Y, Is.EqualTo(0.05f).Within(1e-6f), "the overridden position");
            Assert.That(Oil(scene).Center.X, Is.EqualTo(0.15f).Within(1e-6f), "the prefab's position");
            Assert.That(Oil(scene).Size.Y, Is.EqualTo(0.1f).Within(1e-6f), "the overridden scale");
            Assert.That(Oil(scene).Size.X, Is.EqualTo(0.3f).Within(1e-6f), "the prefab's scale");
            Assert.That(Oil(scene).Phase.RestDensity, Is.EqualTo(850f), "the overridden rest density");
            Assert.That(Oil(scene).Phase.Viscosity, Is.EqualTo(0.1f), "the prefab's viscosity");
        }

        /// <summary>The Oil box made a prefab and placed where it was: the scene reads as the one it came from, every field
        /// of every box alike (run headless, the two give the same diagnostics.csv byte for byte).</summary>
        [Test]
        public void ASpawnBoxMadeAPrefabReadsAsTheSceneItCameFrom()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform));
            var options = new JsonSerializerOptions { IncludeFields = true };

            var built = SceneLoader.Load(project.ScenePath, project.Project).Description;
            var original = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;

            Assert.That(built.SpawnBoxes.Select(b => JsonSerializer.Serialize(b, options)).ToArray(),
                Is.EqualTo(original.SpawnBoxes.Select(b => JsonSerializer.Serialize(b, options)).ToArray()));
            Assert.That(JsonSerializer.Serialize(built.SpawnBoxes.Single(b => b.Phase.Name == "Oil"), options), Does.Contain("\"RestDensity\":900").And.Contain("\"Center\":{\"X\":0.15"),
                "the comparison sees the fields");
        }

        /// <summary>Each instance's objects get fileIDs of their own: two instances of one prefab are two boxes.</summary>
        [Test]
        public void TwoInstancesOfOnePrefabAreTwoBoxes()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform) +
                PrefabProject.Instance(800, oil, "Oil (1)", OilObject, OilTransform,
                    PrefabProject.Override(OilTransform, oil, "m_LocalPosition.y", "0.3"), PrefabProject.Override(OilTransform, oil, "m_LocalScale.y", "0.15")));
            project.Edit("  - {fileID: 701}\n", "  - {fileID: 701}\n  - {fileID: 801}\n");

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            var boxes = scene.Description.SpawnBoxes.Where(b => b.Phase.Name == "Oil").OrderBy(b => b.Name, StringComparer.Ordinal).ToArray();
            Assert.That(boxes.Select(b => b.Name).ToArray(), Is.EqualTo(new[] { "Oil", "Oil (1)" }));
            Assert.That(boxes[0].Center.Y, Is.EqualTo(0.1f).Within(1e-6f));
            Assert.That(boxes[1].Center.Y, Is.EqualTo(0.3f).Within(1e-6f));
        }

        /// <summary>A SpawnBox added to an instance's GameObject lives in the scene, on the stand-in of the prefab's GameObject.</summary>
        [Test]
        public void ASpawnBoxAddedToAPrefabInstanceIsBuiltOnItsGameObject()
        {
            var project = new PrefabProject();
            string bare = project.AddPrefab("Bare", project.Document(OilObject).Replace($"  - component: {{fileID: {OilSpawnBox}}}\n", "") +
                project.Document(OilTransform));
            string added = project.Document(OilSpawnBox).Replace($"m_GameObject: {{fileID: {OilObject}}}", "m_GameObject: {fileID: 702}");
            project.ReplaceOilWith(PrefabProject.Instance(700, bare, "Oil", OilObject, OilTransform,
                    PrefabProject.Override(OilTransform, bare, "m_LocalPosition.z", "0.01"), PrefabProject.Override(OilTransform, bare, "m_LocalScale.z", "0.08"))
                    .Replace("m_AddedComponents: []",
                    $"m_AddedComponents:\n    - targetCorrespondingSourceObject: {{fileID: {OilObject}, guid: {bare}, type: 3}}\n" +
                    $"      insertIndex: -1\n      addedObject: {{fileID: {OilSpawnBox}}}") + added +
                PrefabProject.Stripped(1, 702, OilObject, bare, 700));

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(Oil(scene).Name, Is.EqualTo("Oil"));
            Assert.That(Oil(scene).Center.Z, Is.EqualTo(0.01f).Within(1e-6f), "placed by the instance's Transform");
        }

        /// <summary>A box the scene holds under an instance's GameObject is placed by the prefab's Transform and the
        /// instance's overrides of it.</summary>
        [Test]
        public void ASpawnBoxUnderAPrefabInstanceIsPlacedByIt()
        {
            // The Oil box stays in the scene, moved under an instance of a rig at the origin, raised 0.05 m.
            var project = new PrefabProject();
            string rig = project.AddPrefab("Rig", project.Document(OilObject).Replace($"  - component: {{fileID: {OilSpawnBox}}}\n", "")
                .Replace("m_Name: Oil", "m_Name: Rig") + project.Document(OilTransform)
                .Replace("m_LocalPosition: {x: 0.15, y: 0.1, z: 0}", "m_LocalPosition: {x: 0, y: 0, z: 0}")
                .Replace("m_LocalScale: {x: 0.3, y: 0.2, z: 0.12}", "m_LocalScale: {x: 1, y: 1, z: 1}"));
            project.Edit(project.Document(OilTransform), project.Document(OilTransform).Replace("m_Father: {fileID: 0}", "m_Father: {fileID: 701}"));
            project.Edit($"  - {{fileID: {OilTransform}}}\n", "  - {fileID: 701}\n");
            project.Edit("--- !u!1660057539", PrefabProject.Instance(700, rig, "Rig", OilObject, OilTransform,
                    PrefabProject.Override(OilTransform, rig, "m_LocalPosition.y", "0.05")).Replace("m_AddedGameObjects: []",
                $"m_AddedGameObjects:\n    - targetCorrespondingSourceObject: {{fileID: {OilTransform}, guid: {rig}, type: 3}}\n" +
                $"      insertIndex: -1\n      addedObject: {{fileID: {OilTransform}}}") + "--- !u!1660057539");

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(Oil(scene).Center.Y, Is.EqualTo(0.15f).Within(1e-6f), "0.05 m of the rig's and 0.1 m of its own");
            Assert.That(Oil(scene).Center.X, Is.EqualTo(0.15f).Within(1e-6f));
        }

        /// <summary>An override is a field's new value: one out of range is refused at the override's line, as a value in
        /// the scene itself is at its own.</summary>
        [Test]
        public void AnOverriddenValueOutOfRangeIsRefusedAtTheOverridesLine()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform,
                PrefabProject.Override(OilSpawnBox, oil, "spawn.Phase.RestDensity", "-5")));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("      value: -5")}: GameObject 'Oil', SpawnBox.spawn.Phase.RestDensity"));
        }

        /// <summary>A value the instance keeps from its prefab is mended in the .prefab (for every instance) or overridden
        /// in the scene: the refusal names the instance's line and the value's own line in the prefab.</summary>
        [Test]
        public void APrefabsOwnValueOutOfRangeIsNamedAtItsLineInThePrefab()
        {
            var project = new PrefabProject();
            string oil = project.AddPrefab("Oil", project.Document(OilObject) + project.Document(OilTransform) +
                project.Document(OilSpawnBox).Replace("RestDensity: 900", "RestDensity: -5"));
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("--- !u!1001 &700")} (the value at Assets/Prefabs/Oil.prefab:" +
                $"{project.LineIn("Oil", "      RestDensity: -5")}, which the instance does not override): GameObject 'Oil', SpawnBox.spawn.Phase.RestDensity"));
        }

        /// <summary>A Transform's value is found bad before any field is read (here a NaN in the prefab's position), and is
        /// named in the prefab as well.</summary>
        [Test]
        public void APrefabsTransformValueIsNamedAtItsLineInThePrefab()
        {
            var project = new PrefabProject();
            string oil = project.AddPrefab("Oil", project.Document(OilObject) + project.Document(OilTransform)
                .Replace("m_LocalPosition: {x: 0.15, y: 0.1, z: 0}", "m_LocalPosition:\n    x: 0.15\n    y: NaN\n    z: 0") + project.Document(OilSpawnBox));
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.StartWith($"{project.ScenePath}:{project.LineOf("--- !u!1001 &700")} (the value at Assets/Prefabs/Oil.prefab:" +
                $"{project.LineIn("Oil", "    y: NaN")}, which the instance does not override): GameObject 'Oil', Transform.m_LocalPosition.y must be a finite number"));
        }

        /// <summary>A rotation the instance overrides in one axis holds the prefab's other three: the refusal of the whole
        /// quaternion names the override, which made it what it is.</summary>
        [Test]
        public void AValueOverriddenInPartIsNamedAtTheOverride()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform,
                PrefabProject.Override(OilTransform, oil, "m_LocalRotation.x", "0.5")));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.StartWith($"{project.ScenePath}:{project.LineOf("      value: 0.5")}: GameObject 'Oil', Transform.m_LocalRotation must be a unit quaternion"));
        }

        /// <summary>Each refused override names its instance, and the name is read from the overrides: named afresh for
        /// each, 60 000 of them took over 5 minutes to refuse. 20 000 are refused within 10 s.</summary>
        [Test]
        public void ManyUnusedOverridesAreRefusedInLinearTime()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform,
                Enumerable.Range(0, 20_000).Select(k => PrefabProject.Override(900_000_000 + k, oil, "m_Name", "x")).ToArray()));

            var thrown = Deadline.Within(10, () => Deadline.Thrown(() => SceneLoader.Load(project.ScenePath, project.Project)), "loading the scene");

            Assert.That(thrown, Is.InstanceOf<SceneException>());
            Assert.That(thrown!.Message, Does.Contain("carry overrides the reader refuses (20000)"));
        }

        /// <summary>Unity keeps an override of a field the component no longer has, and ignores it; on the fluid's own
        /// components the reader refuses it, as it refuses a field it does not know in the scene.</summary>
        [Test]
        public void AnOverrideOfAFieldTheSpawnBoxLacksIsRefusedAtItsLine()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform,
                PrefabProject.Override(OilSpawnBox, oil, "spawn.Phase.Density", "850")));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("      propertyPath: spawn.Phase.Density")}: PrefabInstance 'Oil' of " +
                "Assets/Prefabs/Oil.prefab overrides SpawnBox.spawn.Phase.Density, which is no field of the SpawnBox in Assets/Prefabs/Oil.prefab"));
            Assert.That(e.Message, Does.Contain("Unity keeps an override of a field or object its prefab lacks and ignores it"));
        }

        /// <summary>Unity writes an override for each value; one that names a whole block with one value cannot be
        /// applied, and was refused as no field of the SpawnBox, which it is.</summary>
        [Test]
        public void AnOverrideOfAWholeBlockIsRefusedAsOneValueForABlock()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform,
                PrefabProject.Override(OilSpawnBox, oil, "spawn.Phase", "850")));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.StartWith($"{project.ScenePath}: prefab instances that hold or place the fluid carry overrides the reader refuses (1):"));
            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("      propertyPath: spawn.Phase")}: PrefabInstance 'Oil' of " +
                "Assets/Prefabs/Oil.prefab overrides SpawnBox.spawn.Phase, a block of fields, with one value (Unity overrides each field of it: spawn.Phase.<field>)"));
        }

        /// <summary>An instance that deactivates the box's GameObject, or disables its SpawnBox, spawns none of it, as in Unity.</summary>
        [TestCase(OilObject, "m_IsActive")]
        [TestCase(OilSpawnBox, "m_Enabled")]
        public void ABoxTheInstanceTurnsOffIsLeftOut(long target, string flag)
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform, PrefabProject.Override(target, oil, flag, "0")));

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(scene.Description.Phases().Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water" }));
        }

        /// <summary>The integrity check holds a scene's own flags to 0 or 1; an instance's override of one was not held to
        /// it, and an m_IsActive of 2 or an m_Enabled of 'abc' was read as on.</summary>
        [TestCase(OilObject, "m_IsActive", "2", "GameObject.m_IsActive")]
        [TestCase(OilSpawnBox, "m_Enabled", "abc", "SpawnBox.m_Enabled")]
        public void AFlagOverriddenWithNeither0Nor1IsRefusedAtItsLine(long target, string flag, string value, string field)
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform, PrefabProject.Override(target, oil, flag, value)));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.StartWith($"{project.ScenePath}:{project.LineOf($"      value: {value}")}: GameObject 'Oil', {field} must be 0 or 1, " +
                $"as Unity writes a bool (was '{value}')"));
        }

        /// <summary>Unity restructures no instance: which GameObject a component is on, which script it runs and where a
        /// Transform hangs are its prefab's. A hand-written override of them made the SpawnBox vanish without a word
        /// (m_GameObject, m_Script) or was read past (m_Father); each is refused at its line.</summary>
        [TestCase(OilSpawnBox, "m_GameObject", "SpawnBox")]
        [TestCase(OilSpawnBox, "m_Script", "SpawnBox")]
        [TestCase(OilTransform, "m_Father", "Transform")]
        [TestCase(OilObject, "m_Component.Array.data[0].component", "GameObject")]
        [TestCase(999L, "m_Script", "&999")]
        public void AnOverrideOfHowThePrefabsObjectsFitTogetherIsRefused(long target, string property, string type)
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform, PrefabProject.Override(target, oil, property, "")));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf($"      propertyPath: {property}")}: PrefabInstance 'Oil' of " +
                $"Assets/Prefabs/Oil.prefab overrides {type}.{property}, which ties the prefab's objects together"));
        }

        /// <summary>Unity removes neither a GameObject's Transform nor an instance's root (deleting the instance is how
        /// the root leaves). A hand-written removal of the Transform built the box at the world's origin, refused for lying
        /// outside the container; one of the root left the box out without a word. Each is refused at its line.</summary>
        [TestCase(OilTransform, "m_RemovedComponents", "removes the Transform &518734963 of Assets/Prefabs/Oil.prefab, which Unity cannot remove")]
        [TestCase(OilObject, "m_RemovedGameObjects", "removes the root GameObject of Assets/Prefabs/Oil.prefab, which Unity does not")]
        public void ARemovalUnityCannotMakeIsRefusedAtItsLine(long target, string list, string refusal)
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            string removal = $"    - {{fileID: {target}, guid: {oil}, type: 3}}";
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform).Replace($"{list}: []", $"{list}:\n{removal}"));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf(removal)}: PrefabInstance 'Oil' of Assets/Prefabs/Oil.prefab {refusal}"));
        }

        /// <summary>An instance's root hangs under its m_TransformParent as a Transform under its m_Father: one pointing
        /// at the camera's GameObject was taken for no parent, and the box built at the scene's root.</summary>
        [Test]
        public void AnInstanceUnderAGameObjectRatherThanATransformIsRefused()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform)
                .Replace("m_TransformParent: {fileID: 0}", "m_TransformParent: {fileID: 1067556328}"));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("    m_TransformParent: {fileID: 1067556328}")}: " +
                "PrefabInstance &700 m_Modification.m_TransformParent points at a GameObject, not a Transform"));
        }

        [Test]
        public void AComponentTheInstanceRemovesIsLeftOut()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform)
                .Replace("m_RemovedComponents: []", $"m_RemovedComponents:\n    - {{fileID: {OilSpawnBox}, guid: {oil}, type: 3}}"));

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(scene.Description.Phases().Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water" }));
        }

        /// <summary>The Oil box as the child of a rig at the origin, in one prefab: the instance moves the rig, and the
        /// box with it.</summary>
        [Test]
        public void AChildInAPrefabIsPlacedByTheInstancesRoot()
        {
            var project = new PrefabProject();
            string pair = PairPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, pair, "Pair", 11, 12, PrefabProject.Override(12, pair, "m_LocalPosition.y", "0.05")));

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(Oil(scene).Center.Y, Is.EqualTo(0.15f).Within(1e-6f), "0.05 m of the rig's and 0.1 m of its own");
        }

        [Test]
        public void AGameObjectTheInstanceRemovesIsLeftOutWithItsComponents()
        {
            var project = new PrefabProject();
            string pair = PairPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, pair, "Pair", 11, 12)
                .Replace("m_RemovedGameObjects: []", $"m_RemovedGameObjects:\n    - {{fileID: {OilObject}, guid: {pair}, type: 3}}"));

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(scene.Description.Phases().Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water" }));
        }

        /// <summary>Removing a GameObject removes every one under it; the prefab's children were scanned for each one
        /// removed, and removing the top of a chain of 4 000 took 40 s.</summary>
        [Test]
        public void RemovingTheTopOfALongChainTakesLinearTime()
        {
            var project = new PrefabProject();
            const int chain = 4000;
            var links = new System.Text.StringBuilder();
            for (int i = 0; i < chain; i++)
            {
                long go = 10_000 + i, transform = 20_001 + i, father = i == 0 ? OilTransform : transform - 1;
                string children = i + 1 < chain ? $"m_Children:\n  - {{fileID: {transform + 1}}}" : "m_Children: []";
                links.Append($"--- !u!1 &{go}\nGameObject:\n  m_ObjectHideFlags: 0\n  serializedVersion: 6\n  m_Component:\n  - component: {{fileID: {transform}}}\n" +
                    $"  m_Layer: 0\n  m_Name: Link {i}\n  m_TagString: Untagged\n  m_IsActive: 1\n--- !u!4 &{transform}\nTransform:\n  m_ObjectHideFlags: 0\n" +
                    $"  m_GameObject: {{fileID: {go}}}\n  serializedVersion: 2\n  m_LocalRotation: {{x: 0, y: 0, z: 0, w: 1}}\n  m_LocalPosition: {{x: 0, y: 0, z: 0}}\n" +
                    $"  m_LocalScale: {{x: 1, y: 1, z: 1}}\n  m_ConstrainProportionsScale: 0\n  {children}\n  m_Father: {{fileID: {father}}}\n" +
                    "  m_LocalEulerAnglesHint: {x: 0, y: 0, z: 0}\n");
            }
            string oil = project.AddPrefab("Oil", project.Document(OilObject) +
                project.Document(OilTransform).Replace("m_Children: []", "m_Children:\n  - {fileID: 20001}") + links + project.Document(OilSpawnBox));
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform)
                .Replace("m_RemovedGameObjects: []", $"m_RemovedGameObjects:\n    - {{fileID: 10000, guid: {oil}, type: 3}}"));

            var scene = Deadline.Within(10, () => SceneLoader.Load(project.ScenePath, project.Project), "loading the scene");

            Assert.That(Oil(scene).Center.X, Is.EqualTo(0.15f).Within(1e-6f), "the box on the prefab's root stays");
        }

        /// <summary>A prefab is checked as a scene is before it is built: one Unity would break on is refused naming its
        /// own file and line.</summary>
        [Test]
        public void APrefabTheIntegrityCheckRefusesIsNotBuilt()
        {
            var project = new PrefabProject();
            string oil = project.AddPrefab("Oil", project.Document(OilObject) + project.Document(OilTransform) + project.Document(OilSpawnBox) +
                project.Document(OilSpawnBox));
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain("the integrity check refuses prefabs the scene's instances are built from"));
            Assert.That(e.Message, Does.Match($@"Assets/Prefabs/Oil\.prefab:\d+: anchor &{OilSpawnBox} is used by more than one document"));
        }

        /// <summary>An instance placed under one of its own GameObjects (a hand edit; Unity cannot write it) would loop
        /// every walk up the hierarchy.</summary>
        [Test]
        public void AnInstanceUnderItselfIsRefusedAsAParentCycle()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform)
                .Replace("m_TransformParent: {fileID: 0}", "m_TransformParent: {fileID: 701}"));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain("prefab instances put GameObjects in a parent cycle"));
            Assert.That(e.Message, Does.Contain("GameObject 'Oil' &"));
            Assert.That(e.Message, Does.Contain("is its own parent"));
        }

        /// <summary>The Oil box made a prefab nested in a rig, then the box's prefab, the rig's or the scene around the
        /// rig's instance hand-edited as <see cref="MangledSceneTests"/> edits the shipped scenes: each is read with every
        /// number finite, or refused naming the scene, within 10 s; no other exception.</summary>
        [Test]
        public void AMangledPrefabOrInstanceIsReadOrRefusedByName()
        {
            var project = new PrefabProject();
            string rig = NestedRig(project, oil => PrefabProject.Override(OilSpawnBox, oil, "spawn.Phase.RestDensity", "870"));
            project.ReplaceOilWith(PrefabProject.Instance(800, rig, "Rig", 11, 12,
                PrefabProject.Override((700 ^ OilSpawnBox) & long.MaxValue, rig, "spawn.Phase.Viscosity", "0.2")));
            string prefabs = Path.Combine(project.Project.Root, "Assets", "Prefabs");
            string[] files = { Path.Combine(prefabs, "Oil.prefab"), Path.Combine(prefabs, "Rig.prefab"), project.ScenePath };
            string[][] originals = files.Select(File.ReadAllLines).ToArray();
            var random = new Random(7);
            var wrong = new List<string>();
            for (int n = 0; n < 45; n++)
            {
                int edited = n % files.Length;
                var lines = originals[edited].ToList();
                var edits = new List<string>();
                for (int e = 1 + random.Next(3); e > 0; e--) edits.Add(MangledSceneTests.Mangle(lines, random));
                for (int f = 0; f < files.Length; f++) File.WriteAllLines(files[f], f == edited ? lines : originals[f].ToList());
                string what = $"{Path.GetFileName(files[edited])} #{n} ({string.Join("; ", edits)})";

                var (loaded, thrown) = Deadline.Within(10, () =>
                {
                    try { return (SceneLoader.Load(project.ScenePath, project.Project), (Exception?)null); }
                    catch (Exception ex) { return ((LoadedScene?)null, ex); }
                }, $"loading {what}");

                if (thrown is SceneException refusal)
                {
                    if (!refusal.Message.StartsWith(project.ScenePath, StringComparison.Ordinal))
                        wrong.Add($"{what}: the refusal does not start with the scene: {refusal.Message}");
                }
                else if (thrown != null)
                    wrong.Add($"{what}: {thrown.GetType().Name}: {thrown.Message}");
                else if (MangledSceneTests.NotFinite(loaded!.Description, "Description", 0) is string field)
                    wrong.Add($"{what}: read, with {field}");
            }
            Assert.That(wrong, Is.Empty, string.Join("\n", wrong));
        }

        /// <summary>Rig.prefab nests Oil.prefab and overrides its rest density; the scene's instance of the rig raises it
        /// and overrides the nested box's viscosity, naming the box by the fileID the rig gives it (the rig's instance's
        /// fileID xor the box's own). Each level's overrides apply, innermost first.</summary>
        [Test]
        public void APrefabNestingAnotherIsBuiltWithEachLevelsOverrides()
        {
            var project = new PrefabProject();
            string rig = NestedRig(project, oil => PrefabProject.Override(OilSpawnBox, oil, "spawn.Phase.RestDensity", "870"));
            long nestedBox = (700 ^ OilSpawnBox) & long.MaxValue;
            project.ReplaceOilWith(PrefabProject.Instance(800, rig, "Rig", 11, 12,
                PrefabProject.Override(12, rig, "m_LocalPosition.y", "0.05"),
                PrefabProject.Override(nestedBox, rig, "spawn.Phase.Viscosity", "0.2")));

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(Oil(scene).Phase.RestDensity, Is.EqualTo(870f), "the rig's override of its nested box");
            Assert.That(Oil(scene).Phase.Viscosity, Is.EqualTo(0.2f), "the scene's override of the nested box");
            Assert.That(Oil(scene).Center.Y, Is.EqualTo(0.15f).Within(1e-6f), "0.05 m of the rig's and 0.1 m of the box's own");
        }

        /// <summary>A variant is an instance of its base with overrides, in a file of its own; the scene's instance of it
        /// names the base's objects by the fileIDs the variant gives them.</summary>
        [Test]
        public void APrefabVariantIsBuiltFromItsBase()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            string heavy = project.AddPrefab("Heavy Oil", PrefabProject.Instance(900, oil, "Heavy Oil", OilObject, OilTransform,
                PrefabProject.Override(OilSpawnBox, oil, "spawn.Phase.RestDensity", "950")));
            project.ReplaceOilWith(PrefabProject.Instance(700, heavy, "Heavy Oil (1)", (900 ^ OilObject) & long.MaxValue, 901,
                PrefabProject.Override(901, heavy, "m_LocalPosition.z", "0.01"), PrefabProject.Override(901, heavy, "m_LocalScale.z", "0.08")));

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(Oil(scene).Name, Is.EqualTo("Heavy Oil (1)"));
            Assert.That(Oil(scene).Phase.RestDensity, Is.EqualTo(950f), "the variant's override");
            Assert.That(Oil(scene).Phase.Viscosity, Is.EqualTo(0.1f), "the base's viscosity");
            Assert.That(Oil(scene).Center.Z, Is.EqualTo(0.01f).Within(1e-6f), "the scene's override");
        }

        /// <summary>A nested box's value that the outer prefab overrides is named at that override, in the outer prefab.</summary>
        [Test]
        public void ANestedPrefabsOverrideIsNamedAtItsLineInTheOuterPrefab()
        {
            var project = new PrefabProject();
            string rig = NestedRig(project, oil => PrefabProject.Override(OilSpawnBox, oil, "spawn.Phase.RestDensity", "-5"));
            project.ReplaceOilWith(PrefabProject.Instance(800, rig, "Rig", 11, 12));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("--- !u!1001 &800")} (the value at Assets/Prefabs/Rig.prefab:" +
                $"{project.LineIn("Rig", "      value: -5")}, which the instance does not override): GameObject 'Oil', SpawnBox.spawn.Phase.RestDensity"));
        }

        /// <summary>Unity refuses a prefab that nests itself; following it would never end.</summary>
        [Test]
        public void APrefabThatNestsItselfIsRefused()
        {
            var project = new PrefabProject();
            string loop = project.AddPrefab("Loop", project.Document(OilObject) + project.Document(OilTransform).Replace("m_Children: []", "m_Children:\n  - {fileID: 701}") +
                project.Document(OilSpawnBox) + PrefabProject.Instance(700, "SELF", "Inner", OilObject, OilTransform)
                    .Replace("m_TransformParent: {fileID: 0}", $"m_TransformParent: {{fileID: {OilTransform}}}"));
            string file = Path.Combine(project.Project.Root, "Assets", "Prefabs", "Loop.prefab");
            File.WriteAllText(file, File.ReadAllText(file).Replace("SELF", loop));
            project.ReplaceOilWith(PrefabProject.Instance(800, loop, "Loop", OilObject, OilTransform));

            var thrown = Deadline.Within(10, () => Deadline.Thrown(() => SceneLoader.Load(project.ScenePath, project.Project)), "loading the scene");

            Assert.That(thrown, Is.InstanceOf<SceneException>());
            Assert.That(thrown!.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("--- !u!1001 &800")}: PrefabInstance 'Loop' of " +
                "Assets/Prefabs/Loop.prefab: its prefab cannot be read (Assets/Prefabs/Loop.prefab nests itself)"));
        }

        /// <summary>Nesting multiplies what a prefab builds: twenty levels of prefabs that each hold two instances of the
        /// one below would build a million copies of the Oil box (a chain of 2 000 built 4 million objects in nearly 5
        /// minutes). The reader stops counting at its limit and refuses the scene.</summary>
        [Test]
        public void PrefabsNestedManyTimesOverAreRefusedAtTheObjectLimit()
        {
            var project = new PrefabProject();
            string inner = OilPrefab(project);
            long rootObject = OilObject, rootTransform = OilTransform;
            for (int level = 1; level <= 20; level++)
            {
                string twice = string.Concat(new[] { 700L, 710L }.Select(id => PrefabProject.Instance(id, inner, $"Half {id}", rootObject, rootTransform)
                    .Replace("m_TransformParent: {fileID: 0}", "m_TransformParent: {fileID: 12}")));
                inner = project.AddPrefab($"Level {level}", RigRoot(project, child: 701).Replace("  - {fileID: 701}\n", "  - {fileID: 701}\n  - {fileID: 711}\n") + twice);
                (rootObject, rootTransform) = (11, 12);
            }
            project.ReplaceOilWith(PrefabProject.Instance(800, inner, "Tree", rootObject, rootTransform));

            var thrown = Deadline.Within(10, () => Deadline.Thrown(() => SceneLoader.Load(project.ScenePath, project.Project)), "loading the scene");

            Assert.That(thrown, Is.InstanceOf<SceneException>());
            Assert.That(thrown!.Message, Does.StartWith($"{project.ScenePath}: its prefab instances build more than 50000 objects, every level of nesting counted"));
        }

        /// <summary>Each level of nesting is read within the one above it: a chain of 20 000 prefabs, each nesting the
        /// next, exhausted the stack and ended the program. Past 64 levels the scene is refused.</summary>
        [Test]
        public void PrefabsNestedDeeperThanTheLimitAreRefused()
        {
            var project = new PrefabProject();
            string inner = OilPrefab(project);
            long rootObject = OilObject, rootTransform = OilTransform;
            for (int level = 1; level <= 70; level++)
            {
                inner = project.AddPrefab($"Level {level}", RigRoot(project, child: 701) + PrefabProject.Instance(700, inner, "Inner", rootObject, rootTransform)
                    .Replace("m_TransformParent: {fileID: 0}", "m_TransformParent: {fileID: 12}"));
                (rootObject, rootTransform) = (11, 12);
            }
            project.ReplaceOilWith(PrefabProject.Instance(800, inner, "Chain", rootObject, rootTransform));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Is.EqualTo($"{project.ScenePath}: its prefab instances nest prefabs more than 64 levels deep " +
                "(Assets/Prefabs/Level 6.prefab at level 65); the reader refuses nesting that deep"));
        }

        /// <summary>Renaming a GameObject inside an instance writes an m_Name override too, after the root's: the instance is
        /// named by the override of its prefab's root GameObject, not by the last one.</summary>
        [Test]
        public void AnInstanceIsNamedByItsRootsNameNotAChildsRename()
        {
            var project = new PrefabProject();
            string rig = NestedRig(project);
            File.WriteAllText(Path.Combine(project.Project.Root, "Assets", "Prefabs", "Oil.prefab"), "");
            project.ReplaceOilWith(PrefabProject.Instance(800, rig, "Rig Left", 11, 12, PrefabProject.Override(4242, rig, "m_Name", "Handle")));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("--- !u!1001 &800")}: PrefabInstance 'Rig Left' of " +
                "Assets/Prefabs/Rig.prefab: its prefab cannot be read ("));
        }

        /// <summary>An override in a prefab holding the fluid's components whose object the prefab does not hold may be
        /// meant for a fluid field: refused, where Unity ignores it.</summary>
        [Test]
        public void AnOverrideOfAnObjectThePrefabDoesNotHoldIsRefusedWhereItHoldsTheFluid()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform, PrefabProject.Override(4242, oil, "spawn.Jitter", "0.1")));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("      propertyPath: spawn.Jitter")}: PrefabInstance 'Oil' of " +
                "Assets/Prefabs/Oil.prefab overrides spawn.Jitter of &4242, which Assets/Prefabs/Oil.prefab does not hold"));
        }

        /// <summary>A model placed as a prefab instance has its objects from its importer, which the reader cannot run: a
        /// SpawnBox placed under one is refused naming the instance and the model.</summary>
        [Test]
        public void ASpawnBoxUnderAModelsInstanceIsRefusedNamingIt()
        {
            var project = new PrefabProject();
            string rock = project.AddAsset("Rock.fbx", "Kaydara FBX Binary", "ModelImporter");
            project.Edit(project.Document(OilTransform), project.Document(OilTransform).Replace("m_Father: {fileID: 0}", "m_Father: {fileID: 701}"));
            project.Edit($"  - {{fileID: {OilTransform}}}\n", "  - {fileID: 701}\n");
            project.Edit("--- !u!1660057539", PrefabProject.Instance(700, rock, "Rock", 919132149155446097, -8679921383154817045) + "--- !u!1660057539");

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf($"--- !u!114 &{OilSpawnBox}")}: the SpawnBox of GameObject 'Oil', " +
                "which lies under a GameObject of PrefabInstance 'Rock' of Assets/Prefabs/Rock.fbx that places it, which the reader cannot build"));
            Assert.That(e.Message, Does.Contain(Unpack));
        }

        /// <summary>An instance whose source is no prefab (a material, by a hand-edited guid) in a prefab holding the Oil
        /// box: the prefab is refused for it, and the material is not called a model.</summary>
        [Test]
        public void APrefabNestingAnInstanceOfAMaterialIsRefusedNamingIt()
        {
            var project = new PrefabProject();
            string material = project.AddAsset("Paint.mat", "%YAML 1.1\n", "NativeFormatImporter");
            string oil = project.AddPrefab("Oil", project.Document(OilObject) +
                project.Document(OilTransform).Replace("m_Children: []", "m_Children:\n  - {fileID: 701}") + project.Document(OilSpawnBox) +
                PrefabProject.Instance(700, material, "Paint", 1, 2).Replace("m_TransformParent: {fileID: 0}", $"m_TransformParent: {{fileID: {OilTransform}}}"));
            project.ReplaceOilWith(PrefabProject.Instance(800, oil, "Oil", OilObject, OilTransform));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("--- !u!1001 &800")}: PrefabInstance 'Oil' of Assets/Prefabs/Oil.prefab " +
                "holds a SpawnBox on its GameObject 'Oil'; the reader cannot build it: Assets/Prefabs/Paint.mat is neither a prefab nor a model, " +
                "so no objects can be built from it"));
        }

        /// <summary>An override names an object of the instance's own prefab; one naming another asset's object (here the
        /// SpawnBox of a copy of its prefab) changes nothing in Unity and, in a prefab holding the fluid, is refused.</summary>
        [Test]
        public void AnOverrideOfAnotherAssetsObjectIsRefusedWhereThePrefabHoldsTheFluid()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            string other = project.AddPrefab("Other Oil", project.Document(OilObject) + project.Document(OilTransform) + project.Document(OilSpawnBox));
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform,
                PrefabProject.Override(OilSpawnBox, other, "spawn.Phase.RestDensity", "850")));

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("      propertyPath: spawn.Phase.RestDensity")}: PrefabInstance 'Oil' of " +
                $"Assets/Prefabs/Oil.prefab overrides spawn.Phase.RestDensity of &{OilSpawnBox} of another asset (guid {other}); " +
                "an instance's overrides name objects of its own prefab, Assets/Prefabs/Oil.prefab"));
        }

        /// <summary>A prefab file that cannot be read (emptied here) may hold the fluid's components: refused, not guessed.</summary>
        [Test]
        public void AnUnreadablePrefabIsRefusedForWhatItMayHold()
        {
            var project = new PrefabProject();
            string oil = OilPrefab(project);
            project.ReplaceOilWith(PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform));
            File.WriteAllText(Path.Combine(project.Project.Root, "Assets", "Prefabs", "Oil.prefab"), "");

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(project.ScenePath, project.Project))!;

            Assert.That(e.Message, Does.Contain($"{project.ScenePath}:{project.LineOf("--- !u!1001 &700")}: PrefabInstance 'Oil' of " +
                "Assets/Prefabs/Oil.prefab: its prefab cannot be read ("));
            Assert.That(e.Message, Does.Contain("is empty or not a regular file"));
            Assert.That(e.Message, Does.Contain("so whether it holds the fluid's components cannot be told"));
            Assert.That(e.Message, Does.Contain(Unpack));
        }

        /// <summary>A prefab that holds none of the fluid's components and places none (a prop, a light) is not the
        /// reader's business: it is neither built nor held to the integrity check (this one has two documents under one
        /// anchor, which the check refuses in a prefab the fluid is built from).</summary>
        [Test]
        public void APrefabWithoutTheFluidsComponentsIsReadPast()
        {
            var project = new PrefabProject();
            string prop = project.AddPrefab("Prop", project.Document(OilObject).Replace($"  - component: {{fileID: {OilSpawnBox}}}\n", "")
                .Replace("m_Name: Oil", "m_Name: Prop") + project.Document(OilTransform) + project.Document(OilTransform));
            project.Edit("--- !u!1660057539", PrefabProject.Instance(700, prop, "Prop", OilObject, OilTransform) + "--- !u!1660057539");
            project.Edit("  m_Roots:\n", "  m_Roots:\n  - {fileID: 701}\n");

            var scene = SceneLoader.Load(project.ScenePath, project.Project);

            Assert.That(scene.Description.Phases().Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water", "Oil" }));
        }

        /// <summary>A prop's prefab is read for what it holds, not built: a site of eight warehouses of sixty pallets of
        /// sixty crates (58 000 objects built) was built only to be read past, and refused at the object limit.</summary>
        [Test]
        public void ALargePropIsReadPastWithoutBeingBuilt()
        {
            var project = new PrefabProject();
            string Props(string name, string inner, long innerObject, long innerTransform, int count)
            {
                var children = string.Concat(Enumerable.Range(0, count).Select(i => $"  - {{fileID: {1001 + 10 * i}}}\n"));
                string root = RigRoot(project, child: 0).Replace("  - {fileID: 0}\n", children).Replace("m_Name: Rig", $"m_Name: {name}");
                return project.AddPrefab(name, root + string.Concat(Enumerable.Range(0, count).Select(i =>
                    PrefabProject.Instance(1000 + 10 * i, inner, $"{name} {i}", innerObject, innerTransform)
                        .Replace("m_TransformParent: {fileID: 0}", "m_TransformParent: {fileID: 12}"))));
            }
            string crate = project.AddPrefab("Crate", RigRoot(project, child: 0).Replace("  - {fileID: 0}\n", "").Replace("m_Children:\n", "m_Children: []\n")
                .Replace("m_Name: Rig", "m_Name: Crate"));
            string pallet = Props("Pallet", crate, 11, 12, 60);
            string warehouse = Props("Warehouse", pallet, 11, 12, 60);
            string site = Props("Site", warehouse, 11, 12, 8);
            project.Edit("--- !u!1660057539", PrefabProject.Instance(700, site, "Site", 11, 12) + "--- !u!1660057539");
            project.Edit("  m_Roots:\n", "  m_Roots:\n  - {fileID: 701}\n");

            var scene = Deadline.Within(10, () => SceneLoader.Load(project.ScenePath, project.Project), "loading the scene");

            Assert.That(scene.Description.Phases().Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water", "Oil" }));
        }

        /// <summary>Oil.prefab: OilAndWater's Oil box as it stands in the scene; returns its guid.</summary>
        static string OilPrefab(PrefabProject project) =>
            project.AddPrefab("Oil", project.Document(OilObject) + project.Document(OilTransform) + project.Document(OilSpawnBox));

        /// <summary>Pair.prefab: a rig at the origin (&amp;11, Transform &amp;12) with the Oil box as its one child.</summary>
        static string PairPrefab(PrefabProject project) =>
            project.AddPrefab("Pair", RigRoot(project, child: OilTransform) +
                project.Document(OilObject) + project.Document(OilTransform).Replace("m_Father: {fileID: 0}", "m_Father: {fileID: 12}") +
                project.Document(OilSpawnBox));

        /// <summary>A rig's root GameObject &amp;11 and Transform &amp;12 at the origin, unscaled, with one child Transform.</summary>
        static string RigRoot(PrefabProject project, long child) =>
            project.Document(OilObject).Replace($"  - component: {{fileID: {OilSpawnBox}}}\n", "").Replace("m_Name: Oil", "m_Name: Rig")
                .Replace($"&{OilObject}", "&11").Replace($"{{fileID: {OilTransform}}}", "{fileID: 12}") +
            project.Document(OilTransform).Replace($"&{OilTransform}", "&12").Replace($"{{fileID: {OilObject}}}", "{fileID: 11}")
                .Replace("m_LocalPosition: {x: 0.15, y: 0.1, z: 0}", "m_LocalPosition: {x: 0, y: 0, z: 0}")
                .Replace("m_LocalScale: {x: 0.3, y: 0.2, z: 0.12}", "m_LocalScale: {x: 1, y: 1, z: 1}")
                .Replace("m_Children: []", $"m_Children:\n  - {{fileID: {child}}}");

        /// <summary>Rig.prefab: its own root (&amp;11, Transform &amp;12) with an instance &amp;700 of Oil.prefab, which
        /// holds the Oil box, as its one child, with the overrides <paramref name="overrides"/> writes given Oil.prefab's guid.</summary>
        static string NestedRig(PrefabProject project, Func<string, string>? overrides = null)
        {
            string oil = OilPrefab(project);
            return project.AddPrefab("Rig", RigRoot(project, child: 701) +
                PrefabProject.Instance(700, oil, "Oil", OilObject, OilTransform, overrides?.Invoke(oil) ?? "").Replace("m_TransformParent: {fileID: 0}", "m_TransformParent: {fileID: 12}"));
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

            /// <summary>The 1-based line of <paramref name="text"/> in Assets/Prefabs/<paramref name="prefab"/>.prefab.</summary>
            public int LineIn(string prefab, string text) =>
                Array.IndexOf(File.ReadAllLines(Path.Combine(_root, "Assets", "Prefabs", prefab + ".prefab")), text) + 1;

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
            public string AddPrefab(string name, string documents) =>
                AddAsset(name + ".prefab", "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n" + documents, "PrefabImporter");

            /// <summary>Writes Assets/Prefabs/<paramref name="fileName"/> and its .meta for <paramref name="importer"/>;
            /// returns its guid.</summary>
            public string AddAsset(string fileName, string text, string importer)
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
                File.WriteAllText(Path.Combine(folder, fileName), text);
                File.WriteAllText(Path.Combine(folder, fileName + ".meta"), $"fileFormatVersion: 2\nguid: {guid}\n{importer}:\n" +
                    "  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n");
                return guid;
            }

            /// <summary>A PrefabInstance &amp;<paramref name="id"/> of the prefab, named <paramref name="name"/>, with
            /// <paramref name="overrides"/> after its name, and the stripped Transform &amp;(id + 1) of its root, as Unity
            /// writes them.</summary>
            public static string Instance(long id, string prefabGuid, string name, long rootObject, long rootTransform, params string[] overrides) =>
                $"--- !u!1001 &{id}\nPrefabInstance:\n  m_ObjectHideFlags: 0\n  serializedVersion: 2\n  m_Modification:\n" +
                "    serializedVersion: 3\n    m_TransformParent: {fileID: 0}\n    m_Modifications:\n" +
                Override(rootObject, prefabGuid, "m_Name", name) + string.Concat(overrides) +
                "    m_RemovedComponents: []\n    m_RemovedGameObjects: []\n" +
                "    m_AddedGameObjects: []\n    m_AddedComponents: []\n" +
                $"  m_SourcePrefab: {{fileID: 100100000, guid: {prefabGuid}, type: 3}}\n" +
                Stripped(4, id + 1, rootTransform, prefabGuid, id);

            /// <summary>One entry of an instance's m_Modifications: the field at <paramref name="propertyPath"/> of the
            /// prefab's object &amp;<paramref name="target"/> takes <paramref name="value"/>.</summary>
            public static string Override(long target, string prefabGuid, string propertyPath, string value) =>
                $"    - target: {{fileID: {target}, guid: {prefabGuid}, type: 3}}\n      propertyPath: {propertyPath}\n      value: {value}\n" +
                "      objectReference: {fileID: 0}\n";

            public static string Stripped(int classId, long id, long source, string prefabGuid, long instance) =>
                $"--- !u!{classId} &{id} stripped\n{(classId == 1 ? "GameObject" : "Transform")}:\n" +
                $"  m_CorrespondingSourceObject: {{fileID: {source}, guid: {prefabGuid}, type: 3}}\n" +
                $"  m_PrefabInstance: {{fileID: {instance}}}\n  m_PrefabAsset: {{fileID: 0}}\n";

            static string NewGuid() => Guid.NewGuid().ToString("N");
        }
    }
}
