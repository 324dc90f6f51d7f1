using System;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The spinning block of <see cref="SpinningBlock"/> with water at 10 Pa s (nu = 0.01 m^2/s) at 8, 12 and 16
    /// particles a side, and at water's 10^-3 Pa s at 12, under each solver. A rigid rotation is stress-free, so its angular momentum should stay; the
    /// probe prints what it keeps every 0.05 s, its decay rate fitted from 0.05 to 0.25 s, and the rate 2 nu / &lt;r^2&gt;
    /// that a viscous stress of mu grad v alone, without its transpose, would give (the torque of such a stress on a
    /// rigid rotation is -2 mu omega V). A measurement (about a minute of lavapipe), run by name:
    /// <c>bash Headless/test.sh --filter FullyQualifiedName~SpinningBlockProbe</c>.
    /// </summary>
    [Explicit("a measurement, a minute of lavapipe")]
    [TestFixture(PressureSolver.Wcsph)]
    [TestFixture(PressureSolver.Dfsph)]
    public sealed class SpinningBlockProbe
    {
        readonly PressureSolver _solver;

        public SpinningBlockProbe(PressureSolver solver) => _solver = solver;

        [TestCase(8, 10f)]
        [TestCase(12, 10f)]
        [TestCase(16, 10f)]
        [TestCase(12, 0.001f)]
        public void AngularMomentumOfAViscousSpin(int particlesASide, float viscosity)
        {
            float spacing = SpinningBlock.Side / particlesASide;
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, SpinningBlock.Scene(_solver, spacing, viscosity));
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            SpinningBlock.Spin(particles);
            sim.SetParticles(particles);
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
                $"{viscosity:G3} Pa s: angular momentum kept every 0.05 s {string.Join(", ", Array.ConvertAll(kept, k => k.ToString("F5")))}; " +
                $"decay {rate:G3} /s, against 0 for a Newtonian stress and {stressRate:G3} /s for mu grad v alone");
        }

        string SolverChoiceName => _solver == PressureSolver.Dfsph ? "DFSPH" : "WCSPH";
    }
}
