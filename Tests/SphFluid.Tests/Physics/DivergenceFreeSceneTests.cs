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
    /// lose nothing; the oil and water must layer and clear the floor as <see cref="SeparationTests"/> asks of WCSPH (not its
    /// flatness bar, which DFSPH misses: see the test).
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

        /// <summary>The lock exchange at the top of DFSPH's Wendland C2 band (2.9 spacings instead of the scene's 2.85; validation
        /// allows up to 2.9) may bring no fluid centre within a tenth of a spacing of a wall face in its first second, nor to
        /// the last-resort clamp. The density constraint, the walls' included, does not hold the fluid beside a wall at its
        /// lattice place: oil beside the front and back walls drifts towards them at rest density, and before the wall
        /// contact acted by distance (DivergenceFreeSolver.hlsl) the clamp caught 8 by 0.7 s and 14 by 1 s (108 by 6.5 s),
        /// the closest centres at the clamp's inset, a hundredth of a spacing. The contact now stops them a quarter spacing
        /// from the faces; a few get closer where the walls' gradient sum leans away from the face's normal, at an edge,
        /// the closest 0.148 spacings from a face.</summary>
        [Test]
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
            var report = sim.ReadDiagnostics();
            TestContext.Progress.WriteLine($"DFSPH OilAndWater at 2.9 spacings, first second: closest centre {closest:F3} spacings from a wall face; {report}");
            Assert.That(closest, Is.GreaterThanOrEqualTo(0.1));
            Assert.That(report.ClampHits, Is.EqualTo(0));
        }

        /// <summary>SphereWake under DFSPH. Its sphere stands still for the drive's first second in a pool spawned at rest, so
        /// no work is done on the fluid: its mechanical energy may not rise above the spawn's, and nothing may move faster than
        /// a fall through one spacing, sqrt(2 g s). Then the sphere moves (up to 0.26 m/s) for a second, and no fluid centre
        /// may enter it or reach the clamp. While a sphere's own shells were summed for its wall constraint
        /// (BoundarySampling.OwnNumberDensities) they read up to 22 % above rest, and the constraint pushed the fluid off the
        /// still sphere: 8.2 m/s and 2.1 J of energy gained by 0.13 s, unhealthy at 0.37 s.</summary>
        [Test]
        public void SphereWake_StillSphereLeavesThePoolAtRest_AndTheDrivenOneRunsClean()
        {
            var loaded = SceneLoader.Load(RunnerPaths.Scene("SphereWake"), RunnerPaths.Project);
            var scene = loaded.Description;
            Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH SphereWake"), Is.Null, "the scene's own DFSPH settings");
            var rest = scene.Obstacles.Select(o => o.Clone()).ToList();
            var gravity = (System.Numerics.Vector3)scene.Settings.Gravity;
            double fallSpeed = Math.Sqrt(2.0 * gravity.Length() * scene.Settings.ParticleSpacing);
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
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

        /// <summary>Issue #8's bar for DFSPH, #5's layering: index at least 0.95 and under 2 % of the floor layer oil within 6 s,
        /// with no clamp hit (measured: both at 3.0 s, 0.958 and 1.33 %, with the walls weighed by their lattice cells; 2.5 s
        /// before; WCSPH takes 5.0 s). It stood ignored at 21.9 % floor
        /// oil (0.870 at 6 s) while the walls were weighed at the lattice's rest number density instead of the fluid's
        /// (SphBoundary.hlsl's WallWeight) and DFSPH was held to the cubic spline at 2 spacings; with that fixed, that
        /// configuration leaves 8.7 % (0.907) and the scene's own, Wendland C2 at 2.85 spacings relaxed to 0.3, passes. It
        /// then took 22 minutes of lavapipe for 6 s and ran only by hand; with the neighbour lists (SphNeighbourhood.hlsl) a
        /// sub-step costs a third, and the run stops at the first measure that meets both bars, as SeparationTests' does.
        /// #5's third bar, the interface within a spacing of flat, DFSPH misses by half a second: after the lock exchange's
        /// one swing (64 mm of tilt at 3.5 s) its interface creeps back without rocking, 17.2 mm at 6 s and 11.2 mm at 6.5 s,
        /// where WCSPH's crosses flat near 5.4 s (6.9 mm at 5 s; 8.7 mm with the walls' new weights, the 6 s run not repeated). Both are far more damped than the liquids' viscosity damps
        /// the tank's internal seiche (<see cref="InternalSeicheProbe"/>); the test prints the tilt it stopped at and does
        /// not assert it.
        /// <para>With the Chebyshev-accelerated solve (<see cref="SolverIteration"/>, as <c>--solver-iteration chebyshev</c> sets it)
        /// the same bars hold: measured at 2.5 s (layering 0.96, no floor oil, no clamp hit in 6 s; 3.5 constant-density
        /// iterations a sub-step against Jacobi's 11.8).</para></summary>
        [TestCase(SolverIteration.Jacobi, TestName = "DefaultOilAndWater_LayersWithin6Seconds_AndNoOilStaysOnTheFloor")]
        [TestCase(SolverIteration.Chebyshev, TestName = "DefaultOilAndWater_LayersWithin6Seconds_AndNoOilStaysOnTheFloor_Chebyshev")]
        public void DefaultOilAndWater_LayersWithin6Seconds_AndNoOilStaysOnTheFloor(SolverIteration iteration)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph, Iteration = iteration }.ApplyTo(scene, "DFSPH OilAndWater"), Is.Null,
                "the scene's own DFSPH settings");
            Assert.That(scene.Settings.SolverIteration, Is.EqualTo(iteration));
            int water = SeparationTests.Phase(scene, "Water"), oil = SeparationTests.Phase(scene, "Oil");
            var (doneAt, last, report) = SeparationTests.RunUntil(scene, 6.0,
                m => m.LayeringIndex >= 0.95 && m.Phases[oil].FloorShare < 0.02);
            TestContext.Progress.WriteLine($"DFSPH ({iteration}) OilAndWater: layering >= 0.95 and floor oil < 2 % at {doneAt:F2} s: layering {last.LayeringIndex:F3}, " +
                $"oil floor share {100 * last.Phases[oil].FloorShare:F2} %, interface tilt {1000 * last.InterfaceTilt:F1} mm; {report}");
            Assert.That(doneAt, Is.LessThanOrEqualTo(6.0 + 1e-5),
                $"within 6 simulated seconds: layering index >= 0.95 (at 6 s {last.LayeringIndex:F3}) and less than 2 % of the floor layer oil " +
                $"({100 * last.Phases[oil].FloorShare:F2} %)");
            Assert.That(last.Phases[oil].MeanHeight, Is.GreaterThan(last.Phases[water].MeanHeight));
            Assert.That(report.OutsideCount, Is.EqualTo(0));
            Assert.That(report.NanCount, Is.EqualTo(0));
            Assert.That(report.ClampHits, Is.EqualTo(0));
        }
    }
}
