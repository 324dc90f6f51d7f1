using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Reflection;
using NUnit.Framework;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Core.Simulation;
using SphFluid.Tests.Runner;
using SphFluid.UnityFiles.Scenes;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Tests.Integrity
{
    /// <summary>
    /// Each spawn-box and phase value is declared once (<see cref="SettingAttribute"/> on a field of FluidBlock
    /// or of its PhaseDescription block), as the solver settings are: the README's table, the validation, the scenes and
    /// the headless scene reader all agree with that declaration, for every field.
    /// </summary>
    public sealed class SpawnBoxDeclarationTests
    {
        const string Begin = "<!-- SpawnBox table: generated from the declarations, checked by SpawnBoxDeclarationTests -->\n";
        const string End = "<!-- end of SpawnBox table -->";

        static SettingPath[] Declared => SettingRules.DeclaredPaths(typeof(FluidBlock)).ToArray();

        [Test]
        public void EveryPhaseAndSpawnFieldIsDeclared()
        {
            var phaseFields = typeof(PhaseDescription).GetFields(BindingFlags.Public | BindingFlags.Instance);
            Assert.That(phaseFields.Where(f => f.GetCustomAttribute<SettingAttribute>() == null).Select(f => f.Name), Is.Empty,
                "a public PhaseDescription field without [Setting] has no range, unit or tooltip");
            Assert.That(typeof(PhaseDescription).GetProperties(BindingFlags.Public | BindingFlags.Instance), Is.Empty,
                "Unity serializes fields, not properties: a phase property would never reach a scene");
            var boxFields = typeof(FluidBlock).GetFields(BindingFlags.Public | BindingFlags.Instance);
            Assert.That(boxFields.Where(f => f.GetCustomAttribute<SettingAttribute>() == null && !SettingRules.IsBlock(f.FieldType)).Select(f => f.Name), Is.Empty,
                "a public FluidBlock field is either declared or a declared block");
            // The placement is the Transform's and the name the GameObject's: properties, so Unity never serializes them.
            Assert.That(typeof(FluidBlock).GetProperties(BindingFlags.Public | BindingFlags.Instance).Select(p => p.Name),
                Is.EquivalentTo(new[] { "Name", "Center", "Rotation", "Size" }));
            Assert.That(Declared.Select(d => d.Path), Has.Member("Phase.RestDensity").And.Member("Jitter"));
        }

        [Test]
        public void TheReadmeTableIsTheDeclarations() =>
            ReadmeTable.AssertIsTheDeclarations(Begin, End, typeof(FluidBlock), "SpawnBox");

        [Test]
        public void TheDefaultsAreValid()
        {
            var errors = new List<ValidationError>();
            var box = new FluidBlock();
            SettingRules.ValidateAll(box, errors, "SpawnBox", "");
            SettingRules.ValidateAll(box.Phase, errors, "SpawnBox", "Phase.");
            Assert.That(errors.Select(e => e.Message), Is.Empty);
        }

        [TestCaseSource(nameof(NumberPaths))]
        public void AValueBeyondTheDeclaredRangeIsRefusedWithThatRange(string path)
        {
            var declared = Declared.Single(d => d.Path == path);
            var d = declared.Declaration;
            foreach (double wrong in new[] { d.Max * 2 + 1, d.Min - 1 - Math.Abs(d.Min) })
            {
                var scene = SimulationTestScenes.SingleWater();
                declared.SetValue(scene.SpawnBoxes[0], declared.Field.FieldType == typeof(int) ? (object)(int)wrong : (float)wrong);
                var errors = scene.Validate().Where(e => e.Field == "SpawnBoxes[0]." + path).ToList();
                Assert.That(errors, Has.Count.EqualTo(1), $"{path} = {wrong}");
                Assert.That(errors[0].Message, Does.StartWith($"SpawnBox 'Water': {declared.Field.Name} must be in {d.RangeText} (was "), path);
            }
        }

        [Test]
        public void AnEmptyOrOverlongPhaseNameIsRefusedWithTheRange()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes[0].Phase.Name = "";
            Assert.That(scene.Validate().Select(e => e.Message), Has.Member("SpawnBox 'Water': Name must be non-empty, of length in [1, 256] (was empty)"));
            scene.SpawnBoxes[0].Phase.Name = new string('w', 257);
            Assert.That(scene.Validate().Select(e => e.Message), Has.Member("SpawnBox 'Water': Name must have a length in [1, 256] (was 257)"));
        }

        [Test]
        public void EachColourChannelIsRefusedByName()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes[0].Phase.Color = new SettingColor(0.5f, -0.25f, 0.5f, 1.5f);
            var errors = scene.Validate();
            Assert.That(errors.Select(e => e.Field), Is.EqualTo(new[] { "SpawnBoxes[0].Phase.Color.g", "SpawnBoxes[0].Phase.Color.a" }));
            Assert.That(errors[0].Message, Is.EqualTo("SpawnBox 'Water': Color.g must be in [0, 1] (was -0.25)"));
        }

        [Test]
        public void BoxesOfOnePhaseMustAgreeOnEveryDeclaredPhaseValue()
        {
            foreach (var declared in SettingRules.Declared(typeof(PhaseDescription)).Where(d => d.Field.Name != nameof(PhaseDescription.Name)))
            {
                var scene = SimulationTestScenes.OilOnWater();
                var first = scene.SpawnBoxes[0].Phase;
                var second = first.Clone();
                object? value = declared.Field.GetValue(second);
                declared.Field.SetValue(second, value switch
                {
                    float f => f == 0f ? 0.01f : f * 0.875f,
                    SettingColor c => new SettingColor(c.r * 0.5f, c.g, c.b, c.a),
                    _ => throw new NotSupportedException(declared.Field.FieldType.Name),
                });
                Assert.That(first.SameDefinition(second), Is.False, declared.Field.Name);
                Assert.That(first.SameDefinition(first.Clone()), Is.True);
            }
        }

        [Test]
        public void EveryShippedSceneSerializesEverySpawnBoxValueInDeclarationOrder()
        {
            string guid = RunnerPaths.Project.ScriptGuid(RuntimeScripts.SpawnBox);
            var blocks = new HashSet<string>(Declared.SelectMany(d => Prefixes(d.Path)));
            var expected = new List<string>();
            foreach (var d in Declared)
            {
                foreach (string block in Prefixes(d.Path))
                    if (!expected.Contains(block)) expected.Add(block);
                expected.Add(d.Path);
            }
            int boxes = 0;
            foreach (string file in ShippedScenes.All())
            {
                foreach (var box in UnityScene.Load(file).Behaviours(guid))
                {
                    var spawn = box.Root[RuntimeScripts.Spawn];
                    Assert.That(spawn, Is.Not.Null, $"{Path.GetFileName(file)}:{box.Line} has no SpawnBox.{RuntimeScripts.Spawn}");
                    Assert.That(Keys(spawn, "", blocks), Is.EqualTo(expected), $"{Path.GetFileName(file)}:{box.Line}");
                    Assert.That(box.Root.Keys.Where(k => !k.StartsWith("m_", StringComparison.Ordinal)), Is.EqualTo(new[] { RuntimeScripts.Spawn }),
                        $"{Path.GetFileName(file)}:{box.Line}: SpawnBox serializes its declared block only");
                    boxes++;
                }
            }
            Assert.That(boxes, Is.EqualTo(12), "the shipped scenes' spawn boxes: 10 in the demo, 2 in the URP sample");
        }

        [TestCaseSource(nameof(ReadablePaths))]
        public void TheSceneReaderReadsEachDeclaredValue(string path)
        {
            var declared = Declared.Single(d => d.Path == path);
            var loaded = SceneLoader.Load(RunnerPaths.Scene("PlayModeTest"), RunnerPaths.Project).Description;
            var box = loaded.SpawnBoxes[0];
            object current = declared.GetValue(box);
            object edited = current switch
            {
                int i => i == 1 ? 2 : i - 1,
                float _ when path == "Phase." + nameof(PhaseDescription.ParticleMass) =>
                    1.01f * box.Phase.RestDensity * MathF.Pow(loaded.Settings.ParticleSpacing, 3), // near the derived mass
                float f => f == 0f ? 0.5f : f * 0.875f,
                _ => throw new NotSupportedException(current.GetType().Name),
            };
            string indent = new string(' ', 4 + 2 * path.Count(c => c == '.'));
            string leaf = declared.Field.Name;
            string scene = RunnerPaths.EditedScene("PlayModeTest", $"\n{indent}{leaf}: {Text(current)}\n", $"\n{indent}{leaf}: {Text(edited)}\n");
            var read = SceneLoader.Load(scene, RunnerPaths.Project).Description.SpawnBoxes[0];
            Assert.That(declared.GetValue(read), Is.EqualTo(edited), path);
        }

        [Test]
        public void AValueOutOfRangeInASceneNamesItsFileLineFieldAndRange()
        {
            string path = RunnerPaths.EditedScene("PlayModeTest", "\n    Jitter: 0.05\n", "\n    Jitter: 0.75\n");
            int line = Array.IndexOf(File.ReadAllLines(path), "    Jitter: 0.75") + 1;

            var error = Assert.Throws<SceneException>(() => SceneLoader.Load(path, RunnerPaths.Project));

            Assert.That(error.Message, Does.StartWith(path + ": the fluid scene is invalid:"));
            Assert.That(error.Message, Does.Contain(
                $"{path}:{line}: GameObject 'Water', SpawnBox.spawn.Jitter: Jitter must be in [0, 0.5] particle spacings (was 0.75)"));
        }

        static string Text(object value) => string.Format(CultureInfo.InvariantCulture, "{0}", value);

        static IEnumerable<string> Prefixes(string path)
        {
            string[] parts = path.Split('.');
            for (int i = 1; i < parts.Length; i++) yield return string.Join(".", parts.Take(i));
        }

        /// <summary>The serialized keys below a SpawnBox's block, as paths, descending into declared blocks only
        /// (not into a vector's x, y, z or a colour's r, g, b, a).</summary>
        static List<string> Keys(UnityYamlNode node, string prefix, HashSet<string> blocks)
        {
            var keys = new List<string>();
            foreach (var entry in node.Entries)
            {
                string path = prefix + entry.Key;
                keys.Add(path);
                if (blocks.Contains(path)) keys.AddRange(Keys(entry.Value, path + ".", blocks));
            }
            return keys;
        }

        static string[] ReadablePaths() => SettingRules.DeclaredPaths(typeof(FluidBlock))
            .Where(d => d.Field.FieldType == typeof(float) || d.Field.FieldType == typeof(int))
            .Select(d => d.Path).ToArray();

        static string[] NumberPaths() => SettingRules.DeclaredPaths(typeof(FluidBlock))
            .Where(d => d.Field.FieldType == typeof(float) || (d.Field.FieldType == typeof(int) && d.Declaration.Max < int.MaxValue))
            .Select(d => d.Path).ToArray();
    }
}
