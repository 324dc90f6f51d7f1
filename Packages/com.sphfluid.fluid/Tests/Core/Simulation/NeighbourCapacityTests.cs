using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// The entries of the neighbour lists (NeighbourCapacity): half as many again as a particle of the spawn lattice has
    /// neighbours within the support, and none where the lists would not fit in one buffer; WCSPH reads them in one lane only.
    /// </summary>
    public sealed class NeighbourCapacityTests
    {
        static FluidSettings Settings(PressureSolver solver, KernelFamily kernel, float supportRatio)
        {
            var s = new FluidSettings { PressureSolver = solver, SmoothingKernel = kernel, ParticleSpacing = 0.01f };
            s.SmoothingRadius = supportRatio * s.ParticleSpacing;
            return s;
        }

        /// <summary>Points of the cubic lattice of spacing 1 closer than <paramref name="ratio"/> to one of them, itself included.</summary>
        static int LatticeNeighbours(double ratio)
        {
            int reach = (int)ratio, count = 0;
            for (int x = -reach; x <= reach; x++)
                for (int y = -reach; y <= reach; y++)
                    for (int z = -reach; z <= reach; z++)
                        if (x * x + y * y + z * z < ratio * ratio) count++;
            return count;
        }

        [TestCase(KernelFamily.CubicSpline, 2f, 51)]
        [TestCase(KernelFamily.WendlandC2, 2.85f, 146)]
        public void AListHoldsHalfAsManyAgainAsTheLatticeNeighbours(KernelFamily kernel, float supportRatio, int expected)
        {
            int capacity = NeighbourCapacity.For(Settings(PressureSolver.Dfsph, kernel, supportRatio), 10000, NeighbourCapacity.MaxListBytes);
            int atRest = LatticeNeighbours(supportRatio);
            TestContext.Progress.WriteLine($"{kernel} at {supportRatio} spacings: {atRest} lattice neighbours, {capacity} entries");
            Assert.That(capacity, Is.EqualTo(expected));
            Assert.That(capacity, Is.GreaterThanOrEqualTo(1.45 * atRest));
        }

        [Test]
        public void WcsphHasTheSameListsAndReadsThemInOneLaneOnly()
        {
            Assert.That(NeighbourCapacity.For(Settings(PressureSolver.Wcsph, KernelFamily.CubicSpline, 2f), 10000, NeighbourCapacity.MaxListBytes), Is.EqualTo(51 + NeighbourCapacity.RowWords));
            Assert.That(NeighbourCapacity.ListRows(PressureSolver.Wcsph), Is.EqualTo(25), "the grid walk's order: 5 x 5 rows of cells of h/2");
            Assert.That(NeighbourCapacity.ListRows(PressureSolver.Dfsph), Is.EqualTo(1));
            Assert.That(NeighbourCapacity.InUse(PressureSolver.Wcsph, 1), Is.True);
            Assert.That(NeighbourCapacity.InUse(PressureSolver.Wcsph, 2), Is.False);
            Assert.That(NeighbourCapacity.InUse(PressureSolver.Wcsph, 8), Is.False);
            Assert.That(NeighbourCapacity.InUse(PressureSolver.Dfsph, 1), Is.True);
            Assert.That(NeighbourCapacity.InUse(PressureSolver.Dfsph, 8), Is.True);
        }

        [Test]
        public void ListsLargerThanOneBufferAreNotKept()
        {
            var settings = Settings(PressureSolver.Dfsph, KernelFamily.WendlandC2, 2.85f);
            int fits = (int)(NeighbourCapacity.MaxListBytes / (4 * 146));
            Assert.That(NeighbourCapacity.For(settings, fits, long.MaxValue), Is.EqualTo(146));
            Assert.That(NeighbourCapacity.For(settings, fits + 1, long.MaxValue), Is.EqualTo(0), "the particles walk the grid instead");
        }

        /// <summary>lavapipe binds at most 128 MiB in one buffer: lists past it were refused by the device (a run of OilAndWater
        /// at 208 000 particles stopped with "unexpected failure") instead of left to the grid walk.</summary>
        [Test]
        public void ListsLargerThanTheDevicesLargestBufferAreNotKept()
        {
            var settings = Settings(PressureSolver.Dfsph, KernelFamily.WendlandC2, 2.85f);
            const long lavapipe = 128L << 20;
            int fits = (int)(lavapipe / (4 * 146));
            Assert.That(NeighbourCapacity.For(settings, fits, lavapipe), Is.EqualTo(146));
            Assert.That(NeighbourCapacity.For(settings, fits + 1, lavapipe), Is.EqualTo(0));
        }
    }
}
