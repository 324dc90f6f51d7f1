using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>The rounds recorded per DFSPH solve (FluidSimulation.SolveBudget, issue #8): twice the most iterations read back
    /// plus four, shrinking by at most a quarter a read-back, at least doubled after a cut-off, at least 3 but never above
    /// MaxSolverIterations, unchanged when no solve ran.</summary>
    public sealed class SolveBudgetTests
    {
        [TestCase(16, 6, 0, 100, ExpectedResult = 16, TestName = "SolveBudget_TwiceTheMostPlusFour")]
        [TestCase(10, 6, 0, 100, ExpectedResult = 16, TestName = "SolveBudget_GrowsAtOnceToTwiceTheMostPlusFour")]
        [TestCase(100, 6, 0, 100, ExpectedResult = 75, TestName = "SolveBudget_ShrinksByAQuarterAtMost")]
        [TestCase(20, 6, 0, 100, ExpectedResult = 16, TestName = "SolveBudget_ShrinksNoFurtherThanTwiceTheMostPlusFour")]
        [TestCase(16, 0, 0, 100, ExpectedResult = 16, TestName = "SolveBudget_NoSolveKeepsTheBudget")]
        [TestCase(8, 8, 1, 100, ExpectedResult = 20, TestName = "SolveBudget_CutOffTakesTheLargerOfBoth")]
        [TestCase(30, 30, 1, 100, ExpectedResult = 64, TestName = "SolveBudget_CutOffAtLeastDoubles")]
        [TestCase(60, 60, 1, 100, ExpectedResult = 100, TestName = "SolveBudget_NeverAboveTheMaximum")]
        [TestCase(8, 1, 0, 100, ExpectedResult = 6, TestName = "SolveBudget_OneIterationStillGetsItsMargin")]
        [TestCase(8, 0, 1, 2, ExpectedResult = 2, TestName = "SolveBudget_AMaximumBelowThreeWins")]
        public int Budget(int rounds, int most, int cutOff, int max) => FluidSimulation.SolveBudget(rounds, most, cutOff, max);

        /// <summary>From the spawn's budget of MaxSolverIterations, solves of two iterations bring it to 2 x 2 + 4 within ten
        /// read-backs and hold it there; a cut-off at 8 rounds then doubles it, and it comes back down in four.</summary>
        [Test]
        public void TheBudgetSettlesOnTwiceTheNeedsPlusFourAndComesBackAfterACutOff()
        {
            int rounds = 100;
            var path = new System.Collections.Generic.List<int>();
            for (int readBack = 0; readBack < 10; readBack++) path.Add(rounds = FluidSimulation.SolveBudget(rounds, 2, 0, 100));
            Assert.That(path, Is.EqualTo(new[] { 75, 57, 43, 33, 25, 19, 15, 12, 9, 8 }));
            Assert.That(FluidSimulation.SolveBudget(rounds, 2, 0, 100), Is.EqualTo(8), "steady");
            rounds = FluidSimulation.SolveBudget(rounds, 8, 1, 100);
            Assert.That(rounds, Is.EqualTo(20));
            path.Clear();
            for (int readBack = 0; readBack < 4; readBack++) path.Add(rounds = FluidSimulation.SolveBudget(rounds, 2, 0, 100));
            Assert.That(path, Is.EqualTo(new[] { 15, 12, 9, 8 }));
        }
    }
}
