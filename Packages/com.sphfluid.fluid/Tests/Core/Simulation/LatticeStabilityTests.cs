using System;
using System.Numerics;
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
    /// <para>
    /// The lattice's two shear moduli under pressure (the long-wave limit of the same stiffness) must be the second
    /// derivative of the number density under the matching volume-keeping strain, summed here independently; the
    /// figures that Headless/docs/physics.md's "Which waves run fast" reads off are pinned.
    /// </para>
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

        static readonly Vector3 X = Vector3.UnitX, Y = Vector3.UnitY, Diagonal = Vector3.Normalize(new Vector3(1, 1, 0)),
            OtherDiagonal = Vector3.Normalize(new Vector3(1, -1, 0));

        /// <summary>C44 / p and C' / p: along an axis moved along another, and along a face diagonal moved along the
        /// other.</summary>
        static (double Axis, double Diagonal) Moduli(KernelFamily kind, double supportRatio)
        {
            double support = supportRatio * Spacing;
            double axis = LatticeStability.ShearModulusRatio(kind, Spacing, support, X, Y);
            double diagonal = LatticeStability.ShearModulusRatio(kind, Spacing, support, Diagonal, OtherDiagonal);
            TestContext.Progress.WriteLine($"lattice shear moduli per unit pressure: {kind} at {supportRatio} spacings C44 / p {axis:F4}, C' / p {diagonal:F4}");
            return (axis, diagonal);
        }

        /// <summary>sum_j W(|F r_j|) / delta0 over the lattice for the in-plane deformation F = ((a, b), (c, d)).</summary>
        static double StrainedNumberDensity(KernelFamily kind, double support, double a, double b, double c, double d)
        {
            double sum = 0.0;
            int reach = (int)Math.Ceiling(support / Spacing) + 1;
            for (int i = -reach; i <= reach; i++)
                for (int j = -reach; j <= reach; j++)
                    for (int l = -reach; l <= reach; l++)
                    {
                        double x = (a * i + b * j) * Spacing, y = (c * i + d * j) * Spacing, z = l * Spacing;
                        sum += SmoothingKernels.Value(kind, Math.Sqrt(x * x + y * y + z * z), support);
                    }
            return sum / SmoothingKernels.LatticeNumberDensity(kind, Spacing, support);
        }

        /// <summary>The energy of a uniform strain at fixed pressure is p times the number density's change over delta0
        /// per unit volume, so each modulus is that change's second derivative: a simple shear gamma stores C44 gamma^2 /
        /// 2, a volume-keeping stretch exp(e) along x and shrink along y stores 2 C' e^2.</summary>
        [TestCase(KernelFamily.CubicSpline, 2.0)]
        [TestCase(KernelFamily.WendlandC2, 2.85)]
        [TestCase(KernelFamily.WendlandC2, 3.5)]
        public void TheModuliAreTheNumberDensitysCurvatureUnderStrain(KernelFamily kind, double supportRatio)
        {
            // A small step: at 2 spacings lattice points sit on the cubic spline's edge, where W ~ (1 - q)^3 is not smooth,
            // and a difference quotient there errs by about the step.
            double support = supportRatio * Spacing, h = 1e-5;
            var (axis, diagonal) = Moduli(kind, supportRatio);
            double rest = StrainedNumberDensity(kind, support, 1, 0, 0, 1);
            double simple = (StrainedNumberDensity(kind, support, 1, h, 0, 1) - 2 * rest + StrainedNumberDensity(kind, support, 1, -h, 0, 1)) / (h * h);
            double stretch = (StrainedNumberDensity(kind, support, Math.Exp(h), 0, 0, Math.Exp(-h)) - 2 * rest +
                              StrainedNumberDensity(kind, support, Math.Exp(-h), 0, 0, Math.Exp(h))) / (4 * h * h);
            // To a ten-thousandth of the pressure: a hundredth of the smallest figure the docs quote.
            Assert.That(axis, Is.EqualTo(simple).Within(1e-4));
            Assert.That(diagonal, Is.EqualTo(stretch).Within(1e-4));
        }

        [Test]
        public void TheAxisModulusIsTheSameForEveryPairOfAxes()
        {
            double support = 2.85 * Spacing, xy = LatticeStability.ShearModulusRatio(KernelFamily.WendlandC2, Spacing, support, X, Y);
            Assert.That(LatticeStability.ShearModulusRatio(KernelFamily.WendlandC2, Spacing, support, Vector3.UnitZ, X),
                Is.EqualTo(xy).Within(1e-6 * Math.Abs(xy)));
        }

        /// <summary>At the shipped 2.85 spacings the lattice resists stretching about twelve times as hard as a plane's
        /// slip, 7.6 % of the pressure; at 3 spacings half as hard; at 3.5 spacings it has next to no stiffness of either
        /// kind.</summary>
        [Test]
        public void WendlandC2AtTheScenesSupportResistsStretchingFarMoreThanSlip()
        {
            var (axis, diagonal) = Moduli(KernelFamily.WendlandC2, 2.85);
            Assert.That(diagonal, Is.InRange(0.07, 0.08));
            Assert.That(axis, Is.InRange(0.004, 0.008));
            Assert.That(Moduli(KernelFamily.WendlandC2, 3.0).Diagonal, Is.InRange(0.03, 0.04));
            var wide = Moduli(KernelFamily.WendlandC2, 3.5);
            Assert.That(Math.Abs(wide.Axis) + Math.Abs(wide.Diagonal), Is.LessThan(0.01));
        }
    }
}
