using System;
using System.Collections.Generic;
using System.Numerics;
using System.Runtime.InteropServices;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Health
{
    /// <summary>
    /// The same scene and seed give a bit-identical state on the same device: two fresh simulations, stepped
    /// alike, hold the same particle bytes (sorted order, positions, velocities, ids) and the same densities.
    /// The scene switches every kernel variant on: two phases, surface tension, XSPH and a moving sphere.
    /// </summary>
    public sealed class DeterminismTests
    {
        const int Substeps = 40;

        static FluidSceneDescription Scene(int seed)
        {
            var settings = SolverScenes.Coarse(0.04f);
            var tank = new Vector3(0.48f, 0.4f, 0.16f);
            var scene = SolverScenes.Scene(settings, tank,
                SolverScenes.Box("Water", SolverScenes.Water(tension: 0.07f), new Vector3(-0.12f, -0.12f, 0f), new Vector3(0.24f, 0.16f, 0.16f), seed: seed),
                SolverScenes.Box("Oil", SolverScenes.Oil(tension: 0.03f), new Vector3(0.12f, -0.12f, 0f), new Vector3(0.24f, 0.16f, 0.16f), seed: seed + 1, jitter: 0.3f));
            scene.Obstacles.Add(new RigidSphere(new Vector3(0f, 0.05f, 0f), 0.05f, new Vector3(0f, -0.5f, 0f)));
            return scene;
        }

        /// <summary>Particle and density bytes after the stepping <paramref name="step"/> does.</summary>
        static (byte[] Particles, byte[] Densities) StateAfter(FluidSceneDescription scene, Action<FluidSimulation> step)
        {
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, scene))
            {
                step(sim);
                var particles = new Particle[sim.ParticleCount];
                var densities = new Vector4[sim.ParticleCount];
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                return (MemoryMarshal.AsBytes(particles.AsSpan()).ToArray(), MemoryMarshal.AsBytes(densities.AsSpan()).ToArray());
            }
        }

        static int DifferingBytes(byte[] a, byte[] b)
        {
            int n = 0;
            for (int i = 0; i < Math.Min(a.Length, b.Length); i++) if (a[i] != b[i]) n++;
            return n + Math.Abs(a.Length - b.Length);
        }

        [Test]
        public void FixedSubsteps_GiveBitIdenticalStates()
        {
            Action<FluidSimulation> step = sim => sim.StepFixed(Substeps, 0.002f);
            var first = StateAfter(Scene(7), step);
            var second = StateAfter(Scene(7), step);
            Assert.That(first.Particles.Length, Is.EqualTo(192 * Particle.Stride));
            Assert.That(DifferingBytes(first.Particles, second.Particles), Is.EqualTo(0), "particle bytes");
            Assert.That(DifferingBytes(first.Densities, second.Densities), Is.EqualTo(0), "density bytes");
        }

        [Test]
        public void AdaptiveFrames_GiveBitIdenticalStates()
        {
            Action<FluidSimulation> step = sim => { for (int f = 0; f < 6; f++) sim.Step(1f / 60f); };
            var first = StateAfter(Scene(7), step);
            var second = StateAfter(Scene(7), step);
            Assert.That(DifferingBytes(first.Particles, second.Particles), Is.EqualTo(0), "particle bytes");
            Assert.That(DifferingBytes(first.Densities, second.Densities), Is.EqualTo(0), "density bytes");
        }

        [Test]
        public void AnotherSeed_GivesAnotherState()
        {
            Action<FluidSimulation> step = sim => sim.StepFixed(Substeps, 0.002f);
            var first = StateAfter(Scene(7), step);
            var other = StateAfter(Scene(8), step);
            Assert.That(DifferingBytes(first.Particles, other.Particles), Is.GreaterThan(1000), "the comparison can fail");
        }
    }
}
