using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// A scene too large for the device's largest buffer is refused with its counts and the device's limit (DeviceCapacity):
    /// until then lavapipe stopped a run of DamBreak at 5.9 million particles with "unexpected failure" from whichever
    /// buffer it refused first.
    /// </summary>
    public sealed class DeviceCapacityTests
    {
        const long Lavapipe = 128L << 20; // maxStorageBufferRange, and the least D3D11 guarantees

        [Test]
        public void LavapipesLargestBufferHoldsFourMillionParticles()
        {
            Assert.That(DeviceCapacity.MostParticles(Lavapipe), Is.EqualTo(4194304));
            Assert.That(DeviceCapacity.Problem(4194304, 4194304, Lavapipe, "llvmpipe"), Is.Null);
        }

        [Test]
        public void TooManyFluidParticlesAreNamedWithTheLimit()
        {
            Assert.That(DeviceCapacity.Problem(5898240, 1000, Lavapipe, "llvmpipe"), Is.EqualTo(
                "5898240 fluid particles need a buffer of 180 MiB (32 bytes each), more than the 128 MiB the device 'llvmpipe' " +
                "binds in one buffer: it holds at most 4194304 fluid and 4194304 wall particles"));
        }

        [Test]
        public void TooManyWallParticlesAreNamedAsWalls()
        {
            Assert.That(DeviceCapacity.Problem(1000, 4194305, Lavapipe, "llvmpipe"), Does.StartWith("4194305 wall particles need a buffer of 128 MiB"));
        }

        [Test]
        public void ANonPositiveLimitHoldsNothing()
        {
            Assert.That(DeviceCapacity.MostParticles(-1), Is.EqualTo(0));
            Assert.That(DeviceCapacity.Problem(1, 0, 0, "none"), Does.StartWith("1 fluid particles"));
        }
    }
}
