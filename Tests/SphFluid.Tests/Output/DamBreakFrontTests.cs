using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Output;
using SphFluid.Simulation;

namespace SphFluid.Tests.Output
{
    /// <summary>The surge front and the back-wall column of a collapsing column laid out by hand, with spray around it.</summary>
    public sealed class DamBreakFrontTests
    {
        const float Spacing = 0.02f, Support = 0.04f;
        static readonly Vector3 Gravity = new Vector3(0f, -9.81f, 0f);

        // A 1 x 0.5 x 0.2 m tank centred at the origin: back wall x = -0.5, floor y = -0.25.
        static readonly ContainerDescription Tank = new ContainerDescription(Vector3.Zero, Quaternion.Identity, new Vector3(1f, 0.5f, 0.2f));

        /// <summary>Columns 0..<paramref name="columns"/>-1 from the back wall, rows 0..<paramref name="rows"/>-1 from the floor, 10 z layers.</summary>
        static void Block(List<Vector3> into, int firstColumn, int columns, int rows)
        {
            for (int column = firstColumn; column < firstColumn + columns; column++)
                for (int row = 0; row < rows; row++)
                    for (int z = 0; z < 10; z++)
                        into.Add(new Vector3(-0.5f + (column + 0.5f) * Spacing, -0.25f + (row + 0.5f) * Spacing, -0.1f + (z + 0.5f) * Spacing));
        }

        static (double Front, double Column) Measure(List<Vector3> local) =>
            DamBreakFront.Measure(local.ToArray(), new GravityFrame(Tank, Gravity), Spacing, Support);

        [Test]
        public void TheFrontIsTheFarthestFluidOnTheFloorAndTheColumnTheHighestAtTheBackWall()
        {
            var local = new List<Vector3>();
            Block(local, 0, 15, 10);   // column 15 spacings wide and 10 high against the back wall
            Block(local, 15, 10, 1);   // a one-particle film running on to column 24

            var (front, column) = Measure(local);

            Assert.That(front, Is.EqualTo(24.5 * Spacing).Within(1e-5), "film's last column centre, 0.49 m from the back wall");
            Assert.That(column, Is.EqualTo(9.5 * Spacing).Within(1e-5), "top row centre, 0.19 m above the floor");
        }

        [Test]
        public void SprayIsIgnored()
        {
            var local = new List<Vector3>();
            Block(local, 0, 15, 10);
            local.Add(new Vector3(0.3f, -0.24f, 0f));                                    // a lone drop on the floor far ahead
            local.Add(new Vector3(0.1f, -0.24f, 0f));                                    // a pair: one neighbour each
            local.Add(new Vector3(0.11f, -0.24f, 0f));
            local.Add(new Vector3(-0.49f, 0.2f, 0f));                                    // a splash high on the back wall

            var (front, column) = Measure(local);

            Assert.That(front, Is.EqualTo(14.5 * Spacing).Within(1e-5));
            Assert.That(column, Is.EqualTo(9.5 * Spacing).Within(1e-5));
        }

        [Test]
        public void FluidAboveTheFloorBandIsNotTheFront()
        {
            var local = new List<Vector3>();
            Block(local, 0, 5, 3);
            // A slab hanging 3 spacings above the floor (a plunging jet before it lands) reaches farther.
            for (int column = 5; column < 20; column++)
                for (int z = 0; z < 10; z++)
                    local.Add(new Vector3(-0.5f + (column + 0.5f) * Spacing, -0.25f + 3.5f * Spacing, -0.1f + (z + 0.5f) * Spacing));

            var (front, _) = Measure(local);

            Assert.That(front, Is.EqualTo(4.5 * Spacing).Within(1e-5));
        }

        [Test]
        public void NoFluidNearTheFloorGivesNaN()
        {
            var local = new List<Vector3> { new Vector3(0f, 0.2f, 0f) };

            var (front, column) = Measure(local);

            Assert.That(front, Is.NaN);
            Assert.That(column, Is.NaN);
        }

        [Test]
        public void ATankTurnedOntoItsBackWallHasNoFront()
        {
            // Turned 90 degrees about z: the back wall (x = -0.5) is now the floor, and x the height.
            var turned = new ContainerDescription(Vector3.Zero, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2), Tank.Size);
            var local = new List<Vector3>();
            Block(local, 0, 15, 10);

            var (front, column) = DamBreakFront.Measure(local.ToArray(), new GravityFrame(turned, Gravity), Spacing, Support);

            Assert.That(front, Is.NaN);
            Assert.That(column, Is.NaN);
        }

        [Test]
        public void FluidMeasuresReadTheFrontInTheContainersOwnFrame()
        {
            // The same column in a tank moved to (5, 1, 0): the figures do not move with it.
            var local = new List<Vector3>();
            Block(local, 0, 15, 10);
            var offset = new Vector3(5f, 1f, 0f);
            var particles = new Particle[local.Count];
            for (int i = 0; i < particles.Length; i++) particles[i] = new Particle(local[i] + offset, Vector3.Zero, 0, (uint)i);
            var moved = new ContainerDescription(offset, Quaternion.Identity, Tank.Size);

            var m = FluidMeasures.Measure(0, particles, ReadOnlySpan<Vector4>.Empty, new[] { new PhaseProperties { RestDensity = 1000f, ParticleMass = 0.008f } },
                moved, Gravity, Spacing, Support);

            Assert.That(m.SurgeFront, Is.EqualTo(14.5 * Spacing).Within(1e-5));
            Assert.That(m.BackWallColumn, Is.EqualTo(9.5 * Spacing).Within(1e-5));
        }
    }
}
