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
    /// quantity's scale, only the order of the sums differing. On lavapipe, a CPU device, the simulation takes one lane by
    /// itself (NeighbourLanes.For), so there every other GPU test checks the one-lane path against the reference; this one
    /// sets the lanes by hand. The rule itself is tested in the package's Core tests (NeighbourLanesTests). Each laned kernel is covered: DensityPressure (summation), DensityRate and ContinuityDensity
    /// (delta-SPH), WallPressure and Forces (both), NonPressureForces (DFSPH).
    /// </summary>
    public sealed class LanedSumsTests
    {
        const double Tolerance = 1e-5;

        [Test]
        public void TheDeviceChoosesTheLanesAndALaneCountIsChecked()
        {
            using var sim = new FluidSimulation(GpuTestDevice.Shared, SolverKernelTests.RandomScene(false, false, false, false));
            Assert.That(sim.LanesPerParticle, Is.EqualTo(NeighbourLanes.For(sim.ParticleCount, GpuTestDevice.Shared.RunsOnCpu)));
            var error = Assert.Throws<ArgumentOutOfRangeException>(() => sim.LanesPerParticle = 3);
            Assert.That(error!.Message, Does.Contain("lanes per particle must be 1, 2, 4 or 8"));
        }

        [TestCase(WcsphDensity.Summation, PressureSolver.Wcsph, 2, TestName = "LanedSums_Summation_TwoLanes")]
        [TestCase(WcsphDensity.Summation, PressureSolver.Wcsph, 8, TestName = "LanedSums_Summation_EightLanes")]
        [TestCase(WcsphDensity.DeltaSph, PressureSolver.Wcsph, 8, TestName = "LanedSums_DeltaSph_EightLanes")]
        [TestCase(WcsphDensity.Summation, PressureSolver.Dfsph, 8, TestName = "LanedSums_Dfsph_EightLanes")]
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
