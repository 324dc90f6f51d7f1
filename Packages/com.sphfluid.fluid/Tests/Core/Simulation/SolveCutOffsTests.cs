using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// How much of a run's time DFSPH's solves ran out of iterations (SolveCutOffs): each report's share weighted by the
    /// simulated time it covers, the first report (covering no solves) and a reset counting nothing, and a warning only for a
    /// DFSPH run above a tenth.
    /// </summary>
    public sealed class SolveCutOffsTests
    {
        static FluidSettings Dfsph() => new FluidSettings { PressureSolver = PressureSolver.Dfsph };

        [Test]
        public void EachReportIsWeightedByTheTimeItCovers()
        {
            var cutOffs = new SolveCutOffs();
            cutOffs.Observe(0.0, 1.0, 1.0); // the spawn's report: no solve before it
            cutOffs.Observe(0.1, 1.0, 0.0);
            cutOffs.Observe(0.4, 0.0, 0.5);

            Assert.That(cutOffs.ObservedSeconds, Is.EqualTo(0.4).Within(1e-12));
            Assert.That(cutOffs.DensityShare, Is.EqualTo(0.25).Within(1e-12));
            Assert.That(cutOffs.DivergenceShare, Is.EqualTo(0.375).Within(1e-12));
        }

        [Test]
        public void AReportAtTheSameTimeAddsNothingAndAnEarlierOneStartsAgain()
        {
            var cutOffs = new SolveCutOffs();
            cutOffs.Observe(0.0, 0.0, 0.0);
            cutOffs.Observe(1.0, 1.0, 0.0);
            cutOffs.Observe(1.0, 0.0, 0.0);
            Assert.That(cutOffs.DensityShare, Is.EqualTo(1.0));

            cutOffs.Observe(0.0, 0.0, 0.0); // a reset
            Assert.That(cutOffs.ObservedSeconds, Is.EqualTo(0.0));
            cutOffs.Observe(0.5, 0.0, 0.0);
            Assert.That(cutOffs.DensityShare, Is.EqualTo(0.0));
            Assert.That(cutOffs.ObservedSeconds, Is.EqualTo(0.5));
        }

        [Test]
        public void OnlyADfsphRunAboveATenthIsWarned()
        {
            var cutOffs = new SolveCutOffs();
            cutOffs.Observe(0.0, 0.0, 0.0);
            cutOffs.Observe(1.0, SolveCutOffs.WarningShare, 0.0);
            Assert.That(cutOffs.Warning(Dfsph()), Is.Null, "a tenth exactly");

            cutOffs.Observe(2.0, 1.0, 0.0);
            Assert.That(cutOffs.Warning(new FluidSettings { PressureSolver = PressureSolver.Wcsph }), Is.Null);
            string warning = cutOffs.Warning(Dfsph());
            Assert.That(warning, Does.StartWith("DFSPH's solves ran out of their 100 iterations (MaxSolverIterations) in 55 % of the " +
                "simulated time's constant-density solves and 0 % of its divergence-free ones: the errors exceeded the tolerances of 0.1 % and 10 %/s"));
            Assert.That(warning, Does.EndWith("a fluid that fills its closed container exactly cannot get below the tolerance."));
        }

        [Test]
        public void AJacobiRunIsToldOfTheAcceleratedSolveFirst()
        {
            var cutOffs = new SolveCutOffs();
            cutOffs.Observe(0.0, 0.0, 0.0);
            cutOffs.Observe(1.0, 0.5, 0.0);
            Assert.That(cutOffs.Warning(Dfsph()), Does.Contain("cost the whole budget. Set SolverIteration to Chebyshev (the Jacobi solve's " +
                "iterations grow with the square of the fluid's depth in spacings, the accelerated solve's with the depth), raise MaxSolverIterations"));
            var accelerated = Dfsph();
            accelerated.SolverIteration = SolverIteration.Chebyshev;
            Assert.That(cutOffs.Warning(accelerated), Does.Contain("cost the whole budget. Raise MaxSolverIterations").And.Not.Contain("Set SolverIteration"));
        }
    }
}
