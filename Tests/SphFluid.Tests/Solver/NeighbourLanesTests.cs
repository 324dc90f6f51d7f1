using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Reference;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// The laned neighbour loops (NeighbourLanes.hlsl): the same particles, stepped with 2 and 8 threads per particle, give
    /// the densities, accelerations, velocity corrections and delta-SPH rates of one thread per particle to 1e-5 of each
    /// quantity's scale, only the order of the sums differing. The CPU device these tests run on takes one lane by itself
    /// (NeighbourLanes.For), so every other GPU test checks the one-lane path against the reference; this one sets the
    /// lanes by hand. Each laned kernel is covered: DensityPressure (summation), DensityRate and ContinuityDensity
    /// (delta-SPH), WallPressure and Forces (both), NonPressureForces (DFSPH).
    /// </summary>
    public sealed class NeighbourLanesTests
    {
        const double Tolerance = 1e-5;

        [TestCase(1, ExpectedResult = 8, TestName = "NeighbourLanes_EightForAFewParticles")]
        [TestCase(8192, ExpectedResult = 8)]
        [TestCase(8193, ExpectedResult = 4)]
        [TestCase(32768, ExpectedResult = 2)]
        [TestCase(32769, ExpectedResult = 1)]
        [TestCase(1_000_000, ExpectedResult = 1)]
        public int LanesFallWithTheParticleCount(int particles) => NeighbourLanes.For(particles, false);

        [Test]
        public void ACpuDeviceTakesOneLaneAndOnlyPowersOfTwoUpToEightAreTaken()
        {
            Assert.That(NeighbourLanes.For(100, true), Is.EqualTo(1));
            Assert.That(NeighbourLanes.For(GpuTestDevice.Shared.RunsOnCpu ? 100 : 0, GpuTestDevice.Shared.RunsOnCpu), Is.EqualTo(1));
            foreach (int lanes in new[] { 1, 2, 4, 8 }) Assert.That(NeighbourLanes.IsValid(lanes), Is.True, lanes.ToString());
            foreach (int lanes in new[] { 0, 3, 16, -2 }) Assert.That(NeighbourLanes.IsValid(lanes), Is.False, lanes.ToString());
            using var sim = new FluidSimulation(GpuTestDevice.Shared, SolverKernelTests.RandomScene(false, false, false, false));
            var error = Assert.Throws<ArgumentOutOfRangeException>(() => sim.LanesPerParticle = 3);
            Assert.That(error!.Message, Does.Contain("lanes per particle must be 1, 2, 4 or 8"));
        }

        [TestCase(WcsphDensity.Summation, PressureSolver.Wcsph, 2, TestName = "NeighbourLanes_Summation_TwoLanes")]
        [TestCase(WcsphDensity.Summation, PressureSolver.Wcsph, 8, TestName = "NeighbourLanes_Summation_EightLanes")]
        [TestCase(WcsphDensity.DeltaSph, PressureSolver.Wcsph, 8, TestName = "NeighbourLanes_DeltaSph_EightLanes")]
        [TestCase(WcsphDensity.Summation, PressureSolver.Dfsph, 8, TestName = "NeighbourLanes_Dfsph_EightLanes")]
        public void LanesGiveTheSumsOfOneThread(WcsphDensity density, PressureSolver solver, int lanes)
        {
            var one = Forces(density, solver, 1, out var oneRates);
            var many = Forces(density, solver, lanes, out var manyRates);
            int n = one.Particles.Length;
            var oneById = one.IndexById();
            var manyById = many.IndexById();
            Assert.That(ReferenceComparison.Max(n, k => Math.Abs(one.Accelerations[oneById[k]].Y)), Is.GreaterThan(1.0), "the case must have forces");
            ReferenceComparison.Compare("density", Tolerance, n, k => one.Densities[oneById[k]].X, k => many.Densities[manyById[k]].X);
            ReferenceComparison.Compare("pressure", Tolerance, n, k => one.Densities[oneById[k]].W, k => many.Densities[manyById[k]].W);
            ReferenceComparison.CompareVectors("acceleration", Tolerance, n, k => Of(one.Accelerations[oneById[k]]), k => Of(many.Accelerations[manyById[k]]));
            ReferenceComparison.CompareVectors("velocity correction", Tolerance, n, k => Of(one.Corrections[oneById[k]]), k => Of(many.Corrections[manyById[k]]));
            if (density == WcsphDensity.DeltaSph)
            {
                ReferenceComparison.Compare("continuity term", Tolerance, n, k => oneRates[oneById[k]].X, k => manyRates[manyById[k]].X);
                ReferenceComparison.Compare("diffusion term", Tolerance, n, k => oneRates[oneById[k]].Y, k => manyRates[manyById[k]].Y);
            }
        }

        static Double3 Of(Vector4 v) => new Double3(v.X, v.Y, v.Z);

        /// <summary>The noisy two-phase blob of SolverKernelTests (XSPH on, a turning container), its forces computed with
        /// <paramref name="lanes"/> threads per particle.</summary>
        static GpuState Forces(WcsphDensity density, PressureSolver solver, int lanes, out Vector2[] rates)
        {
            var scene = SolverKernelTests.RandomScene(true, false, true, false);
            scene.Settings.WcsphDensity = density;
            scene.Settings.PressureSolver = solver;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene) { LanesPerParticle = lanes };
            var input = SolverKernelTests.RandomParticles(scene, sim.ParticleCount, 1357);
            sim.SetParticles(input);
            sim.ComputeForces();
            rates = new Vector2[sim.ParticleCount];
            if (density == WcsphDensity.DeltaSph) sim.DensityRates.GetData(rates);
            return GpuState.Read(sim);
        }
    }
}
