using System;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Health
{
    /// <summary>Every entry that moves the fluid by a given step (StepFixed, and DFSPH's PredictVelocities and Drift, which
    /// tests drive) refuses a step that is not a finite number of seconds above zero, naming it and its range, and leaves
    /// the particles where they were.</summary>
    public sealed class StepArgumentTests
    {
        [TestCase(0f)]
        [TestCase(-0.001f)]
        [TestCase(float.NaN)]
        [TestCase(float.PositiveInfinity)]
        public void AStepThatIsNoStepIsRefused(float timeStep)
        {
            var scene = SolverKernelTests.RandomScene(false, false, false, false);
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            var before = new Particle[sim.ParticleCount];
            sim.Particles.GetData(before);
            foreach (var (name, step) in new (string, Action)[]
            {
                ("StepFixed", () => sim.StepFixed(1, timeStep)),
                ("PredictVelocities", () => sim.PredictVelocities(timeStep)),
                ("Drift", () => sim.Drift(timeStep)),
            })
            {
                var error = Assert.Throws<ArgumentOutOfRangeException>(() => step(), name);
                Assert.That(error!.ParamName, Is.EqualTo("timeStep"), name);
                Assert.That(error.Message, Does.Contain("finite number > 0 s"), name);
            }
            var after = new Particle[sim.ParticleCount];
            sim.Particles.GetData(after);
            for (int i = 0; i < after.Length; i++)
                Assert.That(after[i].Position, Is.EqualTo(before[i].Position), $"particle {i} moved");
        }
    }
}
