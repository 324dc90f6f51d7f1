using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The viscous step limit (ViscousStepLimit) against the force pass the GPU runs. On a block of lattice the force
    /// turns a velocity wave into -nu Lambda(k) times itself, as the analysis says; a sub-step multiplies the stiffest
    /// wave by 1 - dt nu Lambda_max, so the wave dies at the step the controller allows and grows beyond twice it, where
    /// the old rule, 0.125 H^2 / nu, stood. (HardCaseTests runs a pool at the viscosity's bound, 1000 Pa s, which that
    /// rule blew up within 0.02 s.)
    /// </summary>
    [Category(TestProcesses.LongRuns)]
    public sealed class ViscousStepTests
    {
        const float Spacing = 0.02f;
        const float Viscosity = 1000f; // Pa s: nu = 1 m^2/s, so the viscous step is a tenth of the speed of sound's

        static FluidSceneDescription Block(KernelFamily kernel, float supportRatio, ViscousStress stress = ViscousStress.Laplacian)
        {
            var settings = SolverScenes.Coarse(Spacing);
            settings.ViscousStress = stress;
            settings.SmoothingKernel = kernel;
            settings.SmoothingRadius = supportRatio * Spacing;
            settings.Gravity = Vector3.Zero;
            settings.XsphEpsilon = 0f;
            settings.ArtificialViscosity = 0f;
            settings.MaxSubsteps = 1000;
            var size = new Vector3(16 * Spacing);
            var water = SolverScenes.Box("Water", SolverScenes.Water(Viscosity), Vector3.Zero, size, jitter: 0f);
            return SolverScenes.Scene(settings, size, water);
        }

        /// <summary>v = u cos(k . (x - x_0)) along x on every particle, x_0 a lattice point (the lattice sits half a spacing
        /// off the origin, where the zone corner's cosine would vanish on every particle).</summary>
        static void PutWave(Particle[] particles, Vector3 k, float u)
        {
            var origin = particles[0].Position;
            for (int i = 0; i < particles.Length; i++)
                particles[i].Velocity = new Vector3(u * MathF.Cos(Vector3.Dot(k, particles[i].Position - origin)), 0f, 0f);
        }

        static bool Inside(Vector3 p, float margin) =>
            MathF.Max(MathF.Abs(p.X), MathF.Max(MathF.Abs(p.Y), MathF.Abs(p.Z))) < 8 * Spacing - margin;

        [TestCase(KernelFamily.CubicSpline, 2f, 1f, 1f, 1f)]
        [TestCase(KernelFamily.CubicSpline, 2f, 0.25f, 0f, 0f)]
        [TestCase(KernelFamily.WendlandC2, 2.85f, 1f, 1f, 1f)]
        [TestCase(KernelFamily.WendlandC2, 2.85f, 0.5f, 0.25f, 0f)]
        public void TheForcePassTurnsAWaveIntoLambdaTimesItself(KernelFamily kernel, float supportRatio, float kx, float ky, float kz)
        {
            var scene = Block(kernel, supportRatio);
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            var k = new Vector3(kx, ky, kz) * (MathF.PI / Spacing);
            const float u = 0.01f;
            PutWave(particles, k, u);
            sim.SetParticles(particles);
            sim.Particles.GetData(particles);
            var accelerations = new Vector4[sim.ParticleCount];
            sim.Accelerations.GetData(accelerations);

            double nu = Viscosity / 1000.0;
            double lambda = ViscousStepLimit.Mode(kernel, Spacing, scene.Settings.SmoothingRadius, k.X, k.Y, k.Z);
            double worst = 0.0, squares = 0.0;
            int interior = 0;
            for (int i = 0; i < particles.Length; i++)
            {
                if (!Inside(particles[i].Position, scene.Settings.SmoothingRadius)) continue;
                interior++;
                var expected = new Vector3((float)(-nu * lambda * particles[i].Velocity.X), 0f, 0f);
                var a = new Vector3(accelerations[i].X, accelerations[i].Y, accelerations[i].Z);
                worst = Math.Max(worst, (a - expected).Length() / (nu * lambda * u));
                squares += particles[i].Velocity.X * particles[i].Velocity.X;
            }
            double rms = Math.Sqrt(squares / Math.Max(1, interior));
            TestContext.Progress.WriteLine($"{kernel} at {supportRatio} spacings, k = ({kx}, {ky}, {kz}) pi / s: nu Lambda {nu * lambda:F1} 1/s; " +
                $"{interior} interior particles at {rms / u:F3} u (RMS), largest departure {worst:E2} of nu Lambda u");
            Assert.That(interior, Is.GreaterThan(100));
            Assert.That(rms, Is.GreaterThan(0.5 * u), "the wave is on the particles, not at its nodes");
            Assert.That(worst, Is.LessThan(1e-4));
        }

        /// <summary>The stiffest wave, u = 0.1 mm/s on every particle, after 40 sub-steps of f / (nu Lambda_max); the fastest
        /// particle's speed.</summary>
        static float FastestAfter(KernelFamily kernel, float supportRatio, bool freeSurface, double f,
            ViscousStress stress = ViscousStress.Laplacian)
        {
            var scene = Block(kernel, supportRatio, stress);
            if (freeSurface)
            {
                // Room above the block: its top is a free surface, whose particles, thin under summation density, carry
                // larger volumes than the lattice's.
                scene.Container.Size = new Vector3(16 * Spacing, 24 * Spacing, 16 * Spacing);
                scene.Container.Position = new Vector3(0f, 4 * Spacing, 0f);
            }
            // The explicit force past its limit: without this the sub-steps beyond it would solve the viscosity implicitly.
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene) { ImplicitViscosityAllowed = false };
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            PutWave(particles, new Vector3(1f, 1f, 1f) * (MathF.PI / Spacing), 1e-4f);
            sim.SetParticles(particles);
            double nu = Viscosity / 1000.0;
            sim.StepFixed(40, (float)(f / (nu * ViscousStepLimit.StiffestMode(kernel, Spacing, scene.Settings.SmoothingRadius))));
            sim.Particles.GetData(particles);
            return particles.Max(p => p.Velocity.Length());
        }

        /// <summary>At the step the controller allows (f = 1) the wave dies, beside the walls and under a free surface; at the
        /// old rule's, 0.125 H^2 / nu (f = 2.91 for the cubic spline at 2 spacings, 3.20 for Wendland C2 at 2.85), it grows
        /// without bound.</summary>
        [TestCase(KernelFamily.CubicSpline, 2f, false)]
        [TestCase(KernelFamily.CubicSpline, 2f, true)]
        [TestCase(KernelFamily.WendlandC2, 2.85f, false)]
        [TestCase(KernelFamily.WendlandC2, 2.85f, true)]
        public void TheStiffestWaveDiesAtTheStepAllowedAndGrewAtTheOldRules(KernelFamily kernel, float supportRatio, bool freeSurface)
        {
            double support = supportRatio * Spacing;
            double old = 0.125 * support * support * ViscousStepLimit.StiffestMode(kernel, Spacing, support);
            float allowed = FastestAfter(kernel, supportRatio, freeSurface, 1.0);
            float oldRule = FastestAfter(kernel, supportRatio, freeSurface, old);
            TestContext.Progress.WriteLine($"{kernel} at {supportRatio} spacings{(freeSurface ? ", free surface" : "")}: from 1E-04 m/s, " +
                $"{allowed:E2} m/s after 40 sub-steps at the step allowed, {oldRule:E2} at the old rule's (f = {old:F2})");
            Assert.That(allowed, Is.LessThan(1e-6f));
            Assert.That(oldRule, Is.GreaterThan(1e-2f));
        }

        /// <summary>The strain rate's viscous stress is Morris's pair term twice over, less the pairs' rotation: the controller
        /// allows it half Morris's step (TimeStepController.OperatorViscosity), where the stiffest wave dies beside the walls
        /// and under a free surface. At Morris's own step it grows under Wendland C2's free surface (from 1E-04 to 0.115 m/s);
        /// the cubic spline's shrinks there too, but only to 1.7E-05 m/s in the 40 sub-steps.</summary>
        [TestCase(KernelFamily.CubicSpline, 2f, false, false)]
        [TestCase(KernelFamily.CubicSpline, 2f, true, false)]
        [TestCase(KernelFamily.WendlandC2, 2.85f, false, false)]
        [TestCase(KernelFamily.WendlandC2, 2.85f, true, true)]
        public void TheStrainRatesStiffestWaveDiesAtHalfMorrissStep(KernelFamily kernel, float supportRatio, bool freeSurface, bool growsAtMorris)
        {
            var scene = Block(kernel, supportRatio, ViscousStress.StrainRate);
            double morris = 1.0 / (Viscosity / 1000.0 * ViscousStepLimit.StiffestMode(kernel, Spacing, scene.Settings.SmoothingRadius));
            double share = TimeStepController.ForScene(scene).ViscousTimeStep / morris;
            float allowed = FastestAfter(kernel, supportRatio, freeSurface, share, ViscousStress.StrainRate);
            float atMorris = FastestAfter(kernel, supportRatio, freeSurface, 1.0, ViscousStress.StrainRate);
            TestContext.Progress.WriteLine($"{kernel} at {supportRatio} spacings{(freeSurface ? ", free surface" : "")}, strain-rate stress: " +
                $"from 1E-04 m/s, {allowed:E2} m/s after 40 sub-steps at the step allowed ({share:F2} of Morris's), {atMorris:E2} at Morris's");
            Assert.That(share, Is.EqualTo(0.5).Within(1e-6));
            Assert.That(allowed, Is.LessThan(1e-6f));
            if (growsAtMorris) Assert.That(atMorris, Is.GreaterThan(1e-2f));
        }

        /// <summary>Between the walls the wave's bound is the analysis's, dt nu Lambda_max = 2: it dies at 1.9 and grows at
        /// 2.2. (Under a free surface it grows from about 1.8: the room the step allowed leaves.)</summary>
        [TestCase(KernelFamily.CubicSpline, 2f)]
        [TestCase(KernelFamily.WendlandC2, 2.85f)]
        public void BetweenTheWallsTheBoundIsTwiceTheStepAllowed(KernelFamily kernel, float supportRatio)
        {
            float below = FastestAfter(kernel, supportRatio, false, 1.9), above = FastestAfter(kernel, supportRatio, false, 2.2);
            TestContext.Progress.WriteLine($"{kernel} at {supportRatio} spacings: from 1E-04 m/s, {below:E2} m/s after 40 sub-steps at " +
                $"1.9 / (nu Lambda_max), {above:E2} at 2.2");
            Assert.That(below, Is.LessThan(1e-6f));
            Assert.That(above, Is.GreaterThan(1e-4f));
        }
    }
}
