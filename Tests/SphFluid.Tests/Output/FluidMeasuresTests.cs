using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Output;
using SphFluid.Simulation;

namespace SphFluid.Tests.Output
{
    /// <summary>
    /// Per-phase measures, the layering index at the fluid's settled depth and the potential energy, on lattices
    /// laid out in a box so every answer follows from the layout.
    /// </summary>
    public sealed class FluidMeasuresTests
    {
        const float Spacing = 0.05f;
        static readonly Vector3 Gravity = new Vector3(0f, -9.81f, 0f);

        static PhaseProperties Phase(float restDensity, float mass) => new PhaseProperties { RestDensity = restDensity, ParticleMass = mass };

        /// <summary>
        /// A lattice against the back wall (x = -0.5) of a unit box centred at <paramref name="centre"/>: 10 columns
        /// (x), 4 z layers in the middle of the box, and one phase per row from the floor up.
        /// </summary>
        static Particle[] Rows(Vector3 centre, params uint[] phaseOfRow)
        {
            var particles = new List<Particle>();
            for (int row = 0; row < phaseOfRow.Length; row++)
                for (int column = 0; column < 10; column++)
                    for (int z = 0; z < 4; z++)
                    {
                        var local = new Vector3(-0.5f + (column + 0.5f) * Spacing, -0.5f + (row + 0.5f) * Spacing, (z - 1.5f) * Spacing);
                        particles.Add(new Particle(centre + local, Vector3.Zero, phaseOfRow[row], (uint)particles.Count));
                    }
            return particles.ToArray();
        }

        static ContainerDescription UnitBox(Vector3 centre) => new ContainerDescription(centre, Quaternion.Identity, Vector3.One);

        [Test]
        public void PhasesOfAPerfectlyLayeredPoolAreMeasuredFromTheLattice()
        {
            var centre = new Vector3(3f, 1f, -2f);
            var particles = Rows(centre, 0, 0, 0, 0, 0, 0, 1, 1); // water in rows 0-5, oil in rows 6-7
            var phases = new[] { Phase(1000f, 0.125f), Phase(900f, 0.1125f) };

            var m = FluidMeasures.Measure(2.5, particles, ReadOnlySpan<Vector4>.Empty, phases, UnitBox(centre), Gravity, Spacing, 2 * Spacing);

            var water = m.Phases[0];
            var oil = m.Phases[1];
            Assert.That(m.Time, Is.EqualTo(2.5));
            Assert.That(water.Count, Is.EqualTo(240));
            Assert.That(oil.Count, Is.EqualTo(80));
            Assert.That(water.MeanHeight, Is.EqualTo(0.15).Within(1e-5), "rows at 0.025 .. 0.275 m");
            Assert.That(oil.MeanHeight, Is.EqualTo(0.35).Within(1e-5), "rows at 0.325 and 0.375 m");
            Assert.That(water.Bottom, Is.EqualTo(0.025).Within(1e-5));
            Assert.That(water.Top, Is.EqualTo(0.275).Within(1e-5));
            Assert.That(oil.Bottom, Is.EqualTo(0.325).Within(1e-5));
            Assert.That(oil.Top, Is.EqualTo(0.375).Within(1e-5));
            Assert.That(water.FloorShare, Is.EqualTo(1.0), "only row 0 lies within one spacing of the floor");
            Assert.That(oil.FloorShare, Is.EqualTo(0.0));
            Assert.That(water.WallShare, Is.EqualTo(0.75), "column 0 touches the back wall: 6 of its 8 rows are water");
            Assert.That(oil.WallShare, Is.EqualTo(0.25));
            Assert.That(m.LayeringIndex, Is.EqualTo(1.0), "perfect layers score 1 at the fluid's own depth");
            double potential = 9.81 * (0.125 * 40 * (0.025 + 0.075 + 0.125 + 0.175 + 0.225 + 0.275) + 0.1125 * 40 * (0.325 + 0.375));
            Assert.That(m.PotentialEnergy, Is.EqualTo(potential).Within(1e-4 * potential));
            Assert.That(water.CompressionAverage, Is.NaN, "no densities given");
        }

        [Test]
        public void ThreePhasesLayeredScoreOneInAnyContainerSize()
        {
            // The old index divided by the spawned depth: a large box gave 16.7 for a mere pool.
            var particles = Rows(Vector3.Zero, 0, 0, 1, 1, 2, 2);
            var phases = new[] { Phase(1200f, 1f), Phase(1000f, 1f), Phase(800f, 1f) };
            var large = new ContainerDescription(new Vector3(1.5f, 1.5f, 0f), Quaternion.Identity, new Vector3(4f, 4f, 4f));

            var inUnitBox = FluidMeasures.Measure(0, particles, ReadOnlySpan<Vector4>.Empty, phases, UnitBox(Vector3.Zero), Gravity, Spacing, 2 * Spacing);
            var inLargeBox = FluidMeasures.Measure(0, particles, ReadOnlySpan<Vector4>.Empty, phases, large, Gravity, Spacing, 2 * Spacing);

            Assert.That(inUnitBox.LayeringIndex, Is.EqualTo(1.0));
            Assert.That(inLargeBox.LayeringIndex, Is.EqualTo(1.0));
        }

        [Test]
        public void HeavyOverLightScoresMinusOneAndTheLightPhaseWetsTheFloor()
        {
            var particles = Rows(Vector3.Zero, 1, 1, 0, 0);
            var phases = new[] { Phase(1000f, 1f), Phase(900f, 1f) };

            var m = FluidMeasures.Measure(0, particles, ReadOnlySpan<Vector4>.Empty, phases, UnitBox(Vector3.Zero), Gravity, Spacing, 2 * Spacing);

            Assert.That(m.LayeringIndex, Is.EqualTo(-1.0));
            Assert.That(m.Phases[1].FloorShare, Is.EqualTo(1.0));
            Assert.That(m.Phases[0].FloorShare, Is.EqualTo(0.0));
        }

        [Test]
        public void CompressionAndExpansionAreCountedApart()
        {
            var particles = Rows(Vector3.Zero, 0, 0);
            var densities = new Vector4[particles.Length];
            for (int i = 0; i < densities.Length; i++)
                densities[i] = new Vector4(i % 2 == 0 ? 1020f : 900f, 1234f, 0f, 0f); // +2 % and -10 %, alternately
            var phases = new[] { Phase(1000f, 1f) };

            var m = FluidMeasures.Measure(0, particles, densities, phases, UnitBox(Vector3.Zero), Gravity, Spacing, 2 * Spacing);

            var water = m.Phases[0];
            Assert.That(water.CompressionAverage, Is.EqualTo(0.01).Within(1e-6));
            Assert.That(water.CompressionMax, Is.EqualTo(0.02).Within(1e-6));
            Assert.That(water.ExpansionAverage, Is.EqualTo(0.05).Within(1e-6));
            Assert.That(water.ExpansionMax, Is.EqualTo(0.10).Within(1e-6));
            Assert.That(m.LayeringIndex, Is.NaN, "one phase has no pair to order");
        }

        [Test]
        public void AnEmptyPhaseHasNoFigures()
        {
            var particles = Rows(Vector3.Zero, 0);
            var phases = new[] { Phase(1000f, 1f), Phase(900f, 1f) };

            var m = FluidMeasures.Measure(0, particles, ReadOnlySpan<Vector4>.Empty, phases, UnitBox(Vector3.Zero), Gravity, Spacing, 2 * Spacing);

            Assert.That(m.Phases[1].Count, Is.EqualTo(0));
            Assert.That(m.Phases[1].MeanHeight, Is.NaN);
            Assert.That(m.Phases[1].Top, Is.NaN);
            Assert.That(m.Phases[1].FloorShare, Is.EqualTo(0.0));
            Assert.That(m.LayeringIndex, Is.NaN);
        }

        [Test]
        public void DensitiesOfAnotherLengthAreRefused()
        {
            var particles = Rows(Vector3.Zero, 0);
            var phases = new[] { Phase(1000f, 1f) };

            Assert.That(() => FluidMeasures.Measure(0, particles, new Vector4[3], phases, UnitBox(Vector3.Zero), Gravity, Spacing, 2 * Spacing),
                Throws.ArgumentException.With.Message.Contains("3 densities for 40 particles"));
        }

        [Test]
        public void ATurnedContainerTakesTheFaceGravityPointsAtAsItsFloor()
        {
            // Turned 90 degrees about z: local +x points up in the world, so the local x = -size/2 face is the floor.
            var container = new ContainerDescription(new Vector3(0f, 2f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2), new Vector3(1f, 2f, 3f));
            var frame = new GravityFrame(container, Gravity);

            Assert.That(frame.FloorAxis, Is.EqualTo(0));
            Assert.That(frame.AboveFloor(new Vector3(-0.4f, 0f, 0f)), Is.EqualTo(0.1f).Within(1e-6f));
            Assert.That(frame.FromWalls(new Vector3(-0.4f, 0.7f, 1.2f)), Is.EqualTo(0.3f).Within(1e-6f), "walls: y = +-1 and z = +-1.5");
            Assert.That(frame.LowestCorner, Is.EqualTo(1.5f).Within(1e-6f));
            Assert.That(frame.Extent, Is.EqualTo(1f).Within(1e-6f));
            Assert.That(frame.HeightOf(new Vector3(0.3f, 1.6f, 0f)), Is.EqualTo(0.1f).Within(1e-6f));
            Assert.That(frame.AboveFloor(frame.ToLocal(new Vector3(0.3f, 1.6f, 0f))), Is.EqualTo(0.1f).Within(1e-6f));
        }
    }
}
