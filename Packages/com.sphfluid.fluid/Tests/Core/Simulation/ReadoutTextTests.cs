using System.Text;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>The readouts' cost line in the accuracy-for-time study's currency: GPU seconds per simulated second and
    /// the real-time factor they allow, from a frame's GPU time and the sub-steps that covered it.</summary>
    public sealed class ReadoutTextTests
    {
        [Test]
        public void GpuCostIsPerSubStepAndPerSimulatedSecond()
        {
            // Four sub-steps of 1/240 s cover a 60 Hz frame; 2.5 ms of GPU for it is 0.15 s a simulated second.
            var step = new StepReport(4, 1f / 240f, 4f / 240f, false, 1f / 240f, "cfl", PressureSolver.Dfsph);
            string text = ReadoutText.AppendGpuCost(new StringBuilder(), 2.5, step).ToString();
            Assert.That(text, Is.EqualTo("GPU 2.50 ms per frame, 0.625 ms per sub-step, 0.150 s per simulated s (at most 6.67x real time)"));
        }

        [Test]
        public void AFrameThatAdvancedNothingHasNoCostPerSimulatedSecond()
        {
            string paused = ReadoutText.AppendGpuCost(new StringBuilder(), 0.0, StepReport.None).ToString();
            Assert.That(paused, Is.EqualTo("GPU 0.00 ms per frame, 0.000 ms per sub-step"));
        }

        [Test]
        public void TheViscositySolveIsNamedOnlyWhereItRan()
        {
            Assert.That(ReadoutText.AppendViscositySolve(new StringBuilder(), 0).ToString(), Is.Empty);
            Assert.That(ReadoutText.AppendViscositySolve(new StringBuilder(), 20).ToString(),
                Is.EqualTo("Viscosity solved implicitly: 20 rounds per sub-step"));
        }

        [TestCase(SolverIteration.Jacobi, true, "Jacobi")]
        [TestCase(SolverIteration.Jacobi, false, "Jacobi")]
        [TestCase(SolverIteration.Chebyshev, true, "Chebyshev")]
        [TestCase(SolverIteration.Chebyshev, false, "Chebyshev (divergence-free; density Jacobi)")]
        public void TheIterationNameSaysWhichSolvesTheChebyshevSettingAccelerates(SolverIteration iteration, bool accelerates, string name)
        {
            Assert.That(ReadoutText.IterationName(iteration, accelerates), Is.EqualTo(name));
        }
    }
}
