using System;
using System.Globalization;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Output;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The shipped dam break and oil-and-water scenes under DFSPH (issue #8). The dam break is loaded from a copy of the scene
    /// file with <c>settings.PressureSolver: 1</c> (the int Unity serialises the enum as), so the scene key is read as Unity
    /// writes it. Oil and water runs WCSPH and is switched as <c>--solver dfsph</c> switches it (SolverChoice.FitSupport: its
    /// DFSPH settings, Wendland C2 at 2.85 spacings relaxed to 0.3, fit, so it keeps them). The dam break must stay finite and
    /// lose nothing; the oil and water must layer as <see cref="SeparationTests"/> asks of WCSPH.
    /// </summary>
    public sealed class DivergenceFreeSceneTests
    {
        const float Frame = 1f / 60f;

        static FluidSceneDescription DivergenceFree(string name)
        {
            string path = RunnerPaths.EditedScene(name, "    PressureSolver: 0", "    PressureSolver: 1");
            var scene = SceneLoader.Load(path, RunnerPaths.Project).Description;
            Assert.That(scene.Settings.PressureSolver, Is.EqualTo(PressureSolver.Dfsph), "the scene key settings.PressureSolver: 1");
            return scene;
        }

        [Test]
        public void DamBreak_StaysFiniteAndLosesNothingForTwoSeconds()
        {
            var scene = DivergenceFree("DamBreak");
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            int spawned = sim.ParticleCount;
            double steps = 0;
            int frames = 0;
            while (sim.SimulatedTime < 2.0 - 1e-6)
            {
                sim.Step(Frame);
                steps += sim.LastStep.Substeps;
                frames++;
            }
            var report = sim.ReadDiagnostics();
            TestContext.Progress.WriteLine($"DFSPH dam break, N={spawned}: {steps / frames:F2} sub-steps per frame; {report}");
            Assert.That(report.NanCount, Is.EqualTo(0));
            Assert.That(report.OutsideCount, Is.EqualTo(0));
            Assert.That(report.ParticleCount, Is.EqualTo(spawned));
            Assert.That(report.TotalMass, Is.GreaterThan(0.0));
        }

        /// <summary>Issue #8's bar for DFSPH, #5's layering: measured 0.950 at 2.5 s with 0.6 % of the floor layer oil and no clamp
        /// hit (WCSPH: 5.0 s). It stood ignored at 21.9 % floor oil (0.870 at 6 s) while the walls were weighed at the lattice's
        /// rest number density instead of the fluid's (SphBoundary.hlsl's WallWeight) and DFSPH was held to the cubic spline
        /// at 2 spacings; with the fix, that configuration leaves 9.4 % (0.898) and the scene's own, Wendland C2 at 2.85
        /// spacings relaxed to 0.3, passes (0.992 and 0.00 % at 6 s). Explicit: it took 21 m 57 s of lavapipe on 2 cores, beyond CI's budget;
        /// run it with <c>bash Headless/test.sh --filter "FullyQualifiedName~DefaultOilAndWater_LayersFully"</c>.</summary>
        [Test, Explicit("about 22 minutes on lavapipe: beyond CI's budget")]
        public void DefaultOilAndWater_LayersFullyWithin6Seconds_AndNoOilStaysOnTheFloor()
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH OilAndWater"), Is.Null, "the scene's own DFSPH settings");
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            double reached = double.NaN, next = 0.5;
            FluidMeasures? last = null;
            int water = Phase(sim, "Water"), oil = Phase(sim, "Oil");
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            var s = scene.Settings;
            while (sim.SimulatedTime < 6.0 - 1e-6)
            {
                sim.Step(Frame);
                if (sim.SimulatedTime < next - 1e-6) continue;
                next += 0.5;
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                last = FluidMeasures.Measure(sim.SimulatedTime, particles, densities, sim.PhaseRows, scene.Container, s.Gravity, s.ParticleSpacing, s.SmoothingRadius);
                TestContext.Progress.WriteLine(string.Format(CultureInfo.InvariantCulture, "t={0:F2} s layering {1:F3} oil floor {2:F1} %, {3}",
                    sim.SimulatedTime, last.LayeringIndex, 100 * last.Phases[oil].FloorShare, sim.LastStep));
                if (double.IsNaN(reached) && last.LayeringIndex >= 0.95) reached = sim.SimulatedTime;
            }
            var report = sim.ReadDiagnostics();
            Assert.That(last, Is.Not.Null, "measured every half second");
            TestContext.Progress.WriteLine($"DFSPH OilAndWater: layering 0.95 reached at {reached:F2} s; at 6 s {last.LayeringIndex:F3}, " +
                $"oil floor share {100 * last.Phases[oil].FloorShare:F2} %; {report}");
            Assert.That(reached, Is.LessThanOrEqualTo(6.0 + 1e-5), "layering index >= 0.95 within 6 simulated seconds");
            Assert.That(last.Phases[oil].FloorShare, Is.LessThan(0.02), "less than 2 % of the floor layer is oil");
            Assert.That(last.Phases[oil].MeanHeight, Is.GreaterThan(last.Phases[water].MeanHeight));
            Assert.That(report.OutsideCount, Is.EqualTo(0));
            Assert.That(report.NanCount, Is.EqualTo(0));
            Assert.That(report.ClampHits, Is.EqualTo(0));
        }

        static int Phase(FluidSimulation sim, string name)
        {
            for (int k = 0; k < sim.Phases.Count; k++) if (sim.Phases[k].Name == name) return k;
            throw new ArgumentException(name);
        }
    }
}
