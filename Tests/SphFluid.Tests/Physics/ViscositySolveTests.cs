using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Scenes;
using SphFluid.Reference;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// DFSPH's implicit viscosity solve (SphViscositySolve.hlsl) against the equation it solves and against the explicit
    /// force it replaces beyond the explicit step: the solved velocities against the CPU reference's force; a cellular flow
    /// in a box with free-slip walls, u = U sin(k x) cos(k z), w = -U cos(k x) sin(k z), k = pi / L, divergence-free,
    /// parallel to every wall and free of shear at them, a Stokes mode that decays as exp(-2 nu k^2 t), whose decay rate
    /// under the explicit force the solve must approach as its step comes down to the limit; and OilAndWater's flow with
    /// its oil at 100 Pa s.
    /// </summary>
    public sealed class ViscositySolveTests
    {
        const float Spacing = 0.02f;
        const int Cells = 16;                 // L = 16 spacings along x and z
        const float Viscosity = 100f;         // Pa s: nu = 0.1 m^2/s, the explicit limit 1.27 ms
        const float U = 0.005f;               // m/s: Stokes flow (Re = U L / nu = 0.016)
        const double Seconds = 0.05;
        // Sub-steps a frame: the solves' budget of recorded rounds follows what earlier frames needed (SolveBudget), so
        // frames of 100 sub-steps record the full cap each and took this test twice as long.
        const int FrameSteps = 10;

        /// <summary>DFSPH with the shipped kernel (Wendland C2 at 2.85 spacings), no gravity and no XSPH.</summary>
        static FluidSettings Weightless()
        {
            var settings = SolverScenes.Coarse(Spacing);
            settings.PressureSolver = PressureSolver.Dfsph;
            settings.SmoothingKernel = KernelFamily.WendlandC2;
            settings.SmoothingRadius = 2.85f * Spacing;
            settings.SolverRelaxation = 0.3f;
            settings.Gravity = Vector3.Zero;
            settings.XsphEpsilon = 0f;
            return settings;
        }

        static FluidSceneDescription Box()
        {
            var settings = Weightless();
            settings.MaxSubsteps = 1000;
            var size = new Vector3(Cells * Spacing, 8 * Spacing, Cells * Spacing);
            var water = SolverScenes.Box("Water", SolverScenes.Water(Viscosity), Vector3.Zero, size, jitter: 0f);
            var scene = SolverScenes.Scene(settings, size, water);
            scene.Container.Friction = WallFriction.Slip;
            return scene;
        }

        static double K => Math.PI / (Cells * Spacing);

        static Vector3 Cell(Vector3 p)
        {
            float half = 0.5f * Cells * Spacing;
            double kx = K * (p.X + half), kz = K * (p.Z + half);
            return new Vector3((float)(Math.Sin(kx) * Math.Cos(kz)), 0f, (float)(-Math.Cos(kx) * Math.Sin(kz)));
        }

        /// <summary>The flow's amplitude: the particles' velocities projected on the mode, over its square.</summary>
        static double Amplitude(Particle[] particles)
        {
            double dot = 0.0, norm = 0.0;
            foreach (var p in particles)
            {
                var mode = Cell(p.Position);
                dot += Vector3.Dot(p.Velocity, mode);
                norm += Vector3.Dot(mode, mode);
            }
            return dot / norm;
        }

        /// <summary>The mode's amplitude over U after <paramref name="steps"/> sub-steps covering <see cref="Seconds"/>, the
        /// fluid's momentum over its mass times U, and the implicit solve's rounds a sub-step (0: explicit).</summary>
        static (double amplitude, double momentum, int rounds) Decay(int steps)
        {
            var scene = Box();
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            for (int i = 0; i < particles.Length; i++)
                particles[i].Velocity = U * Cell(particles[i].Position);
            sim.SetParticles(particles);
            float dt = (float)(Seconds / steps);
            for (int done = 0; done < steps; done += FrameSteps)
                sim.StepFixed(Math.Min(FrameSteps, steps - done), dt);
            sim.Particles.GetData(particles);
            var momentum = particles.Aggregate(Vector3.Zero, (sum, p) => sum + p.Velocity);
            var limit = sim.TimeStep.ViscousTimeStep;
            int rounds = sim.ViscositySolveRounds;
            TestContext.Progress.WriteLine($"{steps} steps of {1000 * dt:F3} ms ({dt / limit:F2} of the explicit limit, {rounds} rounds): " +
                $"amplitude {Amplitude(particles) / U:F4} U, momentum {momentum.Length() / particles.Length / U:E2} U");
            return (Amplitude(particles) / U, momentum.Length() / particles.Length / U, rounds);
        }

        /// <summary>The SPH viscous operator's own decay rate for the flow on the spawned particles: its Rayleigh quotient,
        /// -sum a . v / sum v . v with a the CPU reference's viscous acceleration (no gravity, no pressure) for v the mode.</summary>
        static double OperatorRate()
        {
            var scene = Box();
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            for (int i = 0; i < particles.Length; i++)
                particles[i].Velocity = Cell(particles[i].Position);
            var state = new ReferenceSph(scene).Evaluate(particles, false);
            double work = 0.0, squares = 0.0;
            for (int i = 0; i < particles.Length; i++)
            {
                var v = new Double3(particles[i].Velocity);
                work -= Double3.Dot(state.Acceleration[i], v);
                squares += v.LengthSquared();
            }
            return work / squares;
        }

        /// <summary>
        /// The explicit force decays the flow faster than the viscous operator's own rate, and the faster the more sub-steps
        /// it takes: each sub-step's constant-density solve, which corrects compression only, takes a little of the flow
        /// where its particle sums are not divergence-free (beside the walls). So the implicit solve, at fewer sub-steps,
        /// falls behind the explicit force's rate, but stays near backward Euler at the operator's own rate, (1 + lambda
        /// dt)^-n, whose lag at long steps is the method's (Headless/docs/physics.md, "Viscosity solved implicitly").
        /// </summary>
        [Test]
        public void TheCellularFlowDecaysAsBackwardEulerAtTheViscousOperatorsOwnRate()
        {
            double own = OperatorRate();
            double stokes = 2.0 * (Viscosity / 1000.0) * K * K;
            var explicitRuns = new[] { Decay(100), Decay(50) };
            double lambda = -Math.Log(explicitRuns[0].amplitude) / Seconds, fewer = -Math.Log(explicitRuns[1].amplitude) / Seconds;
            TestContext.Progress.WriteLine($"the viscous operator's own rate {own:F3}/s (Stokes's 2 nu k^2: {stokes:F3}/s); " +
                $"explicit force {lambda:F3}/s in 100 sub-steps, {fewer:F3}/s in 50");
            Assert.That(explicitRuns.Select(r => r.rounds), Is.All.EqualTo(0), "within the explicit limit");
            Assert.That(lambda, Is.GreaterThan(fewer), "more sub-steps take more of the flow");
            Assert.That(fewer, Is.GreaterThan(own));
            double previousLag = 0.0;
            foreach (int steps in new[] { 32, 8, 4 })
            {
                var run = Decay(steps);
                double dt = Seconds / steps;
                double rate = -Math.Log(run.amplitude) / Seconds;
                double lag = 1.0 - rate / lambda;
                double euler = Math.Pow(1.0 + own * dt, -steps);
                TestContext.Progress.WriteLine($"  decay rate {rate:F3}/s, {100 * lag:F1} % behind the explicit force's; amplitude " +
                    $"{run.amplitude:F4} U against backward Euler's {euler:F4} U at the operator's rate ({run.amplitude / euler - 1:+0.0%;-0.0%})");
                Assert.That(run.rounds, Is.GreaterThan(0), "the step is beyond the explicit limit");
                Assert.That(lag, Is.GreaterThan(previousLag), "the lag grows with the step");
                Assert.That(lag, Is.LessThan(steps == 32 ? 0.10 : 0.30));
                Assert.That(run.amplitude / euler, Is.InRange(0.92, 1.08));
                Assert.That(run.momentum, Is.LessThan(1e-3), "free-slip walls take no momentum");
                previousLag = lag;
            }
        }

        /// <summary>The solve against the equation it solves, in double precision on the CPU (ReferenceSph's viscous force):
        /// a block of jittered water with a free surface and no-slip walls, random velocities, one prediction at ten times
        /// the explicit limit. The residual of backward Euler, (v* - x) + dt a_visc(x), must be a small part of the change.</summary>
        [TestCase(false)]
        [TestCase(true)]
        public void ThePredictedVelocitiesSolveBackwardEulerToItsTolerance(bool oilOnWater)
        {
            var settings = Weightless();
            var block = new Vector3(10 * Spacing, 8 * Spacing, 10 * Spacing);
            var container = new Vector3(10 * Spacing, 12 * Spacing, 10 * Spacing);
            var scene = oilOnWater
                ? SolverScenes.Scene(settings, container,
                    SolverScenes.Box("Water", SolverScenes.Water(0.05f), new Vector3(0f, -4 * Spacing, 0f), block * new Vector3(1f, 0.5f, 1f), jitter: 0.1f),
                    SolverScenes.Box("Oil", SolverScenes.Oil(Viscosity), new Vector3(0f, 0f, 0f), block * new Vector3(1f, 0.5f, 1f), seed: 2, jitter: 0.1f))
                : SolverScenes.Scene(settings, container,
                    SolverScenes.Box("Water", SolverScenes.Water(Viscosity), new Vector3(0f, -2 * Spacing, 0f), block, jitter: 0.1f));
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            var rng = new SolverScenes.Rng(7);
            for (int i = 0; i < particles.Length; i++)
                particles[i].Velocity = new Vector3(rng.Range(-1f, 1f), rng.Range(-1f, 1f), rng.Range(-1f, 1f)) * 0.01f;
            sim.SetParticles(particles);
            sim.Particles.GetData(particles);
            var predicted = particles.ToDictionary(p => p.Id, p => p.Velocity);
            float dt = (float)(10.0 * sim.TimeStep.ViscousTimeStep);
            sim.PredictVelocities(dt);
            sim.Particles.GetData(particles);

            var state = new ReferenceSph(scene).Evaluate(particles, false);
            double worstResidual = 0.0, largestChange = 0.0;
            for (int i = 0; i < particles.Length; i++)
            {
                var x = new Double3(particles[i].Velocity);
                var change = new Double3(predicted[particles[i].Id]) - x;
                var residual = change + state.Acceleration[i] * dt;
                worstResidual = Math.Max(worstResidual, Math.Sqrt(residual.LengthSquared()));
                largestChange = Math.Max(largestChange, Math.Sqrt(change.LengthSquared()));
            }
            TestContext.Progress.WriteLine($"{particles.Length} particles, {dt / sim.TimeStep.ViscousTimeStep:F1} explicit limits: largest change " +
                $"{largestChange:E3} m/s, largest residual {worstResidual:E3} m/s ({worstResidual / largestChange:E2} of it)");
            // Every wave's error is within the tolerance of its change; the operator multiplies an error by at most
            // 1 + dt nu Lambda_max = 1 + dt / (the explicit limit) into the residual.
            Assert.That(largestChange, Is.GreaterThan(0.005), "the viscosity changed the velocities");
            Assert.That(worstResidual, Is.LessThan(ImplicitViscosity.Tolerance * (1.0 + dt / sim.TimeStep.ViscousTimeStep) * largestChange));
        }

        /// <summary>A viscous liquid's flow that buoyancy drives: OilAndWater with its oil at 100 Pa s, whose explicit limit
        /// is 0.64 ms. Solved implicitly at the scene's own 4.17 ms steps, its kinetic energy at 0.1 s must stay near the
        /// explicit force's at 0.64 ms steps. With the viscosity solved before the constant-density solve instead, each
        /// step's pressure kick went undamped into the drift, a flow that viscosity holds ran 1 + lambda dt times its speed,
        /// and the fluid had 7.3 times the kinetic energy (SphViscositySolve.hlsl).</summary>
        [Test]
        public void ABuoyancyDrivenViscousFlowRunsAsWithTheExplicitForce()
        {
            double KineticAt(string maxTimeStep)
            {
                var path = RunnerPaths.EditedScene("OilAndWater", "MaxTimeStep: 0.005\n", $"MaxTimeStep: {maxTimeStep}\n");
                var scene = SceneLoader.Load(path, RunnerPaths.Project).Description;
                Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH OilAndWater"), Is.Null);
                foreach (var box in scene.SpawnBoxes)
                    if (box.Phase.Name == "Oil") box.Phase.Viscosity = 100f;
                using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
                while (sim.SimulatedTime < 0.1 - 1e-6)
                    sim.Step(1f / 60f);
                double kinetic = sim.ReadDiagnostics().KineticEnergy;
                TestContext.Progress.WriteLine($"steps of {1000 * sim.LastStep.TimeStep:F3} ms ({sim.LastStep.TimeStep / sim.TimeStep.ViscousTimeStep:F2} " +
                    $"explicit limits): kinetic energy at 0.1 s {kinetic:E3} J");
                return kinetic;
            }
            double explicitForce = KineticAt("0.00064"), implicitSolve = KineticAt("0.005");
            Assert.That(implicitSolve / explicitForce, Is.InRange(0.5, 1.6));
        }
    }
}
