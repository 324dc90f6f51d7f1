using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>The rounds recorded per DFSPH solve (SolveBudget.Next, issue #8): twice the most iterations read back
    /// plus four, at least doubled after a cut-off, at least 3 but never above MaxSolverIterations, unchanged when no solve ran.</summary>
    public sealed class SolveBudgetTests
    {
        [TestCase(100, 6, 0, 100, ExpectedResult = 16, TestName = "SolveBudget_TwiceTheMostPlusFour")]
        [TestCase(16, 0, 0, 100, ExpectedResult = 16, TestName = "SolveBudget_NoSolveKeepsTheBudget")]
        [TestCase(8, 8, 1, 100, ExpectedResult = 20, TestName = "SolveBudget_CutOffTakesTheLargerOfBoth")]
        [TestCase(30, 30, 1, 100, ExpectedResult = 64, TestName = "SolveBudget_CutOffAtLeastDoubles")]
        [TestCase(60, 60, 1, 100, ExpectedResult = 100, TestName = "SolveBudget_NeverAboveTheMaximum")]
        [TestCase(8, 1, 0, 100, ExpectedResult = 6, TestName = "SolveBudget_OneIterationStillGetsItsMargin")]
        [TestCase(8, 0, 1, 2, ExpectedResult = 2, TestName = "SolveBudget_AMaximumBelowThreeWins")]
        public int Budget(int rounds, int most, int cutOff, int max) => SolveBudget.Next(rounds, most, cutOff, max);
    }
}
