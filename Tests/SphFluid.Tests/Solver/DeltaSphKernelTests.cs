using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Reference;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// delta-SPH (SphDensityDiffusion.hlsl; WcsphDensity = DeltaSph) against the double-precision CPU reference: on the
    /// noisy, compressed blob of SolverKernelTests (a turning, moving container, so the walls' velocities enter the
    /// continuity term) with carried number densities scattered 2 % around rest, the continuity and diffusion terms, the
    /// density, pressure and accelerations they give, and after one sub-step the change of every carried number density
    /// must match to 1e-5 of each quantity's scale (the particles' motion to 1e-4, see MotionTolerance).
    /// </summary>
    public sealed class DeltaSphKernelTests
    {
        const double Tolerance = 1e-5;

        /// <summary>The particles' motion is held to SolverKernelTests' 1e-4: a float position 0.08 m from the origin rounds a
        /// 0.4 mm displacement at about 1e-5 of it.</summary>
        const double MotionTolerance = 1e-4;

        [TestCase(false, TestName = "DeltaSph_MatchesReference_SinglePhase")]
        [TestCase(true, TestName = "DeltaSph_MatchesReference_TwoPhasesXsph")]
        public void RatesAndSubstepMatchReference(bool multiphase)
        {
            var scene = SolverKernelTests.RandomScene(multiphase, false, multiphase, false);
            scene.Settings.WcsphDensity = WcsphDensity.DeltaSph;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            Assert.That(sim.Plan.DeltaSph, Is.True);
            var input = SolverKernelTests.RandomParticles(scene, sim.ParticleCount, 2468);
            sim.SetParticles(input);
            int n = input.Length;
            var rng = new SolverScenes.Rng(97);
            var carried = new float[n];
            for (int k = 0; k < n; k++)
            {
                var phase = sim.PhaseRows[(int)input[k].Phase];
                carried[input[k].Id] = phase.RestDensity / phase.ParticleMass * rng.Range(0.98f, 1.02f);
            }
            sim.NumberDensities.SetData(carried);
            sim.ComputeForces();

            var gpu = GpuState.Read(sim);
            var byId = gpu.IndexById();
            var start = gpu.ByIdParticles(input);
            var rates = new Vector2[n];
            sim.DensityRates.GetData(rates);
            var delta = new double[n];
            for (int k = 0; k < n; k++) delta[k] = carried[k];
            var reference = new ReferenceSph(scene);
            var velocities = new Double3[n];
            for (int k = 0; k < n; k++) velocities[k] = new Double3(start[k].Velocity);
            reference.DensityRates(start, velocities, delta, out var continuity, out var diffusion);
            var state = reference.Evaluate(start, true, delta);

            Assert.That(ReferenceComparison.Max(n, k => diffusion[k]), Is.GreaterThan(1e-3 * ReferenceComparison.Max(n, k => continuity[k])), "the diffusion must have work");
            ReferenceComparison.Compare("continuity term", Tolerance, n, k => continuity[k], k => rates[byId[k]].X);
            ReferenceComparison.Compare("diffusion term", Tolerance, n, k => diffusion[k], k => rates[byId[k]].Y);
            ReferenceComparison.Compare("number density", Tolerance, n, k => state.NumberDensity[k], k => gpu.Densities[byId[k]].Z);
            ReferenceComparison.Compare("pressure", Tolerance, n, k => state.Pressure[k], k => gpu.Densities[byId[k]].Y);
            Assert.That(ReferenceComparison.Max(n, k => state.Pressure[k]), Is.GreaterThan(100.0), "the case must be compressed");
            ReferenceComparison.CompareVectors("acceleration", Tolerance, n, k => state.Acceleration[k], k => new Double3(gpu.Accelerations[byId[k]].X, gpu.Accelerations[byId[k]].Y, gpu.Accelerations[byId[k]].Z));

            // delta-SPH's wall contact acts by distance alone (SphBoundary.hlsl): the block must hold particles at or above
            // rest density that are closer to a wall than the flat-wall lattice, which summation's contact would leave alone.
            var s = scene.Settings;
            double flatWall = SmoothingKernels.FlatWallNumberDensity(s.SmoothingKernel, s.ParticleSpacing, s.SmoothingRadius);
            int denseAtWalls = 0;
            for (int k = 0; k < n; k++)
                if (state.Density[k] >= sim.PhaseRows[(int)start[k].Phase].RestDensity && state.WallNumberDensity[k] > flatWall) denseAtWalls++;
            Assert.That(denseAtWalls, Is.GreaterThan(0), "dense particles in wall contact");

            const float dt = 0.0005f;
            var expected = reference.Substep(start, state, dt, sim.Plan.Xsph, delta, out _);
            sim.StepFixed(1, dt);
            var after = GpuState.Read(sim);
            var afterById = after.IndexById();
            var stepped = new float[n];
            sim.NumberDensities.GetData(stepped);
            ReferenceComparison.Compare("number density change over the sub-step", Tolerance, n, k => delta[k] - carried[k], k => (double)stepped[k] - carried[k]);
            ReferenceComparison.CompareVectors("displacement", MotionTolerance, n, k => new Double3(expected[k].Position) - new Double3(start[k].Position),
                k => new Double3(after.Particles[afterById[k]].Position) - new Double3(start[k].Position));
            ReferenceComparison.CompareVectors("velocity", MotionTolerance, n, k => new Double3(expected[k].Velocity), k => new Double3(after.Particles[afterById[k]].Velocity));
        }
    }
}
