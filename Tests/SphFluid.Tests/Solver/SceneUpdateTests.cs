using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// The Unity simulator pushes the container and the spheres every frame, moved or not. An unchanged push must
    /// cost nothing (no copy, no validation, no upload: no garbage), and a changed one must still be checked and taken.
    /// </summary>
    public sealed class SceneUpdateTests
    {
        static readonly Vector3 BallCentre = new Vector3(0.06f, 0.04f, 0f);

        static FluidSceneDescription TankWithBall()
        {
            var scene = SolverScenes.Scene(SolverScenes.Coarse(0.04f), new Vector3(0.24f, 0.24f, 0.16f),
                SolverScenes.Box("Water", SolverScenes.Water(), new Vector3(0f, -0.06f, 0f), new Vector3(0.24f, 0.12f, 0.16f)));
            scene.Obstacles.Add(new RigidSphere(BallCentre, 0.03f, Vector3.Zero) { Name = "Ball" });
            return scene;
        }

        /// <summary>Fresh objects equal to what the simulation holds, as a caller that rebuilds them each frame passes.</summary>
        static List<RigidSphere> SameBall() =>
            new List<RigidSphere> { new RigidSphere(BallCentre, 0.03f, Vector3.Zero) { Name = "Ball" } };

        [Test]
        public void UnchangedContainerAndSpheres_AllocateNothing()
        {
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, TankWithBall()))
            {
                var container = sim.Scene.Container.Clone();
                var spheres = SameBall();
                Action push = () =>
                {
                    sim.UpdateContainer(container);
                    sim.UpdateObstacles(spheres);
                };
                AllocatedBy(push, 1000); // the first round pays for the JIT and its tiering
                long bytes = AllocatedBy(push, 1000);

                Assert.That(bytes, Is.EqualTo(0L), "bytes allocated by 1000 unchanged pushes of the container and one sphere");
            }
        }

        /// <summary>Managed bytes this thread allocates over <paramref name="frames"/> calls of <paramref name="push"/>.</summary>
        static long AllocatedBy(Action push, int frames)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int frame = 0; frame < frames; frame++) push();
            return GC.GetAllocatedBytesForCurrentThread() - before;
        }

        [Test]
        public void MovedContainer_IsTaken_AndAnInvalidOneIsStillRefused()
        {
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, TankWithBall()))
            {
                var moved = sim.Scene.Container.Clone();
                moved.Position = new Vector3(0.01f, 0f, 0f);
                moved.Velocity = new Vector3(0.6f, 0f, 0f);
                sim.UpdateContainer(moved);
                moved.Position = Vector3.Zero; // the simulation keeps its own copy
                Assert.That(sim.Scene.Container.Position, Is.EqualTo(new Vector3(0.01f, 0f, 0f)));
                Assert.That(sim.Scene.Container.Velocity, Is.EqualTo(new Vector3(0.6f, 0f, 0f)));

                var broken = sim.Scene.Container.Clone();
                broken.Size = new Vector3(0.24f, float.NaN, 0.16f);
                Assert.That(() => sim.UpdateContainer(broken),
                    Throws.ArgumentException.With.Message.Contains("Container: each Size component must be in [0.08, 1000] m"));
                Assert.That(sim.Scene.Container.Size, Is.EqualTo(new Vector3(0.24f, 0.24f, 0.16f)), "a refused container changes nothing");
            }
        }

        [Test]
        public void AFrictionChangeAloneIsTaken()
        {
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, TankWithBall()))
            {
                var slip = sim.Scene.Container.Clone();
                slip.Friction = WallFriction.Slip;
                sim.UpdateContainer(slip);
                Assert.That(sim.Scene.Container.Friction, Is.EqualTo(WallFriction.Slip));
            }
        }

        [Test]
        public void MovedSphere_IsTaken_AndAnInvalidOneIsStillRefused()
        {
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, TankWithBall()))
            {
                var moved = SameBall();
                moved[0].Center = new Vector3(0.05f, 0.04f, 0f);
                moved[0].Velocity = new Vector3(-0.6f, 0f, 0f);
                sim.UpdateObstacles(moved);
                Assert.That(sim.Scene.Obstacles[0].Center, Is.EqualTo(new Vector3(0.05f, 0.04f, 0f)));
                Assert.That(sim.Scene.Obstacles[0].Velocity, Is.EqualTo(new Vector3(-0.6f, 0f, 0f)));

                var broken = SameBall();
                broken[0].Radius = -1f;
                Assert.That(() => sim.UpdateObstacles(broken),
                    Throws.ArgumentException.With.Message.Contains("Sphere 'Ball': Radius must be in (0, 1000] m (was -1)"));
                Assert.That(sim.Scene.Obstacles[0].Radius, Is.EqualTo(0.03f), "a refused sphere changes nothing");

                sim.UpdateObstacles(new List<RigidSphere>());
                Assert.That(sim.Scene.Obstacles, Is.Empty, "fewer spheres is a change");
            }
        }

        /// <summary>
        /// A moving wall is pushed as a Unity Transform reads after it moved: where it stands at the frame's end, with the
        /// velocity that brought it there. Its walls sweep up to that placement through the frame's sub-steps and end the
        /// frame on it. They were carried a frame past it instead, so the fluid met a sphere a frame's travel ahead of the
        /// law driving it (4.3 mm at SphereWake's 0.26 m/s).
        /// </summary>
        [Test]
        public void AMovingSphereEndsTheFrameWhereItWasPushed()
        {
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, TankWithBall()))
            {
                Vector3 atRest = SphereParticlesMean(sim);
                const float frame = 1f / 60f, speed = 0.6f;
                for (int i = 1; i <= 2; i++)
                {
                    var moved = SameBall();
                    moved[0].Center = BallCentre + new Vector3(speed * frame * i, 0f, 0f);
                    moved[0].Velocity = new Vector3(speed, 0f, 0f);
                    sim.UpdateObstacles(moved);
                    sim.Step(frame);
                    Vector3 travelled = SphereParticlesMean(sim) - atRest;
                    Assert.That(travelled.X, Is.EqualTo(speed * frame * i).Within(1e-6f), $"frame {i}");
                    Assert.That(travelled.Y, Is.EqualTo(0f).Within(1e-6f));
                }
            }
        }

        /// <summary>The container is pushed the same way: a tank moved sideways ends each frame at its pushed position.</summary>
        [Test]
        public void AMovingContainerEndsTheFrameWhereItWasPushed()
        {
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, TankWithBall()))
            {
                Vector3 atRest = WallParticlesMean(sim, BoundaryParticle.ContainerOwner);
                const float frame = 1f / 60f, speed = 0.6f;
                var container = sim.Scene.Container.Clone();
                for (int i = 1; i <= 2; i++)
                {
                    container.Position = new Vector3(speed * frame * i, 0f, 0f);
                    container.Velocity = new Vector3(speed, 0f, 0f);
                    sim.UpdateContainer(container);
                    sim.Step(frame);
                    Vector3 travelled = WallParticlesMean(sim, BoundaryParticle.ContainerOwner) - atRest;
                    Assert.That(travelled.X, Is.EqualTo(speed * frame * i).Within(1e-6f), $"frame {i}");
                }
            }
        }

        static Vector3 SphereParticlesMean(FluidSimulation sim) => WallParticlesMean(sim, 0u);

        static Vector3 WallParticlesMean(FluidSimulation sim, uint owner)
        {
            var walls = new BoundaryParticle[sim.BoundaryCount];
            sim.BoundaryParticles.GetData(walls);
            var sum = Vector3.Zero;
            int count = 0;
            foreach (var wall in walls)
                if (wall.Owner == owner) { sum += wall.Position; count++; }
            Assert.That(count, Is.GreaterThan(0));
            return sum / count;
        }
    }
}
