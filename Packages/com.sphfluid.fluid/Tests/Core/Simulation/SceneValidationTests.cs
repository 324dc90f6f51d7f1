using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    public sealed class SceneValidationTests
    {
        static string[] Messages(FluidSceneDescription scene) => scene.Validate().Select(e => e.Message).ToArray();

        [Test]
        public void ValidScene_HasNoErrors()
        {
            Assert.That(SimulationTestScenes.OilOnWater().Validate(), Is.Empty);
            Assert.That(new FluidSettings().Validate(), Is.Empty);
        }

        [Test]
        public void NegativeRestDensity_NamesBoxFieldRangeAndValue()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[0].Phase.RestDensity = -3f;
            var errors = scene.Validate();
            Assert.That(errors.Select(e => e.Message).ToArray(), Has.Member("SpawnBox 'Water': RestDensity must be in [1, 100000] kg/m^3 (was -3)"));
            Assert.That(errors.Select(e => e.Field).ToArray(), Has.Member("SpawnBoxes[0].Phase.RestDensity"));
        }

        // A scene file's reader names the GameObject and the serialized field itself, so it prints the rule alone: the
        // owner apart from the rule keeps it from saying the box twice.
        [Test]
        public void AnErrorKeepsItsOwnerApartFromItsRule()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[0].Phase.RestDensity = -3f;
            scene.Settings.Stiffness = -1f;
            scene.Container.Friction = (WallFriction)7;
            var errors = scene.Validate();
            var density = errors.Single(e => e.Field == "SpawnBoxes[0].Phase.RestDensity");
            Assert.That(density.Owner, Is.EqualTo("SpawnBox 'Water'"));
            Assert.That(density.Rule, Is.EqualTo("RestDensity must be in [1, 100000] kg/m^3 (was -3)"));
            Assert.That(errors.Single(e => e.Field == "Settings.Stiffness").Owner, Is.EqualTo("FluidSettings"));
            Assert.That(errors.Single(e => e.Field == "Container.Friction").Owner, Is.EqualTo("Container"));
            foreach (var e in errors)
            {
                Assert.That(e.Message, Is.EqualTo(e.Owner + ": " + e.Rule));
                Assert.That(e.Rule, Does.Not.StartWith(e.Owner), e.Field);
            }
        }

        [Test]
        public void ARefusedSpacing_IsNotCarriedIntoTheContainersLeastSize()
        {
            // The container's least size is two spacings: a spacing typed as 1e30 named the range [2E+30, 1000] m there.
            var scene = SimulationTestScenes.OilOnWater();
            scene.Settings.ParticleSpacing = 1e30f;
            var errors = scene.Validate();
            Assert.That(errors.Select(e => e.Field).ToArray(), Has.Member("Settings.ParticleSpacing"));
            Assert.That(errors.Select(e => e.Field).ToArray(), Has.No.Member("Container.Size"));
            scene.Settings.ParticleSpacing = 0.02f;
            scene.Container.Size = new Vector3(0.03f, 0.5f, 0.5f);
            Assert.That(Messages(scene), Has.Member("Container: each Size component must be in [0.04, 1000] m (two particle spacings or more) (was (0.03, 0.5, 0.5))"));
        }

        [Test]
        public void SmoothingRadiusOutsideRatio_IsRefused()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Settings.SmoothingKernel = KernelFamily.WendlandC2;
            scene.Settings.SmoothingRadius = 0.1f;
            Assert.That(Messages(scene), Has.Some.Contains("FluidSettings: SmoothingRadius must be in [0.04, 0.08] m (2 to 4 particle spacings)").And.Contains("(was 0.1)"));
        }

        [Test]
        public void ACubicSplineWiderThanItsPairingLimit_IsRefusedNamingTheOtherKernel()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Settings.SmoothingRadius = 0.06f; // 3 spacings: fine for Wendland C2, not for the cubic spline
            Assert.That(Messages(scene), Has.Some.Contains(
                "FluidSettings: SmoothingRadius must be in [0.04, 0.045] m (2 to 2.25 particle spacings with the CubicSpline kernel; up to 4 with WendlandC2)")
                .And.Contains("(was 0.06)"));
            scene.Settings.SmoothingKernel = KernelFamily.WendlandC2;
            Assert.That(Messages(scene), Has.None.Contains("SmoothingRadius"));
        }

        [TestCase(KernelFamily.CubicSpline, 0.045f, "[0.04, 0.04] m (2 particle spacings for the CubicSpline kernel with the Dfsph pressure solver; 2 to 2.9 with WendlandC2)")]
        [TestCase(KernelFamily.WendlandC2, 0.06f, "[0.04, 0.058] m (2 to 2.9 particle spacings for the WendlandC2 kernel with the Dfsph pressure solver)")]
        public void ADfsphSupportTooWideForItsKernel_IsRefusedWithTheRange(KernelFamily kernel, float radius, string range)
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            scene.Settings.SmoothingKernel = kernel;
            Assert.That(Messages(scene), Has.None.Contains("SmoothingRadius"), "2 spacings");
            scene.Settings.SmoothingRadius = radius;
            Assert.That(Messages(scene), Has.Some.Contains("FluidSettings: SmoothingRadius must be in " + range)
                .And.Contains($"(was {radius.ToString(System.Globalization.CultureInfo.InvariantCulture)})"));
        }

        /// <summary>Wendland C2 at 2.85 spacings (the OilAndWater scene's support) has lambda_max 5.38: DFSPH's full step makes
        /// the stiffest lattice wave grow, and the relaxation must stay within 2 / 5.38.</summary>
        [Test]
        public void AWideDfsphSupport_NeedsTheRelaxationWithinTheJacobiStepsStabilityBound()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            scene.Settings.SmoothingKernel = KernelFamily.WendlandC2;
            scene.Settings.SmoothingRadius = 2.85f * scene.Settings.ParticleSpacing;
            Assert.That(Messages(scene), Has.Some.Contains("FluidSettings: SolverRelaxation must be in [0.05, 0.372")
                .And.Contains("(2 / lambda_max of the Dfsph solve's Jacobi step with WendlandC2 at 2.85 particle spacings: beyond it the lattice's stiffest pressure wave grows) (was 1)"));
            scene.Settings.SolverRelaxation = 0.3f;
            Assert.That(Messages(scene), Has.None.Contains("SolverRelaxation").And.None.Contains("SmoothingRadius"));
            scene.Settings.SmoothingRadius = 2f * scene.Settings.ParticleSpacing;
            scene.Settings.SolverRelaxation = 1f;
            Assert.That(Messages(scene), Has.None.Contains("SolverRelaxation"), "at 2 spacings the papers' full step is measured");
        }

        [TestCase("Stiffness", "Stiffness must be in [1, 1E+09] Pa (was -1)")]
        [TestCase("Gamma", "Gamma must be in [1, 10] (was -1)")]
        [TestCase("XsphEpsilon", "XsphEpsilon must be in [0, 1] (was -1)")]
        [TestCase("CflNumber", "CflNumber must be in [0.01, 1] (was -1)")]
        [TestCase("ParticleShifting", "ParticleShifting must be in [0, 10] (was -1)")]
        [TestCase("MaxTimeStep", "MaxTimeStep must be in [1E-05, 0.1] s (was -1)")]
        public void SettingsOutOfRange_NameTheField(string field, string message)
        {
            var settings = new FluidSettings();
            typeof(FluidSettings).GetField(field).SetValue(settings, -1f);
            Assert.That(settings.Validate().Select(e => e.Message).ToArray(), Has.Member("FluidSettings: " + message));
        }

        /// <summary>A CFL number or a largest sub-step of 1e-30 was valid, and left each frame a few 1e-29 s further on: a
        /// run of OilAndWater for 0.02 simulated seconds had not ended after three minutes. A step that small is refused.</summary>
        [TestCase("CflNumber", "CflNumber must be in [0.01, 1] (was 1E-30)")]
        [TestCase("MaxTimeStep", "MaxTimeStep must be in [1E-05, 0.1] s (was 1E-30)")]
        public void AStepTooSmallToGetAnywhere_IsRefused(string field, string message)
        {
            var settings = new FluidSettings();
            typeof(FluidSettings).GetField(field).SetValue(settings, 1e-30f);
            Assert.That(settings.Validate().Select(e => e.Message).ToArray(), Has.Member("FluidSettings: " + message));
        }

        [Test]
        public void ConflictingPhaseDefinitions_NameBothBoxes()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[1].Phase = SimulationTestScenes.Water();
            scene.SpawnBoxes[1].Phase.RestDensity = 998f;
            var messages = Messages(scene);
            Assert.That(messages, Has.Member("SpawnBox 'Oil': phase 'Water' is defined differently in SpawnBox 'Water' and SpawnBox 'Oil', " +
                "which differ in RestDensity (1000 against 998 kg/m^3); boxes of one phase must agree"));
        }

        // The phases' short form names density, viscosity and tension only: two boxes apart in a value it leaves out were
        // refused with the same text printed for both.
        [Test]
        public void ConflictingPhaseDefinitions_NameEveryValueThatDiffers()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[1].Phase = SimulationTestScenes.Water();
            scene.SpawnBoxes[0].Phase.Absorption = 1f;
            scene.SpawnBoxes[0].Phase.Color = new SettingColor(0.25f, 0.5f, 1f, 0.75f);
            scene.SpawnBoxes[1].Phase.Absorption = 3.5f;
            scene.SpawnBoxes[1].Phase.Color = new SettingColor(0.5f, 0.25f, 1f, 1f);
            var conflict = scene.Validate().Single(e => e.Field == "SpawnBoxes[1].Phase");
            Assert.That(conflict.Rule, Does.Contain(
                "which differ in Color ((0.25, 0.5, 1, 0.75) against (0.5, 0.25, 1, 1)), Absorption (1 against 3.5 1/m);"));
        }

        [Test]
        public void BoxOutsideTheContainer_NamesTheBox()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[1].Center = new Vector3(0.2f, 0f, 0f);
            // The box's size is named beside its centre: a box scaled too large is refused here too, at its position's line.
            Assert.That(Messages(scene), Has.Some.StartsWith("SpawnBox 'Oil': the box (centre (0.2, 0, 0), size (0.5, 0.12, 0.5) m) " +
                "must lie inside the container (centre (0, 0, 0), size (0.5, 0.5, 0.5) m); its corner "));
        }

        // A container refused for its size or placement is not also blamed on every box it no longer holds; a container
        // refused for another value (its friction) still has its boxes checked.
        [Test]
        public void ARefusedContainerPlacementIsNotRepeatedForTheBoxes()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Container.Size = Vector3.Zero;
            Assert.That(scene.Validate().Select(e => e.Field).ToArray(), Is.EqualTo(new[] { "Container.Size" }));
            scene = SimulationTestScenes.OilOnWater();
            scene.Container.Position = new Vector3(float.NaN, 0f, 0f);
            Assert.That(scene.Validate().Select(e => e.Field).ToArray(), Is.EqualTo(new[] { "Container.Position" }));
            scene = SimulationTestScenes.OilOnWater();
            scene.Container.Friction = (WallFriction)7;
            scene.SpawnBoxes[1].Center = new Vector3(0.2f, 0f, 0f);
            Assert.That(scene.Validate().Select(e => e.Field).ToArray(), Is.EqualTo(new[] { "Container.Friction", "SpawnBoxes[1].Center" }));
        }

        [Test]
        public void BoxSmallerThanASpacing_IsRefused()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[0].Size = new Vector3(0.01f, 0.1f, 0.1f);
            Assert.That(Messages(scene), Has.Some.StartsWith("SpawnBox 'Water': each Size component must be in [0.02, 1000] m"));
        }

        // Unity's Transform and a script can hold NaN or infinity; the headless reader refuses them while it reads the
        // scene, but a Fluid in the editor hands its Transforms straight to this validation.
        [TestCase("SpawnBoxes[0].Center", float.NaN)]
        [TestCase("SpawnBoxes[0].Size", float.PositiveInfinity)]
        [TestCase("SpawnBoxes[0].Rotation", float.NaN)]
        [TestCase("SpawnBoxes[0].InitialVelocity", float.NegativeInfinity)]
        [TestCase("Container.Position", float.NaN)]
        [TestCase("Container.Size", float.NaN)]
        [TestCase("Container.Rotation", float.PositiveInfinity)]
        [TestCase("Obstacles[0].Center", float.NaN)]
        [TestCase("Obstacles[0].Radius", float.NaN)]
        public void ANonFinitePlacement_IsRefusedNamingItsField(string field, float value)
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Obstacles.Add(new RigidSphere(scene.Container.Position + new Vector3(0f, 0.15f, 0f), 0.02f, Vector3.Zero) { Name = "Ball" });
            Assert.That(scene.Validate(), Is.Empty, "the scene before the edit");
            FluidBlock box = scene.SpawnBoxes[0];
            ContainerDescription container = scene.Container;
            RigidSphere sphere = scene.Obstacles[0];
            // Only the one component changes, so that nothing but its value can be what is refused.
            Vector3 WithY(Vector3 a) => new Vector3(a.X, value, a.Z);
            switch (field)
            {
                case "SpawnBoxes[0].Center": box.Center = WithY(box.Center); break;
                case "SpawnBoxes[0].Size": box.Size = WithY(box.Size); break;
                case "SpawnBoxes[0].Rotation": box.Rotation = new Quaternion(box.Rotation.X, value, box.Rotation.Z, box.Rotation.W); break;
                case "SpawnBoxes[0].InitialVelocity": box.InitialVelocity = WithY(box.InitialVelocity); break;
                case "Container.Position": container.Position = WithY(container.Position); break;
                case "Container.Size": container.Size = WithY(container.Size); break;
                case "Container.Rotation": container.Rotation = new Quaternion(value, container.Rotation.Y, container.Rotation.Z, container.Rotation.W); break;
                case "Obstacles[0].Center": sphere.Center = WithY(sphere.Center); break;
                case "Obstacles[0].Radius": sphere.Radius = value; break;
            }
            Assert.That(scene.Validate().Select(e => e.Field).ToArray(), Has.Some.StartsWith(field));
        }

        [Test]
        public void JitterAboveHalf_IsRefused()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[0].Jitter = 0.7f;
            Assert.That(Messages(scene), Has.Member("SpawnBox 'Water': Jitter must be in [0, 0.5] particle spacings (was 0.7)"));
        }

        [Test]
        public void TooManyParticles_IsRefused()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Settings.MaxParticles = 100;
            Assert.That(Messages(scene), Has.Some.Contains("the total must be in [1, 100]"));
        }

        [Test]
        public void ObstacleWithZeroRadius_IsRefused()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Obstacles.Add(new RigidSphere(Vector3.Zero, 0f, Vector3.Zero) { Name = "Ball" });
            Assert.That(Messages(scene), Has.Member("Sphere 'Ball': Radius must be in (0, 1000] m (was 0)"));
        }

        // A sphere leaves out the lattice points it covers; one that covers them all once left a scene of no particle,
        // refused only by the GPU buffer's "count must be > 0".
        [Test]
        public void ObstacleCoveringEverySpawnPoint_IsRefused()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Obstacles.Add(new RigidSphere(scene.Container.Position, 5f, Vector3.Zero) { Name = "Ball" });
            var errors = scene.Validate();
            Assert.That(errors.Select(e => e.Field).ToArray(), Is.EqualTo(new[] { "Obstacles[0].Radius" }));
            Assert.That(errors[0].Message, Does.StartWith("Sphere 'Ball': the sphere obstacles ('Ball' of world radius 5 m at ")
                .And.Contain("so the scene would spawn no particle"));
            Assert.That(() => SpawnLayout.Generate(scene), Throws.ArgumentException.With.Message.Contains("would spawn no particle"));
        }

        [Test]
        public void ObstaclesCoveringEverySpawnPoint_NameTheLargestAsTheField()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Obstacles.Add(new RigidSphere(new Vector3(0.2f, 0.2f, 0.2f), 0.01f, Vector3.Zero) { Name = "Pebble" });
            scene.Obstacles.Add(new RigidSphere(scene.Container.Position, 5f, Vector3.Zero) { Name = "Ball" });
            var errors = scene.Validate();
            Assert.That(errors.Select(e => e.Field).ToArray(), Is.EqualTo(new[] { "Obstacles[1].Radius" }));
            Assert.That(errors[0].Message, Does.StartWith("Sphere 'Ball': the sphere obstacles ('Pebble' of world radius 0.01 m at "));
        }

        [Test]
        public void ObstacleCoveringSomeSpawnPoints_IsAllowed()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Obstacles.Add(new RigidSphere(scene.SpawnBoxes[0].Center, 0.02f, Vector3.Zero) { Name = "Ball" });
            Assert.That(scene.Validate(), Is.Empty);
            Assert.That(SpawnLayout.TotalCount(scene), Is.LessThan(SpawnLayout.Count(scene.Settings, scene.SpawnBoxes[0])
                + SpawnLayout.Count(scene.Settings, scene.SpawnBoxes[1])));
        }

        [Test]
        public void EmptyScene_IsRefused()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes.Clear();
            Assert.That(Messages(scene), Has.Member("FluidScene: SpawnBoxes must hold at least one box (was 0)"));
        }

        [Test]
        public void GenerateOnInvalidScene_ThrowsWithEveryMessage()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[0].Phase.RestDensity = -3f;
            Assert.That(() => SpawnLayout.Generate(scene),
                Throws.ArgumentException.With.Message.Contains("SpawnBox 'Water': RestDensity must be in [1, 100000] kg/m^3 (was -3)"));
        }
    }
}
