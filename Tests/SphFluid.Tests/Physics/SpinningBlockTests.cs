using System;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// Conservation of angular momentum: the inviscid spinning block of <see cref="SpinningBlock"/> (12 particles a side,
    /// 1 cm spacings, no physical viscosity; WCSPH keeps its artificial viscosity, a central pair force) keeps the angular
    /// momentum it was spawned with, and stays at rest as a whole, for a quarter second under each solver. A viscous
    /// spin keeps it under the strain rate's viscous stress, and under Morris's Laplacian does not (known limits,
    /// "Morris's viscosity, the default, brakes a spinning liquid"; <see cref="SpinningBlockProbe"/>).
    /// </summary>
    [TestFixture(PressureSolver.Wcsph)]
    [TestFixture(PressureSolver.Dfsph)]
    public sealed class SpinningBlockTests
    {
        readonly PressureSolver _solver;
        double _kept, _drift;

        public SpinningBlockTests(PressureSolver solver) => _solver = solver;

        [OneTimeSetUp]
        public void SpinAQuarterSecond()
        {
            using var sim = SpinningBlock.Spinning(_solver, SpinningBlock.Side / 12, 0f, out var particles);
            double start = SpinningBlock.AngularMomentum(particles);
            while (sim.SimulatedTime < 0.25 - 1e-6) sim.Step(1f / 60f);
            sim.Particles.GetData(particles);
            _kept = SpinningBlock.AngularMomentum(particles) / start;
            _drift = SpinningBlock.Drift(particles);
            TestContext.Progress.WriteLine($"inviscid spinning block, {_solver}, {particles.Length} particles, 0.25 s: " +
                $"angular momentum kept {_kept:F6}, mean velocity {_drift:E2} m/s (the corners spin at {SpinningBlock.Omega * SpinningBlock.Side / Math.Sqrt(2):F3})");
        }

        [Test]
        public void TheAngularMomentumStays() => Assert.That(_kept, Is.EqualTo(1.0).Within(1e-4));

        [Test]
        public void TheBlockStaysAtRestAsAWhole() => Assert.That(_drift, Is.LessThan(1e-5));

        /// <summary>At 10 Pa s (8 particles a side, 15 mm) the strain rate's stress keeps the angular momentum to 1e-3 where
        /// Morris's keeps 0.16 of it (SpinningBlockProbe). DFSPH's sub-steps are 2.2 times the explicit viscous limit, so its
        /// viscosity is the implicit solve's, with the rotation term lagged in the forces (SphViscosity.hlsl).</summary>
        [Test]
        public void AViscousSpinKeepsItsAngularMomentumUnderTheStrainRatesStress()
        {
            using var sim = SpinningBlock.Spinning(_solver, SpinningBlock.Side / 8, 10f, out var particles, ViscousStress.StrainRate);
            double start = SpinningBlock.AngularMomentum(particles);
            while (sim.SimulatedTime < 0.25 - 1e-6) sim.Step(1f / 60f);
            sim.Particles.GetData(particles);
            double kept = SpinningBlock.AngularMomentum(particles) / start;
            double limits = sim.LastStep.TimeStep / TimeStepController.ForScene(sim.Scene).ViscousTimeStep;
            TestContext.Progress.WriteLine($"spinning block at 10 Pa s, strain-rate stress, {_solver}, {particles.Length} particles, 0.25 s: " +
                $"angular momentum kept {kept:F6}; last sub-step {limits:F1} explicit viscous limits{(sim.Plan.ImplicitViscosity ? ", implicit" : "")}");
            Assert.That(kept, Is.EqualTo(1.0).Within(1e-3));
            if (_solver == PressureSolver.Dfsph) Assert.That(limits, Is.GreaterThan(2.0), "the implicit solve is what is tested");
        }
    }
}
