using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Simulation;
using SphFluid.Sorting;

namespace SphFluid.Tests.Primitives
{
    /// <summary>The GPU cell sort against a CPU stable counting sort: exact cell ranges, the exact
    /// (stable) order, and no particle lost or duplicated, in a rotated, off-centre container.</summary>
    public sealed class ParticleSortTests
    {
        private const int MaxParticles = 100000;
        private const float H = 0.05f;

        private static readonly Vector3 ContainerCentre = new Vector3(0.3f, -0.2f, 1.1f);
        private static readonly Quaternion ContainerRotation =
            Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(0.3f, 1f, -0.4f)), 0.6f);
        private static readonly Vector3 ContainerSize = new Vector3(1.0f, 0.6f, 0.8f);

        private IComputeDevice device;
        private ParticleSorter sorter;
        private CellGrid grid;
        private IComputeBuffer particles, sorted;

        [OneTimeSetUp]
        public void CreateSorter()
        {
            device = GpuTestDevice.Shared;
            grid = new CellGrid(ContainerCentre, ContainerRotation, ContainerSize, H);
            sorter = new ParticleSorter(device, MaxParticles, grid.CellCount);
            particles = device.CreateBuffer("ParticleSortTests.Particles", MaxParticles, Particle.Stride);
            sorted = device.CreateBuffer("ParticleSortTests.Sorted", MaxParticles, Particle.Stride);
        }

        [OneTimeTearDown]
        public void ReleaseSorter()
        {
            sorter?.Dispose();
            particles?.Dispose();
            sorted?.Dispose();
        }

        [TestCase(1)]
        [TestCase(255)]
        [TestCase(256)]
        [TestCase(257)]
        [TestCase(100000)]
        public void SortEqualsCpuStableCountingSort(int count)
        {
            Particle[] input = ScatteredParticles(count, count);

            GpuSort result = RunSort(input);

            CheckAgainstCpu(input, result);
        }

        [TestCase(257)]
        [TestCase(100000)]
        public void EveryParticleInOneCellIsKeptInInputOrder(int count)
        {
            Particle[] input = ParticlesInOneCell(count, 5, 3, 4, count);

            GpuSort result = RunSort(input);

            int cell = grid.CellIndexOf(5, 3, 4);
            Assert.That(result.CellCount[cell], Is.EqualTo((uint)count));
            Assert.That(result.CellStart[cell], Is.EqualTo(0u));
            CheckAgainstCpu(input, result);
        }

        [Test]
        public void RotatedContainerMapsAParticleToItsLocalCell()
        {
            // Middle of local cell (7, 2, 9): q = (cell + 0.5 - margin) h - S/2, world = c + R q.
            Vector3 local = (new Vector3(7.5f, 2.5f, 9.5f) - new Vector3(CellGrid.MarginCells)) * H - ContainerSize * 0.5f;
            Vector3 world = ContainerCentre + Vector3.Transform(local, ContainerRotation);
            var input = new[] { new Particle(world, Vector3.Zero, 0u, 42u) };

            GpuSort result = RunSort(input);

            int expected = 7 + grid.DimX * (2 + grid.DimY * 9);
            Assert.That(result.CellCount[expected], Is.EqualTo(1u));
            Assert.That(Sum(result.CellCount), Is.EqualTo(1L));
            Assert.That(result.Particles[0].Id, Is.EqualTo(42u));
        }

        [Test]
        public void ParticlesFarOutsideOrNaNAreKept()
        {
            Particle[] input = ScatteredParticles(1000, 99);
            input[3].Position = new Vector3(float.NaN, 0f, 0f);
            input[10].Position = new Vector3(1e30f, -1e30f, 5f);
            input[500].Position = new Vector3(float.PositiveInfinity, float.NegativeInfinity, float.NaN);

            GpuSort result = RunSort(input);

            Assert.That(Sum(result.CellCount), Is.EqualTo(1000L));
            CheckPermutation(input, result);
            CheckCellRanges(result, result.Particles.Length);
        }

        [Test]
        public void NoParticlesLeavesEveryCellEmpty()
        {
            GpuSort result = RunSort(new Particle[0]);

            Assert.That(Sum(result.CellCount), Is.EqualTo(0L));
            Assert.That(Array.TrueForAll(result.CellStart, s => s == 0u), Is.True);
        }

        [Test]
        public void TooLargeAGridIsRefused()
        {
            var bigger = new CellGrid(ContainerCentre, ContainerRotation, ContainerSize * 2f, H);

            Assert.That(() => sorter.Sort(bigger, particles, sorted, 10),
                Throws.ArgumentException.With.Message.Contains("more than the " + grid.CellCount));
        }

        // ---------------------------------------------------------------- helpers

        private sealed class GpuSort
        {
            public readonly Particle[] Particles;
            public readonly uint[] Source;
            public readonly uint[] CellStart;
            public readonly uint[] CellCount;

            public GpuSort(int particles, int cells)
            {
                Particles = new Particle[particles];
                Source = new uint[particles];
                CellStart = new uint[cells];
                CellCount = new uint[cells];
            }
        }

        private GpuSort RunSort(Particle[] input)
        {
            if (input.Length > 0) particles.SetData(input, 0, 0, input.Length);
            sorter.Sort(grid, particles, sorted, input.Length);
            device.Submit();
            var result = new GpuSort(input.Length, grid.CellCount);
            if (input.Length > 0)
            {
                sorted.GetData(result.Particles);
                sorter.SortedSource.GetData(result.Source);
            }
            sorter.CellStart.GetData(result.CellStart);
            sorter.CellCount.GetData(result.CellCount);
            return result;
        }

        private void CheckAgainstCpu(Particle[] input, GpuSort result)
        {
            int n = input.Length;
            var cells = new int[n];
            var counts = new uint[grid.CellCount];
            for (int i = 0; i < n; i++)
            {
                cells[i] = grid.CellIndexOf(input[i].Position);
                counts[cells[i]]++;
            }
            uint[] starts = PrefixSumTests.CpuExclusiveScan(counts, out _);
            var next = (uint[])starts.Clone();
            var expectedSource = new uint[n];
            for (int i = 0; i < n; i++) expectedSource[next[cells[i]]++] = (uint)i;

            Assert.That(PrefixSumTests.FirstMismatch(result.CellCount, counts), Is.EqualTo(-1), "first cell whose count differs");
            Assert.That(PrefixSumTests.FirstMismatch(result.CellStart, starts), Is.EqualTo(-1), "first cell whose start differs");
            CheckPermutation(input, result);
            CheckCellRanges(result, n);
            // Stable: same-cell particles keep their input order, so the order is exactly the CPU's.
            Assert.That(PrefixSumTests.FirstMismatch(result.Source, expectedSource), Is.EqualTo(-1), "first slot out of stable order");
        }

        // Every input particle appears exactly once, bit for bit, and SortedSource says where it came from.
        private static void CheckPermutation(Particle[] input, GpuSort result)
        {
            int n = input.Length;
            var seen = new bool[n];
            int wrong = -1;
            for (int j = 0; j < n && wrong < 0; j++)
            {
                uint source = result.Source[j];
                if (source >= n || seen[source] || !SameBits(result.Particles[j], input[source])) wrong = j;
                else seen[source] = true;
            }
            Assert.That(wrong, Is.EqualTo(-1), "first sorted slot that is not a distinct input particle");
            Assert.That(Array.TrueForAll(seen, s => s), Is.True);
        }

        // The cell ranges tile [0, n) and every particle sits in the range of the cell the grid gives it
        // (for NaN positions only the GPU knows the cell, so the ranges are checked for tiling only).
        private void CheckCellRanges(GpuSort result, int n)
        {
            uint covered = 0u;
            int wrongCell = -1;
            for (int c = 0; c < grid.CellCount; c++)
            {
                if (result.CellStart[c] != covered && wrongCell < 0) wrongCell = c;
                for (uint j = result.CellStart[c]; j < result.CellStart[c] + result.CellCount[c] && j < n; j++)
                {
                    Vector3 p = result.Particles[j].Position;
                    bool finite = float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z);
                    if (finite && grid.CellIndexOf(p) != c && wrongCell < 0) wrongCell = c;
                }
                covered += result.CellCount[c];
            }
            Assert.That(wrongCell, Is.EqualTo(-1), "first cell whose range is wrong");
            Assert.That(covered, Is.EqualTo((uint)n));
        }

        private static bool SameBits(Particle a, Particle b)
        {
            return BitConverter.SingleToInt32Bits(a.Position.X) == BitConverter.SingleToInt32Bits(b.Position.X)
                   && BitConverter.SingleToInt32Bits(a.Position.Y) == BitConverter.SingleToInt32Bits(b.Position.Y)
                   && BitConverter.SingleToInt32Bits(a.Position.Z) == BitConverter.SingleToInt32Bits(b.Position.Z)
                   && a.Velocity == b.Velocity && a.Phase == b.Phase && a.Id == b.Id;
        }

        private static long Sum(uint[] values)
        {
            long sum = 0;
            foreach (uint v in values) sum += v;
            return sum;
        }

        // Particles near random cell centres (never within 0.15 h of a cell face, so float rounding cannot
        // put the CPU and the GPU on different sides), 1% of them far outside the container; ids shuffled.
        private Particle[] ScatteredParticles(int count, int seed)
        {
            var random = new Random(seed);
            var result = new Particle[count];
            for (int i = 0; i < count; i++)
            {
                var g = new Vector3(random.Next(grid.DimX), random.Next(grid.DimY), random.Next(grid.DimZ))
                        + new Vector3(0.5f) + Jitter(random);
                if (random.Next(100) == 0) g.Y += random.Next(2) == 0 ? -40f : 40f;
                result[i] = new Particle(FromGrid(g), Jitter(random) * 4f, (uint)random.Next(3), 0u);
            }
            uint[] ids = ShuffledIds(count, random);
            for (int i = 0; i < count; i++) result[i].Id = ids[i];
            return result;
        }

        private Particle[] ParticlesInOneCell(int count, int x, int y, int z, int seed)
        {
            var random = new Random(seed);
            var result = new Particle[count];
            uint[] ids = ShuffledIds(count, random);
            for (int i = 0; i < count; i++)
                result[i] = new Particle(FromGrid(new Vector3(x, y, z) + new Vector3(0.5f) + Jitter(random)), Vector3.Zero, 0u, ids[i]);
            return result;
        }

        private static Vector3 Jitter(Random random)
        {
            return new Vector3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f) * 0.7f;
        }

        private static uint[] ShuffledIds(int count, Random random)
        {
            var ids = new uint[count];
            for (int i = 0; i < count; i++) ids[i] = (uint)i;
            for (int i = count - 1; i > 0; i--)
            {
                int j = random.Next(i + 1);
                (ids[i], ids[j]) = (ids[j], ids[i]);
            }
            return ids;
        }

        private static Vector3 FromGrid(Vector3 g)
        {
            Vector3 local = (g - new Vector3(CellGrid.MarginCells)) * H - ContainerSize * 0.5f;
            return ContainerCentre + Vector3.Transform(local, ContainerRotation);
        }
    }
}
