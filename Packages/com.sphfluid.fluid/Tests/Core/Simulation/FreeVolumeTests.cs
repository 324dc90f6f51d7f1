using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    public sealed class FreeVolumeTests
    {
        /// <summary>The test tank (0.5 m, s = 0.02) cut down to its liquids' top, 0.24 m above the floor, plus
        /// <paramref name="clearance"/> spacings: a flush lid, as the lock exchange's that stalled under DFSPH.</summary>
        static FluidSceneDescription Lidded(float clearance, PressureSolver solver = PressureSolver.Dfsph)
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Settings.PressureSolver = solver;
            float floor = -0.25f, top = -0.01f + clearance * scene.Settings.ParticleSpacing;
            scene.Container.Size = new Vector3(0.5f, top - floor, 0.5f);
            scene.Container.Position = new Vector3(0f, (top + floor) / 2f, 0f);
            Assert.That(scene.Validate(), Is.Empty);
            return scene;
        }

        [Test]
        public void AFluidThatFillsItsContainerIsWarnedOfUnderDfsphOnly()
        {
            string warning = FreeVolume.Warning(Lidded(0f));
            Assert.That(warning, Does.StartWith("under DFSPH the fluid (0.06 m^3) leaves "));
            Assert.That(warning, Does.Contain("of the closed 0.06 m^3 container free, less than the 6E-05 m^3 (DensityTolerance 0.1 % of the fluid's volume)"));
            Assert.That(warning, Does.Contain("(its height 0.00024"));
            Assert.That(FreeVolume.Warning(Lidded(0f, PressureSolver.Wcsph)), Is.Null, "WCSPH compresses instead");
        }

        [Test]
        public void ATenthOfASpacingAboveTheFluidIsRoomEnough()
        {
            // The lock exchange under a lid a tenth of a spacing up ran at 14 to 18 iterations, none cut off: its free
            // volume is 0.8 % of the fluid's here, eight times the 0.1 % tolerance.
            Assert.That(FreeVolume.Warning(Lidded(0.1f)), Is.Null);
            Assert.That(FreeVolume.Warning(SimulationTestScenes.OilOnWater()), Is.Null, "half full");
        }

        [Test]
        public void ASubmergedSphereLeavesTheRoomOfTheShellItDisplaces()
        {
            // The spawn leaves out the lattice points within half a spacing of a sphere's surface (SpawnLayout), more
            // volume than the sphere's own: a flush lid over a pool with a sphere in it leaves 3.6e-4 m^3 free.
            var scene = Lidded(0f);
            scene.Obstacles.Add(new RigidSphere(new Vector3(0f, -0.13f, 0f), 0.05f, Vector3.Zero));
            Assert.That(FreeVolume.Warning(scene), Is.Null, "0.1 % of the fluid's volume is 5.9e-5 m^3");
            scene.Settings.DensityTolerance = 1f;
            Assert.That(FreeVolume.Warning(scene), Does.Contain("and the sphere obstacles (0.000523599 m^3) leave 0.000364401 m^3"));
        }
    }
}
