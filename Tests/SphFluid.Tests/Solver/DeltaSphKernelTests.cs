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

            Assert.That(Max(n, k => diffusion[k]), Is.GreaterThan(1e-3 * Max(n, k => continuity[k])), "the diffusion must have work");
            Compare("continuity term", n, k => continuity[k], k => rates[byId[k]].X);
            Compare("diffusion term", n, k => diffusion[k], k => rates[byId[k]].Y);
            Compare("number density", n, k => state.NumberDensity[k], k => gpu.Densities[byId[k]].Z);
            Compare("pressure", n, k => state.Pressure[k], k => gpu.Densities[byId[k]].Y);
            Assert.That(Max(n, k => state.Pressure[k]), Is.GreaterThan(100.0), "the case must be compressed");
            CompareVectors("acceleration", Tolerance, n, k => state.Acceleration[k], k => new Double3(gpu.Accelerations[byId[k]].X, gpu.Accelerations[byId[k]].Y, gpu.Accelerations[byId[k]].Z));

            const float dt = 0.0005f;
            var expected = reference.Substep(start, state, dt, sim.Plan.Xsph, delta, out _);
            sim.StepFixed(1, dt);
            var after = GpuState.Read(sim);
            var afterById = after.IndexById();
            var stepped = new float[n];
            sim.NumberDensities.GetData(stepped);
            Compare("number density change over the sub-step", n, k => delta[k] - carried[k], k => (double)stepped[k] - carried[k]);
            CompareVectors("displacement", MotionTolerance, n, k => new Double3(expected[k].Position) - new Double3(start[k].Position),
                k => new Double3(after.Particles[afterById[k]].Position) - new Double3(start[k].Position));
            CompareVectors("velocity", MotionTolerance, n, k => new Double3(expected[k].Velocity), k => new Double3(after.Particles[afterById[k]].Velocity));
        }

        static double Max(int n, Func<int, double> f)
        {
            double m = 0;
            for (int i = 0; i < n; i++) m = Math.Max(m, Math.Abs(f(i)));
            return m;
        }

        static void Compare(string what, int n, Func<int, double> expected, Func<int, double> actual)
        {
            double scale = Math.Max(Max(n, expected), 1e-30), worst = 0;
            int at = -1;
            for (int i = 0; i < n; i++)
            {
                double e = Math.Abs(actual(i) - expected(i)) / scale;
                if (e > worst) { worst = e; at = i; }
            }
            TestContext.Out.WriteLine($"{what}: scale {scale:G4}, worst relative error {worst:E2}");
            Assert.That(worst, Is.LessThanOrEqualTo(Tolerance), $"{what}: particle id {at} (scale {scale:G4})");
        }

        static void CompareVectors(string what, double tolerance, int n, Func<int, Double3> expected, Func<int, Double3> actual)
        {
            double scale = Math.Max(Max(n, i => expected(i).Length()), 1e-30), worst = 0;
            int at = -1;
            for (int i = 0; i < n; i++)
            {
                var d = actual(i) - expected(i);
                double e = Math.Max(Math.Abs(d.X), Math.Max(Math.Abs(d.Y), Math.Abs(d.Z))) / scale;
                if (e > worst) { worst = e; at = i; }
            }
            TestContext.Out.WriteLine($"{what}: scale {scale:G4}, worst relative component error {worst:E2}");
            Assert.That(worst, Is.LessThanOrEqualTo(tolerance), $"{what}: particle id {at} (scale {scale:G4})");
        }
    }
}
