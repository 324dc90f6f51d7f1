using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// A spawn box holds its volume and its mass at any spacing: the lattice fills the box exactly, boxes that touch
    /// leave no gap between them, and the derived mass makes each box weigh rest density times its volume. Before,
    /// floor(L / s) points per axis lost up to a spacing per axis (6 % of the mass at four times the particles).
    /// </summary>
    public sealed class SpawnVolumeTests
    {
        static readonly Vector3 BoxSize = new Vector3(0.3f, 0.2f, 0.12f);

        static FluidSceneDescription OneBox(float spacing, Vector3 size, float jitter = 0.05f)
        {
            var scene = new FluidSceneDescription
            {
                Settings = new FluidSettings { ParticleSpacing = spacing, SmoothingRadius = 2f * spacing },
                Container = new ContainerDescription { Size = new Vector3(0.6f, 0.6f, 0.3f) },
            };
            scene.SpawnBoxes.Add(new FluidBlock("Water", SimulationTestScenes.Water(), new Vector3(0f, -0.1f, 0f), size) { Jitter = jitter });
            return scene;
        }

        [TestCase(0.015f)]
        [TestCase(0.0119f)]
        [TestCase(0.0189f)]
        [TestCase(0.0095f)]
        [TestCase(0.023f)]
        public void ABoxWeighsRestDensityTimesItsVolumeAtAnySpacing(float spacing)
        {
            var scene = OneBox(spacing, BoxSize);
            double mass = SpawnLayout.Count(scene.Settings, scene.SpawnBoxes[0]) * (double)scene.BuildPhaseTable()[0].ParticleMass;
            double expected = 1000.0 * BoxSize.X * BoxSize.Y * BoxSize.Z;
            // delta0 s^3 = 1 to 1e-4 for the cubic spline on its lattice (RestNumberDensity test), the float table 1e-7.
            Assert.That(mass, Is.EqualTo(expected).Within(2e-4 * expected), $"s = {spacing} m");
        }

        [TestCase(0.015f)]
        [TestCase(0.0119f)]
        [TestCase(0.0189f)]
        public void TheCellStaysWithinAFewPerCentOfTheCubicOne(float spacing)
        {
            // Filling the box stretches the lattice by less than one spacing per axis; the counts are chosen so the
            // cell (and with it the derived mass) stays near s^3, which keeps boxes of one phase at one density.
            var scene = OneBox(spacing, BoxSize);
            double cell = SpawnLayout.CellVolume(scene.Settings, scene.SpawnBoxes[0]);
            Assert.That(cell / Math.Pow(spacing, 3), Is.EqualTo(1.0).Within(0.05), $"s = {spacing} m");
        }

        [Test]
        public void TheLatticeFillsTheBoxHalfASpacingInsideEachFace()
        {
            var scene = OneBox(0.015f, BoxSize, jitter: 0f);
            scene.Settings.Gravity = Vector3.Zero; // the lattice itself, before HydrostaticSpawn lowers it
            var box = scene.SpawnBoxes[0];
            SpawnLayout.CountPerAxis(scene.Settings, box, out int nx, out int ny, out int nz);
            var particles = SpawnLayout.Generate(scene);
            Assert.That(particles.Length, Is.EqualTo(nx * ny * nz));
            var low = box.Center - 0.5f * box.Size;
            var high = box.Center + 0.5f * box.Size;
            float stepY = box.Size.Y / ny;
            Assert.That(particles.Min(p => p.Position.Y) - low.Y, Is.EqualTo(0.5f * stepY).Within(1e-5f));
            Assert.That(high.Y - particles.Max(p => p.Position.Y), Is.EqualTo(0.5f * stepY).Within(1e-5f));
            Assert.That(particles.Min(p => p.Position.X) - low.X, Is.EqualTo(0.5f * box.Size.X / nx).Within(1e-5f));
            Assert.That(high.Z - particles.Max(p => p.Position.Z), Is.EqualTo(0.5f * box.Size.Z / nz).Within(1e-5f));
        }

        [Test]
        public void StackedBoxesLeaveNoGap()
        {
            // Two boxes of water stacked at y = 0, 0.137 m and 0.101 m tall: neither is a whole number of 0.02 m
            // spacings. Before, each lattice sat centred in its box at spacing s (6 and 5 layers), so the layers on
            // either side of the shared face were 0.029 m = 1.45 s apart: a gap in the fluid.
            var scene = OneBox(0.02f, new Vector3(0.2f, 0.137f, 0.1f), jitter: 0f);
            scene.Settings.Gravity = Vector3.Zero;
            var lower = scene.SpawnBoxes[0];
            lower.Center = new Vector3(0f, -0.5f * lower.Size.Y, 0f);
            var upper = new FluidBlock("Upper", SimulationTestScenes.Water(), new Vector3(0f, 0.0505f, 0f), new Vector3(0.2f, 0.101f, 0.1f)) { Jitter = 0f };
            scene.SpawnBoxes.Add(upper);
            Assert.That(scene.Validate(), Is.Empty);
            var particles = SpawnLayout.Generate(scene);
            int lowerCount = (int)SpawnLayout.Count(scene.Settings, lower);
            float lowerTop = particles.Take(lowerCount).Max(p => p.Position.Y);
            float upperBottom = particles.Skip(lowerCount).Min(p => p.Position.Y);
            SpawnLayout.CountPerAxis(scene.Settings, lower, out _, out int lowerLayers, out _);
            SpawnLayout.CountPerAxis(scene.Settings, upper, out _, out int upperLayers, out _);
            float expected = 0.5f * (lower.Size.Y / lowerLayers + upper.Size.Y / upperLayers);
            Assert.That(upperBottom - lowerTop, Is.EqualTo(expected).Within(1e-5f), "the layers meet at the mean of the two boxes' spacings");
            Assert.That(upperBottom - lowerTop, Is.LessThan(1.05f * scene.Settings.ParticleSpacing));
        }

        [Test]
        public void CountMatchesWhatGenerateSpawnsForAwkwardSizes()
        {
            var scene = OneBox(0.017f, new Vector3(0.113f, 0.071f, 0.049f), jitter: 0.5f);
            scene.SpawnBoxes.Add(new FluidBlock("Oil", SimulationTestScenes.Oil(), new Vector3(0.2f, -0.1f, 0f), new Vector3(0.05f, 0.031f, 0.2f)) { Seed = 3 });
            var particles = SpawnLayout.Generate(scene);
            Assert.That(particles.Length, Is.EqualTo(SpawnLayout.TotalCount(scene)));
            Assert.That(particles.Count(p => p.Phase == 1), Is.EqualTo((int)SpawnLayout.Count(scene.Settings, scene.SpawnBoxes[1])));
        }

        [Test]
        public void AnExplicitMassIsJudgedAgainstTheMassDerivedFromTheCell()
        {
            // 0.2 x 0.1 x 0.05 m at s = 0.02 m: 10 x 5 x 3 points, cells of 6.67e-6 m^3 for s^3 = 8e-6, so the derived
            // mass is 0.833 of rho0 / delta0. 0.7 rho0 / delta0 is 0.84 of it: inside the allowed 0.807 to 1.24.
            var scene = OneBox(0.02f, new Vector3(0.2f, 0.1f, 0.05f));
            double nominal = 1000.0 / scene.RestNumberDensity();
            Assert.That(DerivedParticleMass.Of(scene, scene.SpawnBoxes[0].Phase) / nominal, Is.EqualTo(125.0 / 150.0).Within(1e-5));
            scene.SpawnBoxes[0].Phase.ParticleMass = (float)(0.7 * nominal);
            Assert.That(scene.Validate(), Is.Empty);
            scene.SpawnBoxes[0].Phase.ParticleMass = (float)(1.1 * nominal);
            Assert.That(scene.Validate().Select(e => e.Field).ToArray(), Is.EqualTo(new[] { "SpawnBoxes[0].Phase.ParticleMass" }), "1.32 times the derived mass");
        }

        [Test]
        public void APhaseOverSeveralBoxesWeighsRestDensityTimesTheirVolume()
        {
            var scene = OneBox(0.017f, new Vector3(0.113f, 0.071f, 0.049f));
            scene.SpawnBoxes.Add(new FluidBlock("More", SimulationTestScenes.Water(), new Vector3(0.2f, -0.1f, 0f), new Vector3(0.05f, 0.031f, 0.2f)));
            double mass = scene.BuildPhaseTable()[0].ParticleMass * (double)SpawnLayout.TotalCount(scene);
            double volume = scene.SpawnBoxes.Sum(b => (double)b.Size.X * b.Size.Y * b.Size.Z);
            Assert.That(mass, Is.EqualTo(1000.0 * volume).Within(2e-4 * 1000.0 * volume));
        }
    }
}
