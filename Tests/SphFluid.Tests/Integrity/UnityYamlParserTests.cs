using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.UnityFiles.Scenes;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Tests.Integrity
{
    public sealed class UnityYamlParserTests
    {
        const string Header = "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n";

        [Test]
        public void Reads_document_headers_type_names_and_stripped_marker()
        {
            var file = UnityYamlFile.Parse(Header +
                "--- !u!29 &1\nOcclusionCullingSettings:\n  m_ObjectHideFlags: 0\n" +
                "--- !u!4 &-8840 stripped\nTransform:\n  m_PrefabInstance: {fileID: 77}\n" +
                "--- !u!1660057539 &9223372036854775807\nSceneRoots:\n  m_Roots: []\n", "a.unity");

            Assert.That(file.HasUnityHeader, Is.True);
            Assert.That(file.Documents.Select(d => d.ClassId), Is.EqualTo(new[] { 29, 4, 1660057539 }));
            Assert.That(file.Documents.Select(d => d.FileId), Is.EqualTo(new[] { 1L, -8840L, long.MaxValue }));
            Assert.That(file.Documents[0].TypeName, Is.EqualTo("OcclusionCullingSettings"));
            Assert.That(file.Documents[1].IsStripped, Is.True);
            Assert.That(file.Documents[2].Root["m_Roots"].OrFail("m_Roots").IsSequence, Is.True);
            Assert.That(file.Documents[2].Root["m_Roots"].OrFail("m_Roots").Items.Count, Is.EqualTo(0));
        }

        [Test]
        public void Reads_the_block_and_flow_forms_unity_writes()
        {
            var file = UnityYamlFile.Parse(Header +
                "--- !u!114 &5\nMonoBehaviour:\n" +
                "  m_Script: {fileID: 11500000, guid: 0123456789abcdef0123456789abcdef, type: 3}\n" +
                "  m_Name: \n" +
                "  label: 'it''s: quoted'\n" +
                "  escaped: \"tab\\there \\u00e9\"\n" +
                "  near clip plane: 0.3\n" +
                "  bounds: {x: 10, y: -5.5, z: 1e-3}\n" +
                "  tint: {r: 1, g: 0.5, b: 0.25, a: 1}\n" +
                "  apis: 02000000\n" +
                "  weights:\n  - 0.5\n  - 1\n" +
                "  emitters:\n" +
                "  - origin: {x: 0, y: 1, z: 0}\n    radius: 2\n    tags:\n    - a\n    - b\n" +
                "  - origin: {x: 3, y: 1, z: -2}\n    radius: 0.75\n    tags: []\n" +
                "  collisionMask:\n    serializedVersion: 2\n    m_Bits: 4294967295\n" +
                "  note: a long plain string\n    that Unity wrapped\n" +
                "  empty: {}\n" +
                "  tagged: Water #1\n" +
                "  last: Infinity\n", "b.unity");

            var root = file.Find(5).OrFail("document 5").Root;
            var script = root.GetReference("m_Script").OrFail("m_Script");
            Assert.That(script.FileId, Is.EqualTo(11500000L));
            Assert.That(script.Guid, Is.EqualTo("0123456789abcdef0123456789abcdef"));
            Assert.That(script.Type, Is.EqualTo(3));
            Assert.That(root["m_Name"].OrFail("m_Name").IsEmpty, Is.True);
            Assert.That(root.GetString("label"), Is.EqualTo("it's: quoted"));
            Assert.That(root.GetString("escaped"), Is.EqualTo("tab\there \u00e9"));
            Assert.That(root.GetFloat("near clip plane"), Is.EqualTo(0.3f));
            Assert.That(root.GetVector3("bounds"), Is.EqualTo(new Vector3(10f, -5.5f, 0.001f)));
            Assert.That(root.GetColor("tint"), Is.EqualTo(new Vector4(1f, 0.5f, 0.25f, 1f)));
            Assert.That(root.GetString("apis"), Is.EqualTo("02000000"));
            Assert.That(root["weights"].OrFail("weights").Items.Select(i => i.Value), Is.EqualTo(new[] { "0.5", "1" }));
            Assert.That(root.GetFloat("emitters[1].radius"), Is.EqualTo(0.75f));
            Assert.That(root.GetVector3("emitters[1].origin"), Is.EqualTo(new Vector3(3f, 1f, -2f)));
            Assert.That(root.At("emitters[0].tags").OrFail("emitters[0].tags").Items.Select(i => i.Value), Is.EqualTo(new[] { "a", "b" }));
            Assert.That(root.At("emitters[1].tags").OrFail("emitters[1].tags").Items.Count, Is.EqualTo(0));
            Assert.That(root.GetLong("collisionMask.m_Bits"), Is.EqualTo(4294967295L));
            Assert.That(root.GetString("note"), Is.EqualTo("a long plain string that Unity wrapped"));
            Assert.That(root["empty"].OrFail("empty").IsMapping, Is.True);
            Assert.That(root.GetString("tagged"), Is.EqualTo("Water"));
            Assert.That(float.IsPositiveInfinity(root.GetFloat("last")), Is.True);
            Assert.That(root.References().Select(r => r.Path), Is.EqualTo(new[] { "m_Script" }));
        }

        [Test]
        public void Reads_a_meta_file_as_plain_yaml()
        {
            var root = UnityYamlParser.ParseBlock(
                "fileFormatVersion: 2\nguid: 0123456789abcdef0123456789abcdef\nNativeFormatImporter:\n  externalObjects: {}\n" +
                "  mainObjectFileID: 2100000\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n");
            Assert.That(root.GetString("guid"), Is.EqualTo("0123456789abcdef0123456789abcdef"));
            Assert.That(root.GetLong("NativeFormatImporter.mainObjectFileID"), Is.EqualTo(2100000L));
        }

        [TestCase("--- !u!1 &1\nGameObject:\n\tm_Name: x\n", "tab")]
        [TestCase("--- !u!1 &1\nGameObject:\n  m_Name: x\n  m_Name: y\n", "duplicate key 'm_Name'")]
        [TestCase("--- !u!1 &1\nGameObject:\n  m_Name: x\n    m_Layer: 0\n", "unexpected indentation")]
        [TestCase("--- !u!1 &1\nGameObject:\n  m_Name: x\n  m_Tag: {fileID: 0\n", "unclosed '{'")]
        [TestCase("--- !u!1 &1\nGameObject:\n  m_Name: \"x\n  m_Layer: 0\n", "unclosed quoted string")]
        [TestCase("--- !u!1 1\nGameObject:\n  m_Name: x\n", "document header")]
        [TestCase("--- !u!1 &1\nGameObject:\n  m_Name: x\nTransform:\n  m_Name: y\n", "exactly one root key")]
        [TestCase("--- !u!1 &1\nGameObject:\n  m_Name: x\n <<<<<<< HEAD\n", "unexpected")]
        public void Rejects_what_unity_would_refuse_naming_file_and_line(string body, string reason)
        {
            var ex = Assert.Throws<UnityYamlException>(() => UnityYamlFile.Parse(Header + body, "Broken.unity"));
            Assert.That(ex.Message, Does.StartWith("Broken.unity:"));
            Assert.That(ex.Message, Does.Contain(reason));
            Assert.That(ex.LineNumber, Is.GreaterThan(2));
        }

        [Test]
        public void World_transform_composes_parent_position_rotation_and_scale()
        {
            const float s = 0.70710678f;
            var scene = UnityScene.Parse(Header +
                "--- !u!1 &10\nGameObject:\n  m_Component:\n  - component: {fileID: 11}\n  m_Name: Container\n  m_IsActive: 1\n" +
                "--- !u!4 &11\nTransform:\n  m_GameObject: {fileID: 10}\n" +
                "  m_LocalRotation: {x: 0, y: " + s.ToString(System.Globalization.CultureInfo.InvariantCulture) + ", z: 0, w: " + s.ToString(System.Globalization.CultureInfo.InvariantCulture) + "}\n" +
                "  m_LocalPosition: {x: 5, y: 0, z: 0}\n  m_LocalScale: {x: 2, y: 2, z: 2}\n" +
                "  m_Children:\n  - {fileID: 21}\n  m_Father: {fileID: 0}\n" +
                "--- !u!1 &20\nGameObject:\n  m_Component:\n  - component: {fileID: 21}\n  m_Name: Spawn\n  m_IsActive: 1\n" +
                "--- !u!4 &21\nTransform:\n  m_GameObject: {fileID: 20}\n" +
                "  m_LocalRotation: {x: 0, y: 0, z: 0, w: 1}\n  m_LocalPosition: {x: 1, y: 1, z: 0}\n  m_LocalScale: {x: 1, y: 3, z: 1}\n" +
                "  m_Children: []\n  m_Father: {fileID: 11}\n", "World.unity");

            var spawn = scene.FindGameObject("Spawn").OrFail("Spawn");
            var world = spawn.World;
            // 90 degrees about +Y turns local +X into world -Z (as Unity's Quaternion.Euler(0, 90, 0) * Vector3.right does).
            Assert.That(Vector3.Distance(world.Position, new Vector3(5f, 2f, -2f)), Is.LessThan(1e-5f));
            Assert.That(Vector3.Distance(world.Scale, new Vector3(2f, 6f, 2f)), Is.LessThan(1e-6f));
            Assert.That(Vector3.Distance(world.TransformDirection(Vector3.UnitX), -Vector3.UnitZ), Is.LessThan(1e-5f));
            Assert.That(Vector3.Distance(Vector3.Transform(Vector3.Zero, world.LocalToWorld), world.Position), Is.LessThan(1e-5f));
            Assert.That(spawn.Parent.OrFail("Spawn's parent").Name, Is.EqualTo("Container"));
            Assert.That(spawn.HierarchyPath, Is.EqualTo("Container/Spawn"));
            Assert.That(scene.FindGameObject("Container").OrFail("Container").Children.Select(c => c.Name), Is.EqualTo(new[] { "Spawn" }));
            Assert.That(scene.RootTransforms.Select(t => t.FileId), Is.EqualTo(new[] { 11L }));
        }

        /// <summary>A prefab override names a field by the path Unity writes (a sequence's items as Array.data[i]); a copy
        /// asks for each node by that path, and each copied node keeps its line, in the file it was copied from.</summary>
        [Test]
        public void A_copy_names_each_node_by_its_override_path_and_keeps_its_line_in_its_file()
        {
            var root = UnityYamlFile.Parse(Header +
                "--- !u!114 &5\nMonoBehaviour:\n  m_GameObject: {fileID: 4}\n  spawn:\n    size: {x: 1, y: 2}\n    seeds:\n    - 7\n    - 8\n", "a.prefab")
                .Documents[0].Root;
            var asked = new System.Collections.Generic.List<string>();

            var copy = root.CopyFrom("a.prefab", (path, node) =>
            {
                asked.Add(path);
                if (path == "spawn.seeds.Array.data[1]") return UnityYamlNode.Scalar("9", line: 41);
                return node.IsReference ? UnityYamlNode.LocalReference(14, 40) : null;
            });

            Assert.That(asked, Is.EqualTo(new[] { "", "m_GameObject", "spawn", "spawn.size", "spawn.size.x", "spawn.size.y",
                "spawn.seeds", "spawn.seeds.Array.data[0]", "spawn.seeds.Array.data[1]" }));
            Assert.That(copy.GetReference("m_GameObject")?.FileId, Is.EqualTo(14L));
            Assert.That(copy.At("spawn.seeds[1]")?.Value, Is.EqualTo("9"));
            Assert.That(copy.At("spawn.seeds[1]")?.Line, Is.EqualTo(41));
            Assert.That(copy.At("spawn.seeds[1]")?.SourceFile, Is.Null, "a replacement stays where it was");
            Assert.That(copy.At("spawn.size.y")?.Line, Is.EqualTo(root.At("spawn.size.y")?.Line));
            Assert.That(copy.At("spawn.size.y")?.SourceFile, Is.EqualTo("a.prefab"));
            Assert.That(copy.CopyFrom("b.prefab", (_, _) => null).At("spawn.size.y")?.SourceFile, Is.EqualTo("a.prefab"),
                "a copy of a copy keeps the file the value is written in");
            Assert.That(root.At("spawn.seeds[1]")?.Value, Is.EqualTo("8"), "the original is left as it was");
        }
    }
}
