using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// The eigenvalue interval DFSPH's Chebyshev-accelerated solve is tuned for (ChebyshevBounds): its top is the lattice's
    /// stiffest wave with a margin, and at least the relaxed Jacobi step's stability bound, its bottom the quarter wave of
    /// the fluid's depth, at most TunedDepth spacings.
    /// </summary>
    public sealed class ChebyshevBoundsTests
    {
        const double Spacing = 0.02;

        /// <summary>Wendland C2 at 2.85 spacings, lambda_max 5.38 (SolverRelaxationTests), relaxed near its stability bound
        /// (2 / 5.38 = 0.372): the stiffest relaxed wave with its margin is above 2.</summary>
        [Test]
        public void TheTopIsTheStiffestRelaxedWaveWithItsMargin()
        {
            var (_, high) = ChebyshevBounds.For(KernelFamily.WendlandC2, Spacing, 2.85 * Spacing, 0.37, 0.2);
            Assert.That(high, Is.EqualTo(ChebyshevBounds.Margin * 0.37 * 5.38).Within(0.005));
        }

        /// <summary>OilAndWater's solve, relaxed to 0.3: its stiffest lattice wave with the margin is 1.70, below the
        /// Jacobi step's bound of 2, which the top takes instead.</summary>
        [Test]
        public void TheTopIsAtLeastTheJacobiStepsStabilityBound()
        {
            var (_, high) = ChebyshevBounds.For(KernelFamily.WendlandC2, Spacing, 2.85 * Spacing, 0.3, 0.2);
            Assert.That(ChebyshevBounds.Margin * 0.3 * 5.38, Is.LessThan(ChebyshevBounds.JacobiLimit));
            Assert.That(high, Is.EqualTo(ChebyshevBounds.JacobiLimit));
        }

        /// <summary>A long wave's eigenvalue goes with k^2, so with 1 / n^2 for a column of n spacings: about 8 (k s)^2 for Wendland
        /// C2 at 2.85 spacings, k = pi / (2 n s), that is 20 / n^2 before the relaxation.</summary>
        [TestCase(8)]
        [TestCase(32)]
        [TestCase(ChebyshevBounds.TunedDepth)]
        public void TheBottomIsTheQuarterWaveOfTheDepth(int spacings)
        {
            var (low, _) = ChebyshevBounds.For(KernelFamily.WendlandC2, Spacing, 2.85 * Spacing, 0.3, spacings * Spacing);
            Assert.That(low * spacings * spacings / 0.3, Is.EqualTo(20.0).Within(0.5));
        }

        /// <summary>Below the tuned depth's quarter wave the interval does not go, however deep the fluid.</summary>
        [TestCase(80)]
        [TestCase(1000)]
        public void ADeeperFluidIsTunedAsTheTunedDepth(int spacings)
        {
            var (tuned, _) = ChebyshevBounds.For(KernelFamily.WendlandC2, Spacing, 2.85 * Spacing, 0.3, ChebyshevBounds.TunedDepth * Spacing);
            var (low, _) = ChebyshevBounds.For(KernelFamily.WendlandC2, Spacing, 2.85 * Spacing, 0.3, spacings * Spacing);
            Assert.That(low, Is.EqualTo(tuned));
        }

        /// <summary>The constant-density solve is accelerated below the crossover tolerance and takes Jacobi steps at or above
        /// it, which lies within the brackets measured on OilAndWater (ChebyshevBounds.DensityCrossover): at 8.5 spacings
        /// deep (1 080 particles) the accelerated solve is cheaper at 0.1 % and ties at 0.2 %; at 13.4 (its 4 160) cheaper
        /// at 0.1 %, dearer at 0.3 %; at 24.4 (25 900) cheaper at 0.3 %, dearer at 0.5 %.</summary>
        [TestCase(8.5, 0.1f, true)]
        [TestCase(8.5, 0.2f, false)]
        [TestCase(13.4, 0.1f, true)]
        [TestCase(13.4, 0.3f, false)]
        [TestCase(24.4, 0.3f, true)]
        [TestCase(24.4, 0.5f, false)]
        [TestCase(24.4, 1f, false)]
        public void TheConstantDensitySolveIsAcceleratedBelowTheMeasuredCrossover(double spacings, float tolerance, bool accelerated) =>
            Assert.That(ChebyshevBounds.AcceleratesDensitySolve(tolerance, spacings * Spacing, Spacing), Is.EqualTo(accelerated));

        /// <summary>The crossover grows with the depth: a Jacobi solve's rounds grow with the square of it.</summary>
        [Test]
        public void ADeeperFluidIsAcceleratedAtLooserTolerances()
        {
            Assert.That(ChebyshevBounds.AcceleratesDensitySolve(1f, 40 * Spacing, Spacing), Is.False, "40 spacings at 1 %");
            Assert.That(ChebyshevBounds.AcceleratesDensitySolve(1f, 83 * Spacing, Spacing), Is.True, "83 spacings (1M particles) at 1 %");
        }

        [Test]
        public void AColumnOfOneSpacingKeepsTheIntervalOpen()
        {
            var (low, high) = ChebyshevBounds.For(KernelFamily.CubicSpline, Spacing, 2 * Spacing, 1.0, Spacing);
            Assert.That(low, Is.EqualTo(0.5 * high).Within(1e-12));
        }
    }
}
