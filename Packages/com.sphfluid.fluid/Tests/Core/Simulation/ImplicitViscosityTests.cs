using System;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// The implicit viscosity solve's rounds (ImplicitViscosity): the fewest that take every wave's error in the interval
    /// down to the tolerance by Chebyshev's bound, growing as the square root of the step where explicit sub-steps grow
    /// as the step. ViscositySolveTests holds the GPU's solve to backward Euler's equation.
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

        /// <summary>At the 6.5 explicit limits OilAndWater's oil of 100 Pa s meets, 17 rounds (a neighbour pass each) stand
        /// in for 6.5 sub-steps (each with both pressure solves, a sort and four neighbour passes besides); at ten times
        /// the step, three times the rounds stand in for 65.</summary>
        [Test]
        public void TheRoundsGrowAsTheSquareRootOfTheStep()
        {
            int six = ImplicitViscosity.For(KernelFamily.WendlandC2, Spacing, Support, Nu, 6.5 * ExplicitLimit).Rounds;
            int sixtyFive = ImplicitViscosity.For(KernelFamily.WendlandC2, Spacing, Support, Nu, 65 * ExplicitLimit).Rounds;
            Assert.That(six, Is.InRange(15, 19));
            Assert.That((double)sixtyFive / six, Is.InRange(2.5, 3.5));
        }

        [Test]
        public void OnlyADivergenceFreeStepBeyondTheExplicitLimitSolvesIt()
        {
            Assert.That(ImplicitViscosity.Needed(PressureSolver.Dfsph, 1.01 * ExplicitLimit, ExplicitLimit), Is.True);
            Assert.That(ImplicitViscosity.Needed(PressureSolver.Dfsph, ExplicitLimit, ExplicitLimit), Is.False);
            Assert.That(ImplicitViscosity.Needed(PressureSolver.Wcsph, 10 * ExplicitLimit, ExplicitLimit), Is.False);
            Assert.That(ImplicitViscosity.Needed(PressureSolver.Dfsph, 0.005, double.PositiveInfinity), Is.False, "no viscosity");
        }
    }
}
