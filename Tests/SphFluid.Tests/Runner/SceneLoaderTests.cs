using System;
using System.Globalization;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;

namespace SphFluid.Tests.Runner
{
    public sealed class SceneLoaderTests
    {
        [TestCaseSource(typeof(RunnerPaths), nameof(RunnerPaths.ShippedScenes))]
        public void EveryShippedSceneReadsIntoAValidDescription(string name)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene(name), RunnerPaths.Project);

            Assert.That(scene.Name, Is.EqualTo(name));
            Assert.That(scene.Description.Validate(), Is.Empty);
            Assert.That(scene.Description.SpawnBoxes.Count, Is.GreaterThan(0));
            Assert.That(SpawnLayout.TotalCount(scene.Description), Is.InRange(100, scene.Description.Settings.MaxParticles));
            Assert.That(scene.SimulatorObject, Is.EqualTo("Fluid"));
            Assert.That(scene.ContainerObject, Is.EqualTo("Container"));
        }

        [Test]
        public void OilAndWaterHasTwoPhasesSideBySideInsideItsContainer()
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project);
            var d = scene.Description;
            var phases = d.Phases();

            Assert.That(phases.Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water", "Oil" }));
            Assert.That(phases[0].RestDensity, Is.EqualTo(1000f));
            Assert.That(phases[1].RestDensity, Is.EqualTo(900f));
            Assert.That(d.Container.Size.X, Is.EqualTo(0.6f).Within(1e-6f));
            Assert.That(d.Container.Position.Y, Is.EqualTo(0.2f).Within(1e-6f), "the floor is at y = 0");
            Assert.That(d.SpawnBoxes[0].Center.X, Is.LessThan(0f), "water on the left");
            Assert.That(d.SpawnBoxes[1].Center.X, Is.GreaterThan(0f), "oil on the right");
            Assert.That(d.Settings.ParticleSpacing, Is.EqualTo(0.015f));
            Assert.That(SpawnLayout.TotalCount(d), Is.EqualTo(4160));
            Assert.That(scene.Motion.MovesContainer, Is.False);
        }

        [Test]
        public void ColoursAreStoredLinearAsConvertedFromTheInspectorsSrgb()
        {
            var d = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            // Water's inspector colour is (0.25, 0.55, 0.95): sRGB 0.25 is linear 0.0508, which the scene stores.
            Assert.That(d.Phases()[0].Color.r, Is.EqualTo(0.0508f).Within(1e-3f));
            Assert.That(d.Phases()[0].Color.r, Is.EqualTo(ColorSpace.SrgbToLinear(0.25f)).Within(1e-6f));
            Assert.That(d.Phases()[0].Color.b, Is.EqualTo(ColorSpace.SrgbToLinear(0.95f)).Within(1e-6f));
            Assert.That(d.Phases()[0].Color.a, Is.EqualTo(0.8f).Within(1e-6f));
        }

        [Test]
        public void TheRotatingContainerSpinsAndTheSphereIsDriven()
        {
            var rotating = SceneLoader.Load(RunnerPaths.Scene("RotatingContainer"), RunnerPaths.Project);
            Assert.That(rotating.Motion.MovesContainer, Is.True);
            var atRest = rotating.Motion.ContainerOver(rotating.Description.Container, 0.4, 0.5);
            var turned = rotating.Motion.ContainerOver(rotating.Description.Container, 2.9, 3.0);
            Assert.That(atRest.Rotation, Is.EqualTo(rotating.Description.Container.Rotation), "still during the start delay");
            Assert.That(System.Math.Abs(turned.Rotation.Z), Is.GreaterThan(0.3f), "90 degrees about z after 2 s of 45 deg/s");
            Assert.That(turned.AngularVelocity.Z, Is.EqualTo(45f * System.MathF.PI / 180f).Within(1e-5f));

            var wake = SceneLoader.Load(RunnerPaths.Scene("SphereWake"), RunnerPaths.Project);
            Assert.That(wake.Description.Obstacles.Count, Is.EqualTo(1));
            Assert.That(wake.Description.Obstacles[0].Radius, Is.EqualTo(0.045f).Within(1e-6f));
            var moved = wake.Motion.ObstaclesOver(wake.Description.Obstacles, 3.9, 4.0)[0];
            Assert.That(moved.Center.X, Is.EqualTo(-0.32f + 0.5f).Within(1e-4f), "half a period after the delay: the far end");
        }

        [Test]
        public void AFieldOutOfRangeIsReportedWithItsGameObjectComponentAndField()
        {
            string path = RunnerPaths.EditedScene("PlayModeTest", "RestDensity: 1000", "RestDensity: -3");
            int line = File.ReadAllLines(path).ToList().FindIndex(l => l.EndsWith("RestDensity: -3", StringComparison.Ordinal)) + 1;

            var error = Assert.Throws<SceneException>(() => SceneLoader.Load(path, RunnerPaths.Project));

            Assert.That(error.Message, Does.StartWith(path + ": "));
            Assert.That(error.Message, Does.Contain($"{path}:{line}: GameObject 'Water', SpawnBox.spawn.Phase.RestDensity"));
            Assert.That(error.Message, Does.Contain("RestDensity must be in [1, 100000] kg/m^3 (was -3)"));
        }

        [Test]
        public void ASettingOutOfRangeNamesTheSimulatorField()
        {
            string path = RunnerPaths.EditedScene("PlayModeTest", "    SmoothingRadius: 0.04", "    SmoothingRadius: 0.5");

            var error = Assert.Throws<SceneException>(() => SceneLoader.Load(path, RunnerPaths.Project));

            Assert.That(error.Message, Does.Match(@"PlayModeTest\.unity:\d+: GameObject 'Fluid', Fluid\.settings\.SmoothingRadius"));
        }

        /// <summary>Fluid.FindContainer takes the assigned container whether its GameObject is active or not, and reads
        /// its friction; the reader read an inactive one's as the default, NoSlip, where Unity runs the Slip it holds.</summary>
        [Test]
        public void AnAssignedContainerOnAnInactiveGameObjectKeepsItsFriction()
        {
            string path = RunnerPaths.EditedScene("PlayModeTest", ("  m_Name: Container\n  m_TagString: Untagged\n  m_Icon: {fileID: 0}\n  m_NavMeshLayer: 0\n" +
                "  m_StaticEditorFlags: 0\n  m_IsActive: 1", "  m_Name: Container\n  m_TagString: Untagged\n  m_Icon: {fileID: 0}\n  m_NavMeshLayer: 0\n" +
                "  m_StaticEditorFlags: 0\n  m_IsActive: 0"), ("  friction: 1", "  friction: 0"));

            var scene = SceneLoader.Load(path, RunnerPaths.Project);

            Assert.That(scene.Description.Container.Friction, Is.EqualTo(WallFriction.Slip));
            Assert.That(scene.ContainerObject, Is.EqualTo("Container"));
        }

        /// <summary>With no container assigned, Fluid.FindContainer's FindFirstObjectByType finds a disabled FluidContainer
        /// on an active GameObject (it skips inactive GameObjects only); the reader refused the scene as having none.</summary>
        [Test]
        public void AnUnassignedDisabledContainerIsFoundAsUnityFindsIt()
        {
            string path = RunnerPaths.EditedScene("PlayModeTest", ("  container: {fileID: 758566559}", "  container: {fileID: 0}"),
                ("  m_GameObject: {fileID: 1097463687}\n  m_Enabled: 1", "  m_GameObject: {fileID: 1097463687}\n  m_Enabled: 0"));

            var scene = SceneLoader.Load(path, RunnerPaths.Project);

            Assert.That(scene.ContainerObject, Is.EqualTo("Container"));
            Assert.That(scene.Description.Container.Friction, Is.EqualTo(WallFriction.NoSlip), "its friction: 1");
        }

        [Test]
        public void AMissingContainerIsNamed()
        {
            string containerGuid = RunnerPaths.Project.ScriptGuid("FluidContainer");
            string spinnerGuid = RunnerPaths.Project.ScriptGuid("FluidReadout");
            string text = System.IO.File.ReadAllText(RunnerPaths.Scene("PlayModeTest"));
            // Turn the container component into another script and clear the simulator's reference to it.
            text = text.Replace("guid: " + containerGuid, "guid: " + spinnerGuid).Replace("  friction: 1\n", "");
            text = System.Text.RegularExpressions.Regex.Replace(text, @"  container: \{fileID: \d+\}", "  container: {fileID: 0}");
            string path = System.IO.Path.Combine(RunnerPaths.ScratchFolder("scene"), "NoContainer.unity");
            System.IO.File.WriteAllText(path, text);

            var error = Assert.Throws<SceneException>(() => SceneLoader.Load(path, RunnerPaths.Project));

            Assert.That(error.Message, Does.Contain("no active FluidContainer"));
            Assert.That(error.Message, Does.Contain("Fluid.container"));
        }

        // A value that is not even of the field's type is told what to write: the declared range, or an enum's values (an
        // enum's value out of range too, by the validation, with the line).
        [TestCase("    Stiffness: 50000", "    Stiffness: lots",
            @"PlayModeTest\.unity:{line}: GameObject 'Fluid', Fluid\.settings\.Stiffness must be a number in \[1, 1E\+09\] Pa \(was 'lots'\)")]
        [TestCase("    MaxSolverIterations: 100", "    MaxSolverIterations: 99999999999999999999",
            @"PlayModeTest\.unity:{line}: GameObject 'Fluid', Fluid\.settings\.MaxSolverIterations must be a whole number in \[1, 1000\] \(was '99999999999999999999'\)")]
        [TestCase("    PressureSolver: 0", "    PressureSolver: dfsph",
            @"PlayModeTest\.unity:{line}: GameObject 'Fluid', Fluid\.settings\.PressureSolver must be one of 0 \(Wcsph\), 1 \(Dfsph\) \(was 'dfsph'\)")]
        [TestCase("  friction: 1", "  friction: rough",
            @"PlayModeTest\.unity:{line}: GameObject 'Container', FluidContainer\.friction must be one of 0 \(Slip\), 1 \(NoSlip\) \(was 'rough'\)")]
        [TestCase("  friction: 1", "  friction: 5",
            @"PlayModeTest\.unity:{line}: GameObject 'Container', FluidContainer\.friction: Friction must be one of 0 \(Slip\), 1 \(NoSlip\) \(was 5\)")]
        [TestCase("  container: {fileID: 758566559}", "  container: {fileID: 190528737}",
            @"PlayModeTest\.unity:{line}: GameObject 'Fluid', Fluid\.container refers to \{fileID: 190528737\}, which is not a FluidContainer component of this scene")]
        public void AValueItCannotUseNamesTheFieldLineAndWhatItAccepts(string original, string edited, string expected)
        {
            string path = RunnerPaths.EditedScene("PlayModeTest", original, edited);
            string text = System.IO.File.ReadAllText(path);
            int number = text.Substring(0, text.IndexOf(edited, StringComparison.Ordinal)).Count(c => c == '\n') + 1;

            var error = Assert.Throws<SceneException>(() => SceneLoader.Load(path, RunnerPaths.Project));

            Assert.That(error.Message, Does.Match(expected.Replace("{line}", number.ToString(CultureInfo.InvariantCulture))));
        }

        [Test]
        public void AMotionLawOutOfRangeNamesTheFieldLineAndRange()
        {
            string path = RunnerPaths.EditedScene("RotatingContainer", "    AngularSpeed: 45", "    AngularSpeed: 400");

            var error = Assert.Throws<SceneException>(() => SceneLoader.Load(path, RunnerPaths.Project));

            Assert.That(error.Message, Does.Match(@"RotatingContainer\.unity:\d+: GameObject '[^']+', ContainerSpinner\.spin\.AngularSpeed: AngularSpeed must be in \[-360, 360\] deg/s \(was 400\)"));
        }

        /// <summary>A motion the runner cannot give is refused at the line of the component that asks for it: a driver on
        /// a sphere whose obstacle is off, and a second spinner on the container (a copy of its first, &amp;1540063501).</summary>
        [Test]
        public void AMotionTheRunnerCannotGiveNamesItsComponentsLine()
        {
            string driver = RunnerPaths.EditedScene("SphereWake", "  m_Enabled: 1\n  m_EditorHideFlags: 0\n  m_Script: {fileID: 11500000, guid: 5f115756d2174588b65a748dd0438752",
                "  m_Enabled: 0\n  m_EditorHideFlags: 0\n  m_Script: {fileID: 11500000, guid: 5f115756d2174588b65a748dd0438752");
            string spinner = System.Text.RegularExpressions.Regex.Match(File.ReadAllText(RunnerPaths.Scene("RotatingContainer")), @"(?ms)^--- !u!114 &1540063500\n.*?(?=^--- )").Value;
            string twice = RunnerPaths.EditedScene("RotatingContainer", ("  - component: {fileID: 1540063500}\n", "  - component: {fileID: 1540063500}\n  - component: {fileID: 1540063501}\n"),
                ("--- !u!1 &507020402\n", spinner.Replace("&1540063500", "&1540063501") + "--- !u!1 &507020402\n"));

            var undriven = Assert.Throws<SceneException>(() => SceneLoader.Load(driver, RunnerPaths.Project));
            var spun = Assert.Throws<SceneException>(() => SceneLoader.Load(twice, RunnerPaths.Project));

            int Line(string path, string header) => File.ReadAllLines(path).ToList().IndexOf(header) + 1;
            Assert.That(undriven.Message, Does.StartWith($"{driver}:{Line(driver, "--- !u!114 &129498543")}: GameObject 'Sphere' has a SphereDriver but no active SphereObstacle"));
            Assert.That(spun.Message, Does.StartWith($"{twice}:{Line(twice, "--- !u!114 &1540063501")}: more than one ContainerSpinner turns the container 'Container'"));
        }

        /// <summary>The runner simulates one fluid; two are refused with the line of each, which tells apart two
        /// GameObjects of one name, or two Fluids on one (here a copy of the first, &amp;1090854010).</summary>
        [Test]
        public void TwoFluidsAreRefusedNamingTheLineOfEach()
        {
            string fluid = System.Text.RegularExpressions.Regex.Match(File.ReadAllText(RunnerPaths.Scene("PlayModeTest")), @"(?ms)^--- !u!114 &1090854009\n.*?(?=^--- )").Value;
            string path = RunnerPaths.EditedScene("PlayModeTest", ("  - component: {fileID: 1090854009}\n", "  - component: {fileID: 1090854009}\n  - component: {fileID: 1090854010}\n"),
                (fluid, fluid + fluid.Replace("&1090854009", "&1090854010")));
            var lines = File.ReadAllLines(path).ToList();

            var error = Assert.Throws<SceneException>(() => SceneLoader.Load(path, RunnerPaths.Project));

            Assert.That(error.Message, Is.EqualTo($"{path}: 2 active Fluid components (on GameObjects 'Fluid' at line {lines.IndexOf("--- !u!114 &1090854009") + 1}, " +
                $"'Fluid' at line {lines.IndexOf("--- !u!114 &1090854010") + 1}); the runner simulates one fluid per scene"));
        }

        [Test]
        public void AZeroSpinAxisIsRefused()
        {
            string path = RunnerPaths.EditedScene("RotatingContainer", "    Axis:\n      x: 0\n      y: 0\n      z: 1", "    Axis:\n      x: 0\n      y: 0\n      z: 0");
            // Unity writes the vector's members on the lines below its key; the error is about the field as a whole, so
            // it names the key's line, not the first member's.
            int line = File.ReadAllLines(path).ToList().IndexOf("    Axis:") + 1;

            var error = Assert.Throws<SceneException>(() => SceneLoader.Load(path, RunnerPaths.Project));

            Assert.That(error.Message, Does.Contain($"{path}:{line}: GameObject 'Container', ContainerSpinner.spin.Axis: Axis must be finite with magnitude in (0, 1000000]"));
        }

        [Test]
        public void AMissingFileIsASceneError()
        {
            var error = Assert.Throws<SceneException>(() => SceneLoader.Load("/nonexistent/Nothing.unity", RunnerPaths.Project));
            Assert.That(error.Message, Does.Contain("no such scene file"));
        }

        /// <summary>One asset's .meta that could not be read stopped every run in its project before a line was printed
        /// ("file error, the command stopped: ...Notes.txt.meta: is a link to nothing"); Unity opens the project and logs
        /// that asset.</summary>
        [Test]
        public void ALinkToNothingInPlaceOfAnotherAssetsMetaDoesNotStopTheRead()
        {
            string root = RunnerPaths.ProjectCopy("broken-meta");
            string asset = Path.Combine(root, "Assets", "FluidDemo", "Notes.txt");
            File.WriteAllText(asset, "notes\n");
            try { File.CreateSymbolicLink(asset + ".meta", Path.Combine(root, "nowhere")); }
            catch (IOException e) { Assert.Ignore("no symbolic links here: " + e.Message); }

            var scene = SceneLoader.Load(Path.Combine(root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity"));

            Assert.That(scene.Description.Phases().Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water", "Oil" }));
        }
    }
}
