using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// The threads per particle of the laned neighbour loops (NeighbourLanes): the most lanes, up to 8, that keep particles
    /// times lanes within the threads that fill a GPU; one on a CPU device; only powers of two that divide a thread group.
    /// </summary>
    public sealed class NeighbourLanesTests
    {
        [TestCase(1, ExpectedResult = 8)]
        [TestCase(4160, ExpectedResult = 8)]
        [TestCase(8192, ExpectedResult = 8)]
        [TestCase(8193, ExpectedResult = 4)]
        [TestCase(32768, ExpectedResult = 2)]
        [TestCase(32769, ExpectedResult = 1)]
        [TestCase(1000000, ExpectedResult = 1)]
        public int LanesFallWithTheParticleCount(int particles)
        {
            return NeighbourLanes.For(particles, false);
        }

        [Test]
        public void ACpuDeviceTakesOneLane()
        {
            Assert.That(NeighbourLanes.For(100, true), Is.EqualTo(1));
            Assert.That(NeighbourLanes.For(0, false), Is.EqualTo(1));
        }

        [TestCase(1, ExpectedResult = true)]
        [TestCase(2, ExpectedResult = true)]
        [TestCase(4, ExpectedResult = true)]
        [TestCase(8, ExpectedResult = true)]
        [TestCase(0, ExpectedResult = false)]
        [TestCase(3, ExpectedResult = false)]
        [TestCase(16, ExpectedResult = false)]
        [TestCase(-2, ExpectedResult = false)]
        public bool OnlyPowersOfTwoUpToEightAreLaneCounts(int lanes)
        {
            return NeighbourLanes.IsValid(lanes);
        }
    }
}
