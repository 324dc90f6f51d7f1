using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Physics;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// A few frames under the validation layer of the configurations only the physics tests ran, which run on the unvalidated
    /// device (GpuTestDevice.Unvalidated): Headless/test.sh found these kernel variants run there and nowhere validated. Each
    /// run must stay finite and keep every particle inside its container.
    /// </summary>
    public sealed class PhysicsScenesUnderValidationTests
    {
        const float Frame = 1f / 60f;

        static void AssertIntact(FluidSimulation sim, int spawned)
        {
            var report = sim.ReadDiagnostics();
            Assert.That(report.ParticleCount, Is.EqualTo(spawned));
            Assert.That(report.NanCount + report.OutsideCount, Is.EqualTo(0));
        }

        /// <summary>WCSPH's carried density (ContinuityDensity, DensityRate) with XSPH: RestingTankTests' delta-SPH tank.</summary>
        [Test]
        public void DeltaSphTankWithXsph()
        {
            var scene = RestingTankTests.Tank(0.04f, WcsphDensity.DeltaSph);
            Assume.That(scene.Settings.XsphEpsilon, Is.GreaterThan(0f));
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            for (int i = 0; i < 3; i++) sim.Step(Frame);
            AssertIntact(sim, sim.ParticleCount);
        }

        /// <summary>DFSPH's walls moved with the container (WallMovedDensityFactor) with XSPH: CarriedTankTests' tank.</summary>
        [Test]
        public void CarriedDfsphTank()
        {
            var scene = RestingTankTests.Tank(0.04f);
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            var velocity = new Vector3(0.5f, 0f, 0f);
            foreach (var box in scene.SpawnBoxes) box.InitialVelocity = velocity;
            var container = scene.Container.Clone();
            var start = container.Position;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            for (int i = 1; i <= 3; i++)
            {
                container.Position = start + velocity * (i * Frame);
                container.Velocity = velocity;
                sim.UpdateContainer(container);
                sim.Step(Frame);
            }
            AssertIntact(sim, sim.ParticleCount);
        }

        /// <summary>DFSPH's walls moved with two liquids (WallMovedDensityFactor, MULTIPHASE): TurningWallsWarmStartTests'
        /// RotatingContainer, from where its spin starts.</summary>
        [Test]
        public void TurningDfsphContainerOfTwoLiquids()
        {
            var loaded = SceneLoader.Load(RunnerPaths.Scene("RotatingContainer"), RunnerPaths.Project);
            Assume.That(loaded.Motion.MovesContainer, Is.True);
            var rest = loaded.Description.Container.Clone();
            RunDfsphFrom(loaded, loaded.Motion.ContainerSpin!.StartDelay,
                (sim, from, to) => sim.UpdateContainer(loaded.Motion.ContainerOver(rest, from, to)));
        }

        /// <summary>DFSPH around a driven sphere (WallMovedDensityFactor and the divergence diagnostics' DivergenceRate, OBSTACLES):
        /// DivergenceFreeSceneTests' SphereWake, from where its sphere starts to move.</summary>
        [Test]
        public void DfsphAroundADrivenSphere()
        {
            var loaded = SceneLoader.Load(RunnerPaths.Scene("SphereWake"), RunnerPaths.Project);
            Assume.That(loaded.Motion.MovesObstacles, Is.True);
            var rest = loaded.Description.Obstacles.Select(o => o.Clone()).ToList();
            RunDfsphFrom(loaded, loaded.Motion.SphereDrives.Max(d => d.Drive.StartDelay),
                (sim, from, to) => sim.UpdateObstacles(loaded.Motion.ObstaclesOver(rest, from, to)));
        }

        /// <summary>Three frames of a shipped scene under DFSPH as its motion runs from <paramref name="start"/> s on:
        /// <paramref name="move"/> pushes what moves to where each frame [from, to] ends, and the diagnostics are read.</summary>
        static void RunDfsphFrom(LoadedScene loaded, double start, System.Action<FluidSimulation, double, double> move)
        {
            var scene = loaded.Description;
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            for (int i = 1; i <= 3; i++)
            {
                double t = start + i * Frame;
                move(sim, t - Frame, t);
                sim.Step(Frame);
                sim.ReadDiagnostics();
            }
            AssertIntact(sim, sim.ParticleCount);
        }
    }
}
