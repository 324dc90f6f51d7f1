using System;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// Under DFSPH OilAndWater's kinetic energy at 0.1 s follows the step (6.551 mJ at the scene's 4.17 ms sub-steps,
    /// 6.112 at 1.19 ms, 5.630 at 0.312 ms), but the lock exchange's flow does not: most of that energy belongs to the
    /// fluid at rest. The same tank with the oil at the water's rest density, where nothing should move, holds 1.519,
    /// 1.104 and 0.713 mJ, the particle motion of its free surface settling (the summed density reads the fluid missing
    /// above the top layers as expansion, so they sink until they reach rest density); the difference, the
    /// exchange's own energy, is 5.032, 5.008 and 4.917 mJ (Headless/docs/physics.md, "Whose energy follows the step";
    /// Headless/tools/step-energy-ladder.sh). So the scene's own step resolves the exchange: a quarter of it changes the
    /// exchange's energy by 0.5 %, where the scene's total changes by 7 %.
    /// </summary>
    [Category(TestProcesses.LongRuns)]
    public sealed class DivergenceFreeStepEnergyTests
    {
        const float Frame = 1f / 60f;
        const double Seconds = 0.1;

        /// <summary>OilAndWater under DFSPH with sub-steps of at most <paramref name="maxTimeStep"/>, its oil at
        /// <paramref name="oilDensity"/> (the still copy: the water's); its kinetic energy (J) and sub-step (s) at 0.1 s.</summary>
        static (double kinetic, float step) KineticEnergyAt(float maxTimeStep, float? oilDensity)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH OilAndWater"), Is.Null);
            scene.Settings.MaxTimeStep = maxTimeStep;
            if (oilDensity is { } density)
                scene.SpawnBoxes.Single(b => b.Phase.Name == "Oil").Phase.RestDensity = density;
            Assert.That(scene.Validate(), Is.Empty);

            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            do sim.Step(Frame);
            while (sim.SimulatedTime < Seconds - 1e-6);
            double kinetic = sim.ReadDiagnostics().KineticEnergy;
            TestContext.Progress.WriteLine($"DFSPH OilAndWater{(oilDensity.HasValue ? " (still: oil at the water's density)" : "")}, " +
                $"sub-steps of {1000 * sim.LastStep.TimeStep:F3} ms: kinetic energy {1000 * kinetic:F3} mJ at {sim.SimulatedTime:F3} s");
            return (kinetic, sim.LastStep.TimeStep);
        }

        [Test]
        public void TheExchangesOwnEnergyHoldsAtAQuarterOfTheScenesStep()
        {
            var scene = KineticEnergyAt(0.005f, null);
            var still = KineticEnergyAt(0.005f, 1000f);
            var quarterScene = KineticEnergyAt(0.00125f, null);
            var quarterStill = KineticEnergyAt(0.00125f, 1000f);

            Assert.That(quarterScene.step, Is.LessThan(0.3f * scene.step), "the edited runs take a quarter of the scene's step");
            double exchange = scene.kinetic - still.kinetic, quarterExchange = quarterScene.kinetic - quarterStill.kinetic;
            TestContext.Progress.WriteLine($"the exchange's own energy: {1000 * exchange:F3} mJ and {1000 * quarterExchange:F3} mJ " +
                $"({100 * (quarterExchange / exchange - 1):+0.00;-0.00} %); the scene's: {100 * (quarterScene.kinetic / scene.kinetic - 1):+0.00;-0.00} %");
            // Measured 0.5 %; without the jitter 0.7 %, and 0.8 % at a tenfold tighter density tolerance.
            Assert.That(Math.Abs(quarterExchange / exchange - 1), Is.LessThanOrEqualTo(0.015));
        }
    }
}
