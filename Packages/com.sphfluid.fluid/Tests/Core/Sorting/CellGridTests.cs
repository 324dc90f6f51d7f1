using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Sorting;

namespace SphFluid.Tests.Core.Sorting
{
    public sealed class CellGridTests
    {
        [Test]
        public void DimsCoverTheContainerPlusTwoMarginCellsPerSide()
        {
            var grid = new CellGrid(Vector3.Zero, Quaternion.Identity, new Vector3(1f, 0.5f, 0.26f), 0.1f);

            Assert.That(new[] { grid.DimX, grid.DimY, grid.DimZ }, Is.EqualTo(new[] { 14, 9, 7 }));
            Assert.That(grid.CellCount, Is.EqualTo(14 * 9 * 7));
        }

        /// <summary>The solver's grid: cells of h/2, which a walk of two cells each side covers, and a margin of one h.</summary>
        [Test]
        public void TheSupportsGridHasCellsOfHalfTheSupportAndAMarginOfOneSupport()
        {
            var grid = CellGrid.ForSupport(Vector3.Zero, Quaternion.Identity, new Vector3(1f, 0.5f, 0.26f), 0.2f);

            Assert.That(grid.CellSize, Is.EqualTo(0.1f));
            Assert.That(new[] { grid.DimX, grid.DimY, grid.DimZ }, Is.EqualTo(new[] { 14, 9, 7 }));
            Assert.That(CellGrid.MarginCells * grid.CellSize, Is.EqualTo(0.2f), "the margin is one support radius");
        }

        [Test]
        public void ContainerCornerCellsSitInsideTheMargin()
        {
            var grid = new CellGrid(new Vector3(2f, -1f, 0.5f), Quaternion.Identity, new Vector3(1f, 1f, 1f), 0.1f);

            grid.CellCoordOf(new Vector3(2f - 0.45f, -1f - 0.45f, 0.5f - 0.45f), out int x0, out int y0, out int z0);
            grid.CellCoordOf(new Vector3(2f + 0.45f, -1f + 0.45f, 0.5f + 0.45f), out int x1, out int y1, out int z1);

            Assert.That(new[] { x0, y0, z0 }, Is.EqualTo(new[] { 2, 2, 2 }));
            Assert.That(new[] { x1, y1, z1 }, Is.EqualTo(new[] { 11, 11, 11 }));
        }

        [Test]
        public void RotatedContainerMapsALocalPointToItsLocalCell()
        {
            var centre = new Vector3(1f, 2f, 3f);
            Quaternion rotation = Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(1f, 2f, 0.5f)), 0.9f);
            var size = new Vector3(0.8f, 0.4f, 0.6f);
            var grid = new CellGrid(centre, rotation, size, 0.1f);
            // Local point in the middle of local cell (2, 5, 3): q = (cell + 0.5 - margin) cell size - S/2.
            var local = new Vector3(2.5f, 5.5f, 3.5f) * 0.1f - new Vector3(CellGrid.MarginCells * 0.1f) - size * 0.5f;
            Vector3 world = centre + Vector3.Transform(local, rotation);

            grid.CellCoordOf(world, out int x, out int y, out int z);

            Assert.That(new[] { x, y, z }, Is.EqualTo(new[] { 2, 5, 3 }));
            Assert.That(grid.CellIndexOf(world), Is.EqualTo(2 + grid.DimX * (5 + grid.DimY * 3)));
        }

        /// <summary>A grid placed again with its container keeps mapping the container's own points to the same cells
        /// (FluidSimulation moves it with a carried or turning container), with its dims unchanged.</summary>
        [Test]
        public void PlacedAgainTheGridFollowsItsContainer()
        {
            var size = new Vector3(0.8f, 0.4f, 0.6f);
            var grid = new CellGrid(Vector3.Zero, Quaternion.Identity, size, 0.1f);
            var local = new Vector3(2.5f, 5.5f, 3.5f) * 0.1f - new Vector3(CellGrid.MarginCells * 0.1f) - size * 0.5f;
            int cells = grid.CellCount;
            var centre = new Vector3(0.7f, -0.2f, 1.3f);
            Quaternion rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 1.2f);

            grid.Place(centre, rotation);
            grid.CellCoordOf(centre + Vector3.Transform(local, rotation), out int x, out int y, out int z);

            Assert.That(new[] { x, y, z }, Is.EqualTo(new[] { 2, 5, 3 }));
            Assert.That(grid.CellCount, Is.EqualTo(cells));
            Assert.That(grid.Centre, Is.EqualTo(centre));
        }

        [Test]
        public void WorldToGridIsWrittenForColumnVectorsWithTranslationInTheLastColumn()
        {
            Quaternion rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.7f);
            var grid = new CellGrid(new Vector3(0.3f, -0.2f, 1.1f), rotation, new Vector3(1f, 2f, 3f), 0.25f);
            var world = new Vector3(0.7f, 0.1f, 0.4f);
            Matrix4x4 m = grid.WorldToGrid;

            // What HLSL's mul(m, float4(world, 1)) computes, with m[r][c] = M{r+1}{c+1}.
            var columnVector = new Vector3(
                m.M11 * world.X + m.M12 * world.Y + m.M13 * world.Z + m.M14,
                m.M21 * world.X + m.M22 * world.Y + m.M23 * world.Z + m.M24,
                m.M31 * world.X + m.M32 * world.Y + m.M33 * world.Z + m.M34);
            Vector3 expected = (Vector3.Transform(world - grid.Centre, Quaternion.Conjugate(rotation))
                                + new Vector3(0.5f, 1f, 1.5f) + new Vector3(CellGrid.MarginCells * 0.25f)) / 0.25f;

            Assert.That(Vector3.Distance(columnVector, expected), Is.LessThan(1e-4f));
            Assert.That(Vector3.Distance(grid.GridPositionOf(world), expected), Is.LessThan(1e-4f));
            Assert.That(new[] { m.M41, m.M42, m.M43, m.M44 }, Is.EqualTo(new[] { 0f, 0f, 0f, 1f }));
        }

        [Test]
        public void PointsOutsideTheGridClampIntoItsBorderCells()
        {
            var grid = new CellGrid(Vector3.Zero, Quaternion.Identity, new Vector3(1f, 1f, 1f), 0.1f);

            grid.CellCoordOf(new Vector3(-50f, 0.05f, 1e30f), out int x, out int y, out int z);
            grid.CellCoordOf(new Vector3(float.NaN, float.NaN, float.NaN), out int nx, out int ny, out int nz);

            Assert.That(new[] { x, y, z }, Is.EqualTo(new[] { 0, 7, 13 }));
            Assert.That(new[] { nx, ny, nz }, Is.EqualTo(new[] { 0, 0, 0 }));
        }

        [Test]
        public void NonPositiveSupportIsRefusedNamingTheSmoothingRadius()
        {
            Exception error = Catch(() => _ = CellGrid.ForSupport(Vector3.Zero, Quaternion.Identity, Vector3.One, 0f));

            Assert.That(error, Is.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(error.Message, Does.Contain("smoothing radius").And.Contain("was 0"));
        }

        [Test]
        public void NonPositiveCellSizeIsRefused()
        {
            Exception error = Catch(() => _ = new CellGrid(Vector3.Zero, Quaternion.Identity, Vector3.One, float.NaN));

            Assert.That(error, Is.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(error.Message, Does.Contain("cell size").And.Contain("was NaN"));
        }

        [Test]
        public void DegenerateContainerIsRefused()
        {
            Exception error = Catch(() => _ = new CellGrid(Vector3.Zero, Quaternion.Identity, new Vector3(1f, 0f, 1f), 0.1f));

            Assert.That(error, Is.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(error.Message, Does.Contain("container size must be finite and > 0 m on every axis (was (1, 0, 1))"));
        }

        /// <summary>Cells of h/2: 4 x 2 x 2 m at h = 8 mm needs 1000 x 500 x 500 cells and two margin cells a side, and the
        /// smallest h that fits the 2^25 cells is named.</summary>
        [Test]
        public void TooManyCellsIsRefusedNamingSizeRadiusDimsAndTheSmallestRadius()
        {
            Exception error = Catch(() => _ = CellGrid.ForSupport(Vector3.Zero, Quaternion.Identity, new Vector3(4f, 2f, 2f), 0.008f));

            Assert.That(error, Is.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(error.Message, Does.Contain("container size (4, 2, 2) m").And.Contain("smoothing radius h = 0.008")
                .And.Contain("1004 x 504 x 504").And.Contain(CellGrid.MaxCellCount.ToString()));
            string smallest = System.Text.RegularExpressions.Regex.Match(error.Message, @"at least ([0-9.]+) m").Groups[1].Value;
            float h = float.Parse(smallest, System.Globalization.CultureInfo.InvariantCulture);
            Assert.That(() => _ = CellGrid.ForSupport(Vector3.Zero, Quaternion.Identity, new Vector3(4f, 2f, 2f), h), Throws.Nothing,
                $"the named smallest radius {smallest} m fits");
            Assert.That(Catch(() => _ = CellGrid.ForSupport(Vector3.Zero, Quaternion.Identity, new Vector3(4f, 2f, 2f), 0.999f * h)),
                Is.TypeOf<ArgumentOutOfRangeException>(), "and a radius a thousandth smaller does not");
        }

        private static Exception Catch(Action action)
        {
            try
            {
                action();
            }
            catch (Exception e)
            {
                return e;
            }
            return null;
        }
    }
}
