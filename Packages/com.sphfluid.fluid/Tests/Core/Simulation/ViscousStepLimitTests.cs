using System;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// The viscous step limit (ViscousStepLimit): the viscous force's waves on the particle lattice. Long waves must decay
    /// as the Navier-Stokes equations' nu k^2, or the force is not the liquid's viscosity; the stiffest wave sets the step,
    /// and the rule it replaced allowed steps beyond that wave's stability bound. The GPU force pass is held to the same
    /// waves in ViscousStepTests.
    /// </summary>
    public sealed class ViscousStepLimitTests
    {
        const double Spacing = 1.0;

        /// <summary>The shipped supports: the cubic spline at 2 spacings (DamBreak, Splash and the others) and Wendland C2
        /// at 2.85 (RestingTank, OilAndWater).</summary>
        [TestCase(KernelFamily.CubicSpline, 2.0, 5.82)]
        [TestCase(KernelFamily.WendlandC2, 2.85, 3.15)]
        public void TheStiffestWaveIsTheZonesCorner(KernelFamily kind, double supportRatio, double expected)
        {
            double support = supportRatio * Spacing;
            double stiffest = ViscousStepLimit.StiffestMode(kind, Spacing, support);
            double corner = ViscousStepLimit.Mode(kind, Spacing, support, Math.PI, Math.PI, Math.PI);
            double rows = ViscousStepLimit.RowBound(kind, Spacing, support);
            TestContext.Progress.WriteLine($"{kind} at {supportRatio} spacings: Lambda_max s^2 {stiffest:F3} (corner {corner:F3}, " +
                $"Gershgorin {rows:F3}); step {1.0 / stiffest:F3} s^2/nu, bound 2 / Lambda_max {2.0 / stiffest:F3}, " +
                $"the old 0.125 H^2 {0.125 * support * support:F3}");
            Assert.That(stiffest, Is.EqualTo(expected).Within(0.01));
            Assert.That(corner, Is.EqualTo(stiffest).Within(1e-9 * stiffest), "neighbours an odd number of steps away move against each other");
            Assert.That(stiffest, Is.LessThanOrEqualTo(rows));
            // At the step allowed, the Gershgorin bound too (any velocities, still walls in place of neighbours) stays stable.
            Assert.That(rows / stiffest, Is.LessThan(2.0));
            Assert.That(0.125 * support * support, Is.GreaterThan(2.0 / stiffest), "the old rule allowed steps that make this wave grow");
        }

        /// <summary>Long waves decay at nu k^2 Lambda(k) / k^2: within 1 % of the liquid's nu k^2 for the cubic spline at 2
        /// spacings, and 4.8 % short for Wendland C2 at 2.85, where the force's 0.01 H^2 in the denominator takes more.</summary>
        [TestCase(KernelFamily.CubicSpline, 2.0, 0.991)]
        [TestCase(KernelFamily.WendlandC2, 2.85, 0.952)]
        public void LongWavesDecayAsTheLiquidsViscosity(KernelFamily kind, double supportRatio, double expected)
        {
            double support = supportRatio * Spacing;
            foreach (double k in new[] { 0.02, 0.1 })
            {
                double along = ViscousStepLimit.Mode(kind, Spacing, support, k, 0, 0) / (k * k);
                double diagonal = ViscousStepLimit.Mode(kind, Spacing, support, k / Math.Sqrt(3), k / Math.Sqrt(3), k / Math.Sqrt(3)) / (k * k);
                TestContext.Progress.WriteLine($"{kind} at {supportRatio} spacings, k s = {k}: Lambda / k^2 {along:F4} along an axis, {diagonal:F4} along a diagonal");
                Assert.That(along, Is.EqualTo(expected).Within(0.002));
                Assert.That(diagonal, Is.EqualTo(along).Within(0.002), "isotropic");
            }
        }

        [Test]
        public void TheStepScalesWithTheSpacingSquaredOverNu()
        {
            double step = ViscousStepLimit.For(KernelFamily.WendlandC2, 0.015, 0.04275, 0.1 / 900.0);
            Assert.That(step, Is.EqualTo(1.0 / 3.15 * 0.015 * 0.015 * 900.0 / 0.1).Within(0.005 * step));
            Assert.That(ViscousStepLimit.For(KernelFamily.WendlandC2, 0.015, 0.04275, 0.0), Is.EqualTo(double.PositiveInfinity));
        }
    }
}
