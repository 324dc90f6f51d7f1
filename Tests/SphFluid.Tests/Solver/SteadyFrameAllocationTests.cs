using System;
using System.Collections.Generic;
using System.Numerics;
using System.Runtime.CompilerServices;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// Unity calls <see cref="FluidSimulation.Step"/> and <see cref="FluidSimulation.RequestDiagnostics"/> every frame,
    /// and every byte of garbage they make brings Mono's collector closer to a visible hitch. Measured here on a
    /// <see cref="StandInDevice"/>, so that the bytes are the solver's own, for a tank at rest, a turning container
    /// and a driven sphere; and the health check Unity runs on each report.
    /// </summary>
    /// <remarks>
    /// .NET 10 places some objects that never leave a method on the stack, where Mono would allocate them; the test
    /// project turns that off (JitObjectStackAllocation=0 in its runtimeconfig), and
    /// <see cref="TheCountSeesObjectsThatNeverEscape"/> proves it did, or these zeros would prove nothing.
    /// </remarks>
    public sealed class SteadyFrameAllocationTests
    {
        const float Frame = 1f / 60f;
        const int Frames = 300;
        static readonly Vector3 BallCentre = new Vector3(0.06f, 0.04f, 0f);

        static FluidSceneDescription TankWithBall()
        {
            var scene = SolverScenes.Scene(SolverScenes.Coarse(0.04f), new Vector3(0.24f, 0.24f, 0.16f),
                SolverScenes.Box("Water", SolverScenes.Water(), new Vector3(0f, -0.06f, 0f), new Vector3(0.24f, 0.12f, 0.16f)),
                SolverScenes.Box("Oil", SolverScenes.Oil(), new Vector3(0f, 0.04f, 0f), new Vector3(0.24f, 0.04f, 0.16f)));
            scene.Obstacles.Add(new RigidSphere(BallCentre, 0.03f, Vector3.Zero) { Name = "Ball" });
            return scene;
        }

        [Test]
        public void TheCountSeesObjectsThatNeverEscape()
        {
            long bytes = AllocatedBy(() => NonEscapingArray(), 100);
            Assert.That(bytes, Is.GreaterThanOrEqualTo(100L * 40L),
                "bytes counted for 100 arrays of four ints that never leave their method (each is 40 B on the heap)");
        }

        /// <summary>Fully optimised from its first call (no tiering): the very code that could stack-allocate.</summary>
        [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
        static int NonEscapingArray()
        {
            var values = new int[4];
            values[1] = 3;
            return values[1] + values.Length;
        }

        [Test]
        public void TankAtRest_StepsAndRequestsDiagnostics_WithNoGarbage()
        {
            var device = new StandInDevice();
            using (var sim = new FluidSimulation(device, TankWithBall()))
            {
                Action frame = () =>
                {
                    sim.Step(Frame);
                    sim.RequestDiagnostics();
                };
                AllocatedBy(frame, Frames); // the first frames pay for the JIT, its tiering and the one report
                long dispatches = device.Dispatches;
                long bytes = AllocatedBy(frame, Frames);

                Assert.That(sim.LastStep.Substeps, Is.GreaterThan(0), "the frames ran sub-steps");
                Assert.That(device.Dispatches - dispatches, Is.GreaterThan(Frames * 10L), "the frames dispatched the solver");
                Assert.That(sim.LatestDiagnostics, Is.Not.Null, "diagnostics arrived");
                Assert.That(bytes, Is.EqualTo(0L), $"bytes allocated by {Frames} frames of a tank at rest");
            }
        }

        /// <summary>DFSPH with its oil at 100 Pa s, frames of two lengths: each frame's new step sizes the implicit viscosity
        /// solve again (ImplicitViscosity), from the lattice's row sum the simulation keeps.</summary>
        [Test]
        public void ViscousLiquidUnderDfsph_ChangingItsStepEveryFrame_WithNoGarbage()
        {
            var scene = TankWithBall();
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            scene.Settings.SolverRelaxation = 0.3f;
            scene.SpawnBoxes[1].Phase.Viscosity = 100f;
            var device = new StandInDevice();
            using (var sim = new FluidSimulation(device, scene))
            {
                int frames = 0;
                Action frame = () => sim.Step(frames++ % 2 == 0 ? Frame : 1.2f * Frame);
                AllocatedBy(frame, Frames);
                long bytes = AllocatedBy(frame, Frames);

                Assert.That(sim.ViscositySolveRounds, Is.GreaterThan(0), "the viscosity was solved implicitly");
                Assert.That(bytes, Is.EqualTo(0L), $"bytes allocated by {Frames} frames of a viscous liquid under DFSPH");
            }
        }

        [Test]
        public void TurningContainer_StepsWithNoGarbage()
        {
            var device = new StandInDevice();
            using (var sim = new FluidSimulation(device, TankWithBall()))
            {
                var container = sim.Scene.Container.Clone(); // one description, refilled each frame as Unity does
                int frameIndex = 0;
                Action frame = () =>
                {
                    frameIndex++;
                    container.Rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.01f * frameIndex);
                    container.AngularVelocity = new Vector3(0f, 0f, 0.01f / Frame);
                    sim.UpdateContainer(container);
                    sim.Step(Frame);
                    sim.RequestDiagnostics();
                };
                AllocatedBy(frame, Frames);
                long bytes = AllocatedBy(frame, Frames);

                Assert.That(sim.Plan.UploadContainerTransform, Is.True, "the container moved every frame");
                Assert.That(sim.Scene.Container.Rotation, Is.EqualTo(container.Rotation), "the last rotation was taken");
                Assert.That(bytes, Is.EqualTo(0L), $"bytes allocated by {Frames} frames of a turning container");
            }
        }

        [Test]
        public void TurningContainer_StillRefusesAnInvalidRotation()
        {
            using (var sim = new FluidSimulation(new StandInDevice(), TankWithBall()))
            {
                var container = sim.Scene.Container.Clone();
                container.Rotation = new Quaternion(float.NaN, 0f, 0f, 1f);
                Assert.That(() => sim.UpdateContainer(container),
                    Throws.ArgumentException.With.Message.Contains("Container: Rotation"));
                Assert.That(sim.Scene.Container.Rotation, Is.EqualTo(Quaternion.Identity), "a refused container changes nothing");
            }
        }

        [Test]
        public void DrivenSphere_StepsWithNoGarbage()
        {
            var device = new StandInDevice();
            using (var sim = new FluidSimulation(device, TankWithBall()))
            {
                var spheres = new List<RigidSphere> { sim.Scene.Obstacles[0].Clone() }; // refilled each frame as Unity does
                int frameIndex = 0;
                Action frame = () =>
                {
                    frameIndex++;
                    float x = 0.03f * (float)Math.Sin(0.05 * frameIndex);
                    spheres[0].Center = BallCentre + new Vector3(x, 0f, 0f);
                    spheres[0].Velocity = new Vector3(0.03f * 0.05f * (float)Math.Cos(0.05 * frameIndex) / Frame, 0f, 0f);
                    sim.UpdateObstacles(spheres);
                    sim.Step(Frame);
                    sim.RequestDiagnostics();
                };
                AllocatedBy(frame, Frames);
                long bytes = AllocatedBy(frame, Frames);

                Assert.That(sim.Scene.Obstacles[0].Center, Is.EqualTo(spheres[0].Center), "the last centre was taken");
                Assert.That(sim.Scene.Obstacles[0], Is.Not.SameAs(spheres[0]), "the simulation keeps its own description");
                Assert.That(bytes, Is.EqualTo(0L), $"bytes allocated by {Frames} frames of a driven sphere");
            }
        }

        [Test]
        public void DrivenSphere_StillRefusesANonFiniteCentre()
        {
            using (var sim = new FluidSimulation(new StandInDevice(), TankWithBall()))
            {
                var spheres = new List<RigidSphere> { sim.Scene.Obstacles[0].Clone() };
                spheres[0].Center = new Vector3(float.NaN, 0.04f, 0f);
                Assert.That(() => sim.UpdateObstacles(spheres),
                    Throws.ArgumentException.With.Message.Contains("Sphere 'Ball': Center"));
                Assert.That(sim.Scene.Obstacles[0].Center, Is.EqualTo(BallCentre), "a refused sphere changes nothing");
            }
        }

        [Test]
        public void HealthyCheck_AndDriverObservation_AllocateNothing()
        {
            var scene = TankWithBall();
            var check = new HealthCheck(scene, 100);
            var phases = new[] { new PhaseDiagnostics("Water", 60, 0.01f, 0.05f), new PhaseDiagnostics("Oil", 40, 0.01f, 0.04f) };
            var healthy = new DiagnosticsReport(1.0, 0.01, 0.2f, 0, 0, phases, 0.5);
            var spheres = new List<RigidSphere>(scene.Obstacles);
            Action frame = () =>
            {
                check.ObserveDrivers(scene.Container, spheres);
                if (check.Check(healthy) != null) throw new InvalidOperationException("the healthy report was refused");
            };
            AllocatedBy(frame, Frames);
            long bytes = AllocatedBy(frame, Frames);

            Assert.That(check.Check(healthy), Is.Null, "a report within every bound is healthy");
            Assert.That(bytes, Is.EqualTo(0L), $"bytes allocated by {Frames} healthy checks and driver observations");
            var fast = new DiagnosticsReport(1.0, 0.01, 2f * check.SpeedBound, 0, 0, phases, 0.5);
            Assert.That(check.Check(fast).Message, Does.Contain("speed of sound"), "a problem still says how the speed bound is made up");
        }

        /// <summary>Managed bytes this thread allocates over <paramref name="frames"/> calls of <paramref name="frame"/>.</summary>
        static long AllocatedBy(Action frame, int frames)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < frames; i++) frame();
            return GC.GetAllocatedBytesForCurrentThread() - before;
        }
    }
}
