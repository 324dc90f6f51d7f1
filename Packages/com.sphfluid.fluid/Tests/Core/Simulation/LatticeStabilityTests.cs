using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// The spawn lattice's stability under pressure (LatticeStability), at the resting tank's mid-depth pressure
    /// (rho0 g 0.15 m: the tank of RestingTankTests, 0.3 m of water) and spacing (25 mm). It must say what the tank
    /// measured: the cubic spline at 2 spacings grows (measured at about 17/s from a balanced state, whatever the time
    /// step and the stiffness: TankEquilibriumProbe), Wendland C2 at 3 and 4 spacings grows at most slowly (measured
    /// decaying: what little the lattice gains, the artificial viscosity takes), and Wendland C2 at 2.8 to 2.9 spacings
    /// does not grow at all. Prints each kernel's growth rate.
    /// </summary>
    public sealed class LatticeStabilityTests
    {
        const double Spacing = 0.025, RestDensity = 1000.0, MidDepthPressure = RestDensity * 9.81 * 0.15;

        static double Growth(KernelFamily kind, double supportRatio)
        {
            double sigma = LatticeStability.GrowthRate(kind, Spacing, supportRatio * Spacing, MidDepthPressure, RestDensity);
            TestContext.Progress.WriteLine($"lattice under {MidDepthPressure:F0} Pa: {kind} at {supportRatio} spacings grows at {sigma:F1}/s");
            return sigma;
        }

        [Test]
        public void TheCubicSplineAtTwoSpacingsIsUnstableUnderPressure() =>
            Assert.That(Growth(KernelFamily.CubicSpline, 2.0), Is.GreaterThan(10.0));

        [TestCase(2.8)]
        [TestCase(2.85)]
        [TestCase(2.9)]
        public void WendlandC2NearThreeSpacingsIsStable(double supportRatio) =>
            Assert.That(Growth(KernelFamily.WendlandC2, supportRatio), Is.EqualTo(0.0));

        [TestCase(3.0)]
        [TestCase(4.0)]
        public void WendlandC2AtThreeAndFourSpacingsGrowsSlowly(double supportRatio) =>
            Assert.That(Growth(KernelFamily.WendlandC2, supportRatio), Is.LessThan(5.0));
    }
}
