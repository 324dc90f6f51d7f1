using System;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// The implicit viscosity solve's rounds (ImplicitViscosity): the fewest that take every wave's error in the interval
    /// down to the tolerance by Chebyshev's bound, growing as the square root of the step where explicit sub-steps grow
    /// as the step. ViscositySolveTests holds the GPU's solve to the equations of its two stages.
    /// </summary>
    public sealed class ImplicitViscosityTests
    {
        const double Spacing = 0.015, Support = 2.85 * Spacing; // OilAndWater's lattice
        const double Nu = 100.0 / 900.0;                          // its oil at 100 Pa s

        static double ExplicitLimit => ViscousStepLimit.For(KernelFamily.WendlandC2, Spacing, Support, Nu);

        /// <summary>1 / T_K((b + a) / (b - a)): the bound on every wave's error after K rounds.</summary>
        static double Bound(ImplicitViscosity solve, int rounds)
        {
            double ratio = (ImplicitViscosity.High + solve.Low) / (ImplicitViscosity.High - solve.Low);
            return 1.0 / Math.Cosh(rounds * Math.Log(ratio + Math.Sqrt(ratio * ratio - 1.0)));
        }

        [TestCase(1.01)]
        [TestCase(6.5)]
        [TestCase(65.0)]
        public void TheRoundsAreTheFewestThatMeetTheTolerance(double explicitSteps)
        {
            var solve = ImplicitViscosity.For(KernelFamily.WendlandC2, Spacing, Support, Nu, explicitSteps * ExplicitLimit);
            TestContext.Progress.WriteLine($"{explicitSteps} explicit limits: a = {solve.Low:F4}, {solve.Rounds} rounds");
            Assert.That(Bound(solve, solve.Rounds), Is.LessThanOrEqualTo(ImplicitViscosity.Tolerance));
            if (solve.Rounds > 1)
                Assert.That(Bound(solve, solve.Rounds - 1), Is.GreaterThan(ImplicitViscosity.Tolerance));
            Assert.That(solve.Low, Is.GreaterThan(0f).And.LessThan(1f));
        }

        /// <summary>At the 6.5 explicit limits OilAndWater's oil of 100 Pa s meets, two stages of 10 rounds (a neighbour pass
        /// each) stand in for 6.5 sub-steps (each with both pressure solves, a sort and four neighbour passes besides); at
        /// ten times the step, about three times the rounds stand in for 65. A stage's step is gamma dt, so its rounds are
        /// those of one backward Euler solve of dt times about sqrt(gamma), 0.54: the two stages cost 1.08 times the one
        /// solve (17 rounds at 6.5 limits, 51 at 65).</summary>
        [Test]
        public void TheRoundsGrowAsTheSquareRootOfTheStep()
        {
            var six = ImplicitViscosity.For(KernelFamily.WendlandC2, Spacing, Support, Nu, 6.5 * ExplicitLimit);
            int sixtyFive = ImplicitViscosity.For(KernelFamily.WendlandC2, Spacing, Support, Nu, 65 * ExplicitLimit).Rounds;
            Assert.That(six.Rounds, Is.InRange(9, 11));
            Assert.That((double)sixtyFive / six.Rounds, Is.InRange(2.5, 3.5));
            Assert.That(six.StageStep, Is.EqualTo(ImplicitViscosity.StageFraction * 6.5 * ExplicitLimit).Within(1e-4).Percent);
            Assert.That(ImplicitViscosity.Stages * six.Rounds, Is.LessThanOrEqualTo(1.25 * 17), "about what one backward Euler solve of dt took");
        }

        /// <summary>Alexander's gamma: the two stages are second order only for gamma^2 - 2 gamma + 1/2 = 0, and L-stable
        /// for its root below one.</summary>
        [Test]
        public void TheStageFractionMakesTheStepSecondOrder()
        {
            double g = ImplicitViscosity.StageFraction;
            Assert.That(g * g - 2.0 * g + 0.5, Is.EqualTo(0.0).Within(1e-15));
            Assert.That(g, Is.GreaterThan(0.0).And.LessThan(1.0));
        }

        [Test]
        public void OnlyAStepBeyondTheExplicitLimitSolvesIt()
        {
            Assert.That(ImplicitViscosity.Needed(1.01 * ExplicitLimit, ExplicitLimit), Is.True);
            Assert.That(ImplicitViscosity.Needed(ExplicitLimit, ExplicitLimit), Is.False);
            Assert.That(ImplicitViscosity.Needed(0.005, double.PositiveInfinity), Is.False, "no viscosity");
        }

        /// <summary>Beyond the explicit limit DFSPH always solves; WCSPH only where its rounds cost less than the sub-steps they
        /// stand for: not at the 2.9 limits OilAndWater's oil at 100 Pa s meets at WCSPH's step, at ten limits and more.</summary>
        [Test]
        public void WcsphSolvesOnlyWhereItPaysOff()
        {
            double rowSum = ImplicitViscosity.LatticeRowSum(KernelFamily.WendlandC2, Spacing, Support);
            Assert.That(ImplicitViscosity.PaysOff(PressureSolver.Dfsph, 1.01 * ExplicitLimit, ExplicitLimit, rowSum, Nu), Is.True);
            Assert.That(ImplicitViscosity.PaysOff(PressureSolver.Wcsph, 2.9 * ExplicitLimit, ExplicitLimit, rowSum, Nu), Is.False);
            Assert.That(ImplicitViscosity.PaysOff(PressureSolver.Wcsph, 10 * ExplicitLimit, ExplicitLimit, rowSum, Nu), Is.True);
            Assert.That(ImplicitViscosity.PaysOff(PressureSolver.Wcsph, 100 * ExplicitLimit, ExplicitLimit, rowSum, Nu), Is.True);
            Assert.That(ImplicitViscosity.PaysOff(PressureSolver.Dfsph, ExplicitLimit, ExplicitLimit, rowSum, Nu), Is.False, "within the limit");
        }

        /// <summary>DFSPH solves once a sub-step over its whole step; WCSPH on each half kick, over half of it.</summary>
        [Test]
        public void WcsphSolvesEachHalfKick()
        {
            Assert.That(ImplicitViscosity.SolvesPerStep(PressureSolver.Dfsph), Is.EqualTo(1));
            Assert.That(ImplicitViscosity.Span(PressureSolver.Dfsph, 0.004), Is.EqualTo(0.004));
            Assert.That(ImplicitViscosity.SolvesPerStep(PressureSolver.Wcsph), Is.EqualTo(2));
            Assert.That(ImplicitViscosity.Span(PressureSolver.Wcsph, 0.004), Is.EqualTo(0.002));
        }
    }
}
