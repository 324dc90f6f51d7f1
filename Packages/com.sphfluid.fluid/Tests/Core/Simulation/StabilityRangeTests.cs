using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>The ranges that keep a scene stable: no overlapping spawn boxes, a particle mass near the derived one,
    /// a speed of sound above the scene's speeds and at most a hundred times them. Default settings in a 0.5 m tank:
    /// c = 18.71 m/s for water, free fall along the 0.866 m diagonal 4.122 m/s.</summary>
    public sealed class StabilityRangeTests
    {
        static string[] Messages(FluidSceneDescription scene) => scene.Validate().Select(e => e.Message).ToArray();

        static FluidSceneDescription TwoBoxes(Vector3 centreA, Vector3 centreB, Quaternion rotation, float size)
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes[0] = new FluidBlock("A", SimulationTestScenes.Water(), centreA, new Vector3(size, size, size)) { Rotation = rotation };
            scene.SpawnBoxes.Add(new FluidBlock("B", SimulationTestScenes.Water(), centreB, new Vector3(size, size, size)) { Rotation = rotation, Seed = 2 });
            return scene;
        }

        [Test]
        public void TouchingBoxes_AreAccepted()
        {
            Assert.That(SimulationTestScenes.OilOnWater().Validate(), Is.Empty, "oil sits on the water box, face to face");
        }

        [Test]
        public void OverlappingBoxes_NameBothAndTheDepth()
        {
            var scene = TwoBoxes(new Vector3(0f, -0.1f, 0f), new Vector3(0.06f, -0.1f, 0f), Quaternion.Identity, 0.1f);
            Assert.That(Messages(scene), Is.EqualTo(new[]
            {
                "SpawnBox 'B': the box must not overlap SpawnBox 'A' (they interpenetrate by 0.04 m; boxes may only touch, within 0.0002 m): overlapping boxes spawn particles on top of each other",
            }));
            Assert.That(scene.Validate()[0].Field, Is.EqualTo("SpawnBoxes[1].Center"));
        }

        [Test]
        public void TiltedBoxesWhoseBoundingBoxesOverlap_AreAcceptedWhenTheyDoNot()
        {
            // Both turned 45 degrees about z, centres 0.1414 m apart along their own x axis: they touch no more
            // than their 0.1 m edges allow, although their world bounding boxes overlap by 0.041 m.
            var turn = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 4f);
            var apart = TwoBoxes(new Vector3(0f, -0.1f, 0f), new Vector3(0.1f, 0f, 0f), turn, 0.1f);
            Assert.That(apart.Validate(), Is.Empty);
            var closer = TwoBoxes(new Vector3(0f, -0.1f, 0f), new Vector3(0.06f, -0.04f, 0f), turn, 0.1f);
            Assert.That(Messages(closer), Has.Some.Contains("interpenetrate by 0.0151"));
        }

        enum Layout { Grid, Wall, OneSpot }

        /// <summary>Boxes a spacing wide on a grid filling a cube (<see cref="Layout.Grid"/>) or a square in the plane
        /// x = 0 (<see cref="Layout.Wall"/>), or all at the tank's centre, in a tank that holds them.</summary>
        static FluidSceneDescription ManyBoxes(int count, Layout layout)
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes.Clear();
            int side = (int)Math.Ceiling(Math.Pow(count, layout == Layout.Wall ? 0.5 : 1.0 / 3.0));
            scene.Container.Size = new Vector3(Math.Max(1f, 0.02f * side + 0.5f));
            for (int i = 0; i < count; i++)
            {
                var cell = layout == Layout.Wall ? new Vector3(0f, i % side, i / side) : new Vector3(i % side, i / side % side, i / (side * side));
                var centre = layout == Layout.OneSpot ? Vector3.Zero : 0.02f * (cell - new Vector3(layout == Layout.Wall ? 0f : 0.5f * side, 0.5f * side, 0.5f * side));
                scene.SpawnBoxes.Add(new FluidBlock("B" + i, SimulationTestScenes.Water(), centre, new Vector3(0.02f)) { Seed = i + 1 });
            }
            return scene;
        }

        /// <summary>Every pair of boxes was tested, in the editor too: these 20 000 took 25 s. Only pairs whose bounding
        /// boxes meet are tested now.</summary>
        [Test]
        public void TwentyThousandBoxesSideBySide_AreValidatedInSeconds() =>
            AssertValidatedInSeconds(ManyBoxes(20000, Layout.Grid));

        /// <summary>The sweep ran along x, where boxes laid in one plane across x all meet: these 100 000 took 14.5 s.
        /// It runs along the axis where it meets fewest pairs now (1.4 s on the same machine).</summary>
        [Test]
        public void AHundredThousandBoxesInAWallAcrossX_AreValidatedInSeconds() =>
            AssertValidatedInSeconds(ManyBoxes(100000, Layout.Wall));

        static void AssertValidatedInSeconds(FluidSceneDescription scene)
        {
            var watch = System.Diagnostics.Stopwatch.StartNew();
            var errors = scene.Validate();
            Assert.That(watch.Elapsed.TotalSeconds, Is.LessThan(5.0));
            Assert.That(errors, Is.Empty, "boxes side by side only touch (the overlap rule runs only on a scene with no other error)");
        }

        /// <summary>Every overlapping pair was named: 2 000 boxes at one spot made 1 999 000 messages. Ten pairs are named
        /// and one more error says that more overlap.</summary>
        [Test]
        public void BoxesPiledAtOneSpot_NameTenPairsAndSayMoreOverlap()
        {
            var errors = ManyBoxes(2000, Layout.OneSpot).Validate();
            Assert.That(errors.Count, Is.EqualTo(11));
            Assert.That(errors[0].Message, Does.StartWith("SpawnBox 'B1': the box must not overlap SpawnBox 'B0' (they interpenetrate by 0.02 m"));
            Assert.That(errors[0].Field, Is.EqualTo("SpawnBoxes[1].Center"));
            Assert.That(errors[10].Field, Is.EqualTo("SpawnBoxes"));
            Assert.That(errors[10].Message, Is.EqualTo("FluidScene: more pairs of spawn boxes overlap than the 10 named; move the boxes apart, then validate again"));
        }

        [Test]
        public void ParticleMass_MustBeNearTheDerivedOne()
        {
            var scene = SimulationTestScenes.SingleWater();
            double derived = 1000.0 / scene.RestNumberDensity();
            double factor = Math.Pow(4.5, 1.0 / 7.0); // 1.2397 at gamma = 7
            scene.SpawnBoxes[0].Phase.ParticleMass = (float)(derived * factor * 0.999);
            Assert.That(scene.Validate(), Is.Empty);
            scene.SpawnBoxes[0].Phase.ParticleMass = (float)(derived * factor * 1.001);
            var errors = scene.Validate();
            Assert.That(errors.Select(e => e.Field).ToArray(), Is.EqualTo(new[] { "SpawnBoxes[0].Phase.ParticleMass" }));
            Assert.That(errors[0].Message, Does.StartWith($"SpawnBox 'Water': ParticleMass must be 0 (derived: {derived:G6} kg) or in ["));
            Assert.That(errors[0].Message, Does.Contain("(0.806648 to 1.2397 times the derived mass for this spacing, support radius, rest density and Gamma)"));
        }

        [Test]
        public void GravityFasterThanSound_IsRefusedWithItsRange()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.Settings.Gravity = new Vector3(0f, -203f, 0f);
            Assert.That(Messages(scene), Is.EqualTo(new[]
            {
                "FluidSettings: Gravity must have magnitude in [0, 202.073] m/s^2 for this scene, or Stiffness must be at least 50229.5 Pa: "
                + "free fall along the container's 0.866025 m diagonal (18.7512 m/s) plus the fastest spawn box (0 m/s) and walls or spheres (0 m/s) "
                + "must stay below the speed of sound 18.7083 m/s of phase 'Water' (was 203)",
            }));
            scene.Settings.Gravity = new Vector3(0f, -202f, 0f);
            Assert.That(scene.Validate(), Is.Empty);
        }

        [Test]
        public void SpawnFasterThanSound_NamesTheBox()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes[0].InitialVelocity = new Vector3(15f, 0f, 0f);
            var errors = scene.Validate();
            Assert.That(errors.Select(e => e.Field).ToArray(), Is.EqualTo(new[] { "SpawnBoxes[0].InitialVelocity" }));
            Assert.That(errors[0].Message, Does.StartWith("SpawnBox 'Water': InitialVelocity must have magnitude in [0, 14.5862] m/s for this scene").And.EndWith("(was 15)"));
        }

        [Test]
        public void StiffnessAHundredTimesTheSceneSpeed_IsTheMost()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.Settings.Stiffness = 2.42e7f;
            Assert.That(scene.Validate(), Is.Empty);
            scene.Settings.Stiffness = 1e9f;
            Assert.That(Messages(scene), Has.Some.StartWith("FluidSettings: Stiffness must be in [1, 2.42735E+07] Pa for this scene: the speed of sound 2645.75 m/s of phase 'Water' must be at most 100 times the fastest speed the scene can reach, 4.12206 m/s"));
        }

        [Test]
        public void AirOverWater_NeedsAStiffnessWindow()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[1].Phase = new PhaseDescription("Air", 1f, 1e-5f);
            Assert.That(Messages(scene), Has.Some.StartWith("FluidSettings: Stiffness must be in [1, 24273.5] Pa for this scene: the speed of sound 591.608 m/s of phase 'Air'"));
            scene.Settings.Stiffness = 20000f; // c = 11.8 m/s for water, 374 m/s for air: inside [2427, 24273] Pa
            Assert.That(scene.Validate(), Is.Empty);
        }
    }
}
