using System;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless.Cli;
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
    /// lose nothing; the oil and water must layer, clear the floor and lay a flat interface as <see cref="SeparationTests"/> asks
    /// of WCSPH.
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
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
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

        /// <summary>The lock exchange at the top of DFSPH's Wendland C2 band (2.9 spacings instead of the scene's 2.85; validation
        /// allows up to 2.9) may bring no fluid centre within a tenth of a spacing of a wall face in its first second, nor to
        /// the last-resort clamp, and at 1 s at most 30 centres may lie within 0.35 spacings of the front and back walls (at
        /// rest beside a flat wall a centre is half a spacing from the face). While a wall particle had only the pressure its
        /// own compression built, the fluid beside a wall was pushed into it by the difference, and oil beside the front and
        /// back walls drifted towards them at rest density: the clamp caught 8 by 0.7 s and 14 by 1 s (108 by 6.5 s), the
        /// closest centres at the clamp's inset, a hundredth of a spacing. The wall contact acting by distance
        /// (DivergenceFreeSolver.hlsl) then stopped them a quarter spacing from the faces, the closest 0.148 spacings from a
        /// face at an edge, with 122 centres within 0.35 spacings at 1 s (WallCreepProbe). With the walls' pressure held at
        /// least at the fluid's (WallStepAtLeast) 13 are, and the closest is 0.256 spacings from a face.</summary>
        [Test]
        [Category(TestProcesses.LongRuns)]
        public void OilAndWaterAtTheTopOfTheBand_KeepsItsCentresOffTheWalls()
        {
            string path = RunnerPaths.EditedScene("OilAndWater", "SmoothingRadius: 0.04275", "SmoothingRadius: 0.0435");
            var scene = SceneLoader.Load(path, RunnerPaths.Project).Description;
            Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH OilAndWater at 2.9 spacings"), Is.Null);
            float spacing = scene.Settings.ParticleSpacing;
            Assert.That(scene.Settings.SmoothingRadius / spacing, Is.EqualTo(2.9).Within(1e-4));
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            double closest = double.MaxValue, next = 0.1;
            while (sim.SimulatedTime < 1.0 - 1e-6)
            {
                sim.Step(Frame);
                if (sim.SimulatedTime < next - 1e-6) continue;
                next += 0.1;
                sim.Particles.GetData(particles);
                closest = Math.Min(closest, TankMeasures.ClosestToWalls(particles, scene.Container) / spacing);
            }
            var container = scene.Container;
            int nearFrontAndBack = particles.Count(p => container.Size.Z / 2 - Math.Abs(p.Position.Z - container.Position.Z) < 0.35 * spacing);
            var report = sim.ReadDiagnostics();
            TestContext.Progress.WriteLine($"DFSPH OilAndWater at 2.9 spacings, first second: closest centre {closest:F3} spacings from a wall face; " +
                $"{nearFrontAndBack} centres within 0.35 spacings of the front and back walls at 1 s; {report}");
            Assert.That(closest, Is.GreaterThanOrEqualTo(0.1));
            Assert.That(nearFrontAndBack, Is.LessThanOrEqualTo(30), "centres within 0.35 spacings of the front and back walls at 1 s");
            Assert.That(report.ClampHits, Is.EqualTo(0));
        }

        /// <summary>SphereWake under DFSPH. Its sphere stands still for the drive's first second in a pool spawned at rest, so
        /// no work is done on the fluid: its mechanical energy may not rise above the spawn's, and nothing may move faster than
        /// a fall through one spacing, sqrt(2 g s). Then the sphere moves (up to 0.26 m/s) for a second, and no fluid centre
        /// may enter it or reach the clamp. While a sphere's own shells were summed for its wall constraint
        /// (BoundarySampling.OwnNumberDensities) they read up to 22 % above rest, and the constraint pushed the fluid off the
        /// still sphere: 8.2 m/s and 2.1 J of energy gained by 0.13 s, unhealthy at 0.37 s.</summary>
        [Test]
        [Category(TestProcesses.LongRuns)]
        public void SphereWake_StillSphereLeavesThePoolAtRest_AndTheDrivenOneRunsClean()
        {
            var loaded = SceneLoader.Load(RunnerPaths.Scene("SphereWake"), RunnerPaths.Project);
            var scene = loaded.Description;
            Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH SphereWake"), Is.Null, "the scene's own DFSPH settings");
            var rest = scene.Obstacles.Select(o => o.Clone()).ToList();
            var gravity = (System.Numerics.Vector3)scene.Settings.Gravity;
            double fallSpeed = Math.Sqrt(2.0 * gravity.Length() * scene.Settings.ParticleSpacing);
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            int spawned = sim.ParticleCount;
            var particles = new Particle[spawned];
            sim.Particles.GetData(particles);
            double spawnEnergy = FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity), energyRise = double.MinValue, stillSpeed = 0;
            double movingSpeed = 0, closest = double.MaxValue;
            var report = sim.ReadDiagnostics();
            for (int frame = 1; frame <= 120; frame++)
            {
                double t = frame / 60.0;
                var obstacles = loaded.Motion.ObstaclesOver(rest, t - Frame, t);
                sim.UpdateObstacles(obstacles);
                sim.Step(Frame);
                report = sim.ReadDiagnostics();
                sim.Particles.GetData(particles);
                if (t <= 1.0 + 1e-6)
                {
                    energyRise = Math.Max(energyRise, FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity) - spawnEnergy);
                    stillSpeed = Math.Max(stillSpeed, report.MaxSpeed);
                    continue;
                }
                movingSpeed = Math.Max(movingSpeed, report.MaxSpeed);
                var centre = obstacles[0].Center; // where the sphere stands at the frame's end
                closest = Math.Min(closest, particles.Min(p => (double)System.Numerics.Vector3.Distance(p.Position, centre)) - obstacles[0].Radius);
            }
            TestContext.Progress.WriteLine($"DFSPH SphereWake, N={spawned}: still sphere, 1 s: energy {spawnEnergy:F4} J at spawn, largest rise {energyRise:F4} J, " +
                $"fastest {stillSpeed:F3} m/s (a fall through a spacing {fallSpeed:F3}); moving sphere, 1 to 2 s: fastest {movingSpeed:F3} m/s, " +
                $"closest fluid centre {1000 * closest:F2} mm outside the sphere; {report}");
            Assert.That(energyRise, Is.LessThanOrEqualTo(0.0), "no work is done on the pool while the sphere stands still");
            Assert.That(stillSpeed, Is.LessThan(fallSpeed));
            Assert.That(closest, Is.GreaterThan(0.0), "no fluid centre inside the moving sphere");
            Assert.That(report.ClampHits, Is.EqualTo(0));
            Assert.That(report.ParticleCount, Is.EqualTo(spawned));
            Assert.That(report.OutsideCount + report.NanCount, Is.EqualTo(0));
        }

        /// <summary>Issue #8's bar for DFSPH, #5's layering: index at least 0.95, under 2 % of the floor layer oil and the
        /// interface's plane rising less than a spacing across the floor, all within 6 s, with no clamp hit, as
        /// <see cref="SeparationTests"/> asks of WCSPH (which meets them at 5.0 s, as its swing back crosses flat). Measured
        /// at the first half-second sample that meets all three: 5.5 s (layering 1.00, no floor oil, 7 mm; the Chebyshev
        /// solve 6.0 s, 0.9 mm, with 16.5 mm at 5.5 s). Until the walls' pressure was held at least at the fluid's
        /// (DivergenceFreeSolver.hlsl's WallStepAtLeast) DFSPH missed the flatness bar: after the lock exchange's one swing (56 mm of tilt at 3.5 s) its
        /// interface crept back without rocking, 17.4 mm at 6 s and 12.4 mm at 6.5 s, and the test asserted the other two
        /// (met at 3.0 s: 0.957 and 0.34 % floor oil; 2.5 s now, 0.962 and none). Now it swings back through flat (118 mm
        /// at 3.5 s, 7 mm at 5.5 s). It stood ignored at 21.9 % floor oil (0.870 at 6 s) while the walls were weighed at
        /// the lattice's rest number density instead of the fluid's (SphBoundary.hlsl's WallWeight) and DFSPH was held to
        /// the cubic spline at 2 spacings; with that fixed, that configuration leaves 8.7 % (0.907) and the scene's own,
        /// Wendland C2 at 2.85 spacings relaxed to 0.3, passes. It then took 22 minutes of lavapipe for 6 s and ran only by
        /// hand; with the neighbour lists (SphNeighbourhood.hlsl) a sub-step costs a third, and the run stops at the first
        /// measure that meets every bar.
        /// The scene's own solve, Jacobi's.</summary>
        [Test]
        [Category(TestProcesses.LongRuns)]
        public void DefaultOilAndWater_LayersFlatWithin6Seconds_AndNoOilStaysOnTheFloor() => LayersFlatWithin6Seconds(SolverIteration.Jacobi);

        /// <summary>The same bars with the Chebyshev-accelerated solve (<see cref="SolverIteration"/>, as
        /// <c>--solver-iteration chebyshev</c> sets it), which the scene leaves off: met at 6.0 s (layering 0.997, no floor
        /// oil, 0.9 mm; 4.5 constant-density iterations a sub-step against Jacobi's 14.5). Run by name (`bash
        /// Headless/test.sh --filter "Name~LayersFlatWithin6Seconds_AndNoOilStaysOnTheFloor_Chebyshev"`, six minutes of
        /// lavapipe): with it CI ran past its 20-minute goal (Headless/docs/known-limits.md), and CI holds the accelerated
        /// solve to the resting tank (DivergenceFreeTankTests), the column depths (SolverIterationScalingTests) and this
        /// scene's first frames at 1 % (LooseToleranceTests).</summary>
        [Test]
        [Explicit("six minutes of lavapipe: run it by name (CI runs the Jacobi solve's)")]
        public void DefaultOilAndWater_LayersFlatWithin6Seconds_AndNoOilStaysOnTheFloor_Chebyshev() => LayersFlatWithin6Seconds(SolverIteration.Chebyshev);

        static void LayersFlatWithin6Seconds(SolverIteration iteration)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph, Iteration = iteration }.ApplyTo(scene, "DFSPH OilAndWater"), Is.Null,
                "the scene's own DFSPH settings");
            Assert.That(scene.Settings.SolverIteration, Is.EqualTo(iteration));
            int water = SeparationTests.Phase(scene, "Water"), oil = SeparationTests.Phase(scene, "Oil");
            double spacing = scene.Settings.ParticleSpacing;
            var (doneAt, last, report) = SeparationTests.RunUntil(scene, 6.0,
                m => m.LayeringIndex >= 0.95 && m.Phases[oil].FloorShare < 0.02 && Math.Abs(m.InterfaceTilt) < spacing);
            TestContext.Progress.WriteLine($"DFSPH ({iteration}) OilAndWater: layering >= 0.95, floor oil < 2 % and tilt < {1000 * spacing:F0} mm at {doneAt:F2} s: " +
                $"layering {last.LayeringIndex:F3}, oil floor share {100 * last.Phases[oil].FloorShare:F2} %, interface tilt {1000 * last.InterfaceTilt:F1} mm; {report}");
            Assert.That(doneAt, Is.LessThanOrEqualTo(6.0 + 1e-5),
                $"within 6 simulated seconds: layering index >= 0.95 (at 6 s {last.LayeringIndex:F3}), less than 2 % of the floor layer oil " +
                $"({100 * last.Phases[oil].FloorShare:F2} %), the interface rising less than a spacing ({1000 * last.InterfaceTilt:F1} mm)");
            Assert.That(last.Phases[oil].MeanHeight, Is.GreaterThan(last.Phases[water].MeanHeight));
            Assert.That(report.OutsideCount, Is.EqualTo(0));
            Assert.That(report.NanCount, Is.EqualTo(0));
            Assert.That(report.ClampHits, Is.EqualTo(0));
        }
    }
}
