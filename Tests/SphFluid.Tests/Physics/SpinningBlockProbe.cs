using System;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The spinning block of <see cref="SpinningBlock"/> with water at 10 Pa s (nu = 0.01 m^2/s) at 8, 12 and 16
    /// particles a side, and at water's 10^-3 Pa s at 12, under each solver. A rigid rotation is stress-free, so its
    /// angular momentum should stay; the probe prints what it keeps every 0.05 s, its decay rate fitted from 0.05 to
    /// 0.25 s, and the rate 2 nu / &lt;r^2&gt; that a viscous stress of mu grad v alone, without its transpose, would give
    /// (the torque of such a stress on a rigid rotation is -2 mu omega V). Morris's viscous force is such a stress at
    /// a free surface; the experiment rotation-free-viscosity keeps the spin. A measurement (about a minute of
    /// lavapipe), run by name:
    /// <c>bash Headless/test.sh --filter FullyQualifiedName~SpinningBlockProbe</c>.
    /// </summary>
    [Explicit("a measurement, a minute of lavapipe")]
    [TestFixture(PressureSolver.Wcsph)]
    [TestFixture(PressureSolver.Dfsph)]
    public sealed class SpinningBlockProbe
    {
        readonly PressureSolver _solver;

        public SpinningBlockProbe(PressureSolver solver) => _solver = solver;

        [TestCase(8, 10f, ViscousStress.Laplacian)]
        [TestCase(12, 10f, ViscousStress.Laplacian)]
        [TestCase(16, 10f, ViscousStress.Laplacian)]
        [TestCase(12, 0.001f, ViscousStress.Laplacian)]
        [TestCase(8, 10f, ViscousStress.StrainRate)]
        [TestCase(12, 10f, ViscousStress.StrainRate)]
        [TestCase(16, 10f, ViscousStress.StrainRate)]
        public void AngularMomentumOfAViscousSpin(int particlesASide, float viscosity, ViscousStress stress)
        {
            float spacing = SpinningBlock.Side / particlesASide;
            using var sim = SpinningBlock.Spinning(_solver, spacing, viscosity, out var particles, stress);
            double start = SpinningBlock.AngularMomentum(particles);
            double stressRate = 2.0 * viscosity / 1000.0 / SpinningBlock.MeanSquaredRadius(particles);
            var kept = new double[6];
            for (int sample = 0; sample < kept.Length; sample++)
            {
                while (sim.SimulatedTime < 0.05 * sample - 1e-6) sim.Step(1f / 60f);
                sim.Particles.GetData(particles);
                kept[sample] = SpinningBlock.AngularMomentum(particles) / start;
            }
            double rate = Math.Log(kept[1] / kept[5]) / 0.2;
            TestContext.Progress.WriteLine($"{SolverChoiceName} {particlesASide}^3 ({particles.Length} particles, {1000 * spacing:F1} mm), " +
                $"{viscosity:G3} Pa s, {stress} stress{(sim.Plan.ImplicitViscosity ? ", implicit" : "")}: angular momentum kept every 0.05 s {string.Join(", ", Array.ConvertAll(kept, k => k.ToString("F5")))}; " +
                $"decay {rate:G3} /s, against 0 for a Newtonian stress and {stressRate:G3} /s for mu grad v alone");
        }

        /// <summary>What 2 nu / &lt;r^2&gt; makes of OilAndWater's oil (0.1 Pa s, 900 kg/m^3) spinning in a swirl 10 cm in radius
        /// (&lt;r^2&gt; = R^2 / 2): the e-folding time the docs quote.</summary>
        [Test]
        public void TheShippedOilsSpinDown()
        {
            double rate = 2.0 * (0.1 / 900.0) / (0.5 * 0.1 * 0.1);
            TestContext.Progress.WriteLine($"OilAndWater's oil in a swirl 10 cm in radius, by 2 nu / <r^2>: decay {rate:G3} /s, e-folding {1.0 / rate:F1} s");
        }

        string SolverChoiceName => _solver == PressureSolver.Dfsph ? "DFSPH" : "WCSPH";
    }
}
