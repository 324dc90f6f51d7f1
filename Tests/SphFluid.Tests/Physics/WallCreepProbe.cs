using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// How DFSPH's fluid creeps towards the walls: a measurement run by name, `bash Headless/test.sh --filter
    /// FullyQualifiedName~WallCreepProbe`, which CI does not run (about 20 s of lavapipe). OilAndWater at 2.9 spacings
    /// (the top of DFSPH's Wendland C2 band) runs its first second; every 0.1 s it prints the clamp hits, how many fluid
    /// centres lie within 0.35 spacings of the front and back walls (at rest beside a flat wall a centre is 0.5 from the
    /// face) and how many of them are oil, the closest centre to any face, and for the centre closest to the front or back
    /// wall its number density against its rest and that of the wall particles within a spacing of it against theirs
    /// (the solves' own sums, read back). The boundary buffers are found by the names FluidSimulation gives them.
    /// </summary>
    [Explicit("a measurement, not a check: run it by name")]
    public sealed class WallCreepProbe
    {
        sealed class NamedBuffers : ForwardingDevice
        {
            public readonly Dictionary<string, IComputeBuffer> Buffers = new Dictionary<string, IComputeBuffer>();
            public NamedBuffers(IComputeDevice inner) : base(inner) { }
            public override IComputeBuffer CreateBuffer(string name, int count, int stride) => Buffers[name] = Inner.CreateBuffer(name, count, stride);
        }

        [Test]
        public void FluidBesideTheFrontAndBackWalls()
        {
            string path = RunnerPaths.EditedScene("OilAndWater", "SmoothingRadius: 0.04275", "SmoothingRadius: 0.0435");
            var scene = SceneLoader.Load(path, RunnerPaths.Project).Description;
            Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH OilAndWater at 2.9 spacings"), Is.Null);
            var device = new NamedBuffers(GpuTestDevice.Unvalidated);
            using var sim = new FluidSimulation(device, scene);
            float s = scene.Settings.ParticleSpacing, h = scene.Settings.SmoothingRadius;
            var container = scene.Container;
            var half = container.Size / 2;
            int oil = SeparationTests.Phase(scene, "Oil");
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            double next = 0.1;
            while (sim.SimulatedTime < 1.0 - 1e-6)
            {
                sim.Step(1f / 60f);
                if (sim.SimulatedTime < next - 1e-6) continue;
                next += 0.1;
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                var wallBuffer = device.Buffers["FluidSimulation.BoundarySorted"];
                var walls = new BoundaryParticle[wallBuffer.Count];
                wallBuffer.GetData(walls);
                var solve = new Vector4[walls.Length]; // (delta_b, alpha_b, q step, rest delta), by sorted wall particle
                device.Buffers["FluidSimulation.BoundarySolve"].GetData(solve);

                double FrontBackGap(Particle p) => (half.Z - Math.Abs(p.Position.Z - container.Position.Z)) / s;
                var near = particles.Where(p => FrontBackGap(p) < 0.35).ToList();
                double closest = TankMeasures.ClosestToWalls(particles, container) / s;
                int nearest = Enumerable.Range(0, particles.Length).OrderBy(i => FrontBackGap(particles[i])).First();
                var phase = sim.PhaseRows[(int)particles[nearest].Phase];
                double own = densities[nearest].Z / (phase.RestDensity / phase.ParticleMass) - 1;
                var beside = Enumerable.Range(0, walls.Length)
                    .Where(b => solve[b].W > 0 && (walls[b].Position - particles[nearest].Position).Length() < s)
                    .Select(b => solve[b].X / solve[b].W - 1).ToList();
                string wallReading = beside.Count > 0 ? $"{100 * beside.Min():F2} to {100 * beside.Max():F2} %" : "none within a spacing";
                TestContext.Progress.WriteLine($"t={sim.SimulatedTime:F1} s clamp hits {sim.ReadDiagnostics().ClampHits}: {near.Count} centres within 0.35 spacings " +
                    $"of the front and back walls ({near.Count(p => p.Phase == oil)} oil), closest to any face {closest:F3} spacings; " +
                    $"the nearest to the front or back wall, {FrontBackGap(particles[nearest]):F3} spacings, reads {100 * own:F3} % from its rest, " +
                    $"its wall particles {wallReading} ({h / s:F2}-spacing support)");
            }
        }
    }
}
