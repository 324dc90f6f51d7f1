using System;
using System.IO;
using System.Linq;
using System.Reflection;
using NUnit.Framework;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Integrity
{
    /// <summary>
    /// Each setting is declared once (<see cref="SettingAttribute"/> on a FluidSettings field): the README's table,
    /// the validation, the scenes and the headless scene reader all agree with that declaration, for every field.
    /// </summary>
    public sealed class SettingsDeclarationTests
    {
        const string Begin = "<!-- FluidSettings table: generated from the declarations, checked by SettingsDeclarationTests -->\n";
        const string End = "<!-- end of FluidSettings table -->";

        static DeclaredSetting[] Declared => SettingRules.Declared(typeof(FluidSettings)).ToArray();

        [Test]
        public void EverySettingsFieldIsDeclared()
        {
            var undeclared = typeof(FluidSettings).GetFields(BindingFlags.Public | BindingFlags.Instance)
                .Where(f => f.GetCustomAttribute<SettingAttribute>() == null).Select(f => f.Name);
            Assert.That(undeclared, Is.Empty, "a public FluidSettings field without [Setting] has no range, unit or tooltip");
            Assert.That(typeof(FluidSettings).GetProperties(BindingFlags.Public | BindingFlags.Instance), Is.Empty,
                "Unity serializes fields, not properties: a settings property would never reach a scene");
        }

        [Test]
        public void TheReadmeTableIsTheDeclarations() =>
            ReadmeTable.AssertIsTheDeclarations(Begin, End, typeof(FluidSettings), "FluidSettings");

        [Test]
        public void TheDefaultsAreValid()
        {
            Assert.That(new FluidSettings().Validate().Select(e => e.Message), Is.Empty);
        }

        [TestCaseSource(nameof(NumberFields))]
        public void AValueBeyondTheDeclaredRangeIsRefusedWithThatRange(string field)
        {
            var info = typeof(FluidSettings).GetField(field)!;
            var declaration = info.GetCustomAttribute<SettingAttribute>()!;
            foreach (double wrong in new[] { declaration.Max * 2 + 1, declaration.Min - 1 - Math.Abs(declaration.Min) })
            {
                var settings = new FluidSettings();
                info.SetValue(settings, info.FieldType == typeof(int) ? (object)(int)Math.Max(int.MinValue, Math.Min(int.MaxValue, wrong)) : (float)wrong);
                var errors = settings.Validate().Where(e => e.Field == "Settings." + field).ToList();
                Assert.That(errors, Has.Count.EqualTo(1), $"{field} = {wrong}");
                Assert.That(errors[0].Message, Does.Contain($"FluidSettings: {field} must be in"));
                if (field != nameof(FluidSettings.SmoothingRadius)) // its range is also relative to the spacing
                    Assert.That(errors[0].Message, Does.Contain(declaration.RangeText), field);
            }
        }

        [Test]
        public void AnUndefinedSolverIsRefusedNamingTheChoices()
        {
            var settings = new FluidSettings { PressureSolver = (PressureSolver)7 };
            var error = settings.Validate().Single();
            Assert.That(error.Message, Is.EqualTo("FluidSettings: PressureSolver must be one of 0 (Wcsph), 1 (Dfsph) (was 7)"));
        }

        [Test]
        public void EveryShippedSceneSerializesEveryDeclaredSettingInDeclarationOrder()
        {
            foreach (string scene in ShippedScenes.All())
            {
                var lines = File.ReadAllLines(scene);
                int at = Array.IndexOf(lines, "  " + RuntimeScripts.Settings + ":");
                Assert.That(at, Is.GreaterThan(0), $"{Path.GetFileName(scene)} has no Fluid.settings");
                var keys = lines.Skip(at + 1).TakeWhile(l => l.StartsWith("    ", StringComparison.Ordinal))
                    .Where(l => !l.StartsWith("      ", StringComparison.Ordinal))
                    .Select(l => l.Trim().Split(':')[0]);
                Assert.That(keys, Is.EqualTo(Declared.Select(d => d.Field.Name)), Path.GetFileName(scene));
            }
        }

        [TestCaseSource(nameof(NumberFields))]
        public void TheSceneReaderReadsEachDeclaredField(string field)
        {
            var info = typeof(FluidSettings).GetField(field)!;
            var loaded = SceneLoader.Load(RunnerPaths.Scene("PlayModeTest"), RunnerPaths.Project).Description.Settings;
            object current = info.GetValue(loaded)!;
            string text = Convert.ToString(current, System.Globalization.CultureInfo.InvariantCulture)!;
            // A distinct value inside the range, so that the check sees this very field read.
            object edited = info.FieldType == typeof(int) ? (object)((int)current == 1 ? 2 : (int)current - 1) : (float)current * 0.875f;
            // The support stays within the cubic spline's 2 to 2.25 spacings (FluidSettings.MaxCubicSplineSupportRatio).
            if (field == nameof(FluidSettings.SmoothingRadius)) edited = loaded.ParticleSpacing * 2.2f;
            if (field == nameof(FluidSettings.ParticleSpacing)) edited = (float)current * 0.95f;
            string editedText = Convert.ToString(edited, System.Globalization.CultureInfo.InvariantCulture)!;
            string path = RunnerPaths.EditedScene("PlayModeTest", $"    {field}: {text}\n", $"    {field}: {editedText}\n");
            var read = SceneLoader.Load(path, RunnerPaths.Project).Description.Settings;
            Assert.That(info.GetValue(read), Is.EqualTo(edited), field);
        }

        static string[] NumberFields() => SettingRules.Declared(typeof(FluidSettings))
            .Where(d => d.Field.FieldType == typeof(float) || d.Field.FieldType == typeof(int))
            .Select(d => d.Field.Name).ToArray();
    }
}
