using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// The divergence-free solve's stop rate (DivergenceSolveTolerance): the setting's rate a second at the shipped
    /// scenes' sub-steps, and at a shorter sub-step the density change a sub-step the setting allows over a 60 Hz frame's
    /// quarter, whatever the density tolerance.
    /// </summary>
    public sealed class DivergenceSolveToleranceTests
    {
        static FluidSettings Dfsph(float divergence = 10f, float density = 0.1f) =>
            new FluidSettings { PressureSolver = PressureSolver.Dfsph, DivergenceTolerance = divergence, DensityTolerance = density };

        /// <summary>OilAndWater's 4.17 ms sub-steps (a 60 Hz frame in four) and the 5 ms of MaxTimeStep keep 10 %/s.</summary>
        [TestCase(1f / 240f)]
        [TestCase(0.005f)]
        public void AtTheShippedScenesSubStepsTheRateIsTheSettings(float dt) =>
            Assert.That(DivergenceSolveTolerance.At(Dfsph(), dt), Is.EqualTo(0.1f).Within(1e-7));

        /// <summary>At the 1M spacing's 1.39 ms sub-steps 10 %/s would allow 0.014 % a sub-step; the solve accepts the
        /// 0.042 % of 4.17 ms, 30 %/s.</summary>
        [Test]
        public void AtAShortSubStepTheDensityChangeASubStepIsHeld()
        {
            float dt = 1f / 720f;
            float rate = DivergenceSolveTolerance.At(Dfsph(), dt);
            Assert.That(rate, Is.EqualTo(0.3f).Within(1e-6));
            Assert.That(rate * dt, Is.EqualTo(0.1f * DivergenceSolveTolerance.ReferenceStep).Within(1e-9));
        }

        [Test]
        public void ATighterSettingStaysAsMuchTighter_AndTheDensityToleranceDoesNotMoveIt()
        {
            float dt = 0.001f;
            float shipped = DivergenceSolveTolerance.At(Dfsph(), dt);
            Assert.That(DivergenceSolveTolerance.At(Dfsph(divergence: 0.01f), dt), Is.EqualTo(shipped / 1000f).Within(1e-9));
            Assert.That(DivergenceSolveTolerance.At(Dfsph(density: 1f), dt), Is.EqualTo(shipped));
            Assert.That(DivergenceSolveTolerance.At(Dfsph(density: 0.01f), dt), Is.EqualTo(shipped));
        }

        [Test]
        public void BeforeAnyStepTheRateIsTheSettings()
        {
            Assert.That(DivergenceSolveTolerance.At(Dfsph(), 0f), Is.EqualTo(0.1f).Within(1e-7));
            Assert.That(DivergenceSolveTolerance.At(Dfsph(), float.NaN), Is.EqualTo(0.1f).Within(1e-7));
        }
    }
}
