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
        /// where its particle sums are not divergence-free (beside the walls). The implicit solve's two stages step the
        /// operator's decay by (1 - (1 - 2 gamma) x) / (1 + gamma x)^2 with x = lambda dt, within a few tenths of a percent of
        /// exp(-x) at these steps, where backward Euler's 1 / (1 + x) lags. So at every step the flow's decay rate must be
        /// the operator's to within what the explicit force's own differs from it (the solve's share), and at the longest
        /// step nearer it than backward Euler's at that rate, which the solve's one stage did not reach (Headless/docs/
        /// physics.md, "Viscosity solved implicitly").
        /// </summary>
        [Test]
        public void TheCellularFlowDecaysAtTheViscousOperatorsOwnRate()
        {
            double own = OperatorRate();
            double stokes = 2.0 * (Viscosity / 1000.0) * K * K;
            var explicitRuns = new[] { Decay(100), Decay(50) };
            double lambda = -Math.Log(explicitRuns[0].amplitude) / Seconds, fewer = -Math.Log(explicitRuns[1].amplitude) / Seconds;
            TestContext.Progress.WriteLine($"the viscous operator's own rate {own:F3}/s (Stokes's 2 nu k^2: {stokes:F3}/s); " +
                $"explicit force {lambda:F3}/s in 100 sub-steps ({lambda / own - 1:+0.0%;-0.0%}), {fewer:F3}/s in 50");
            Assert.That(explicitRuns.Select(r => r.rounds), Is.All.EqualTo(0), "within the explicit limit");
            Assert.That(lambda, Is.GreaterThan(fewer), "more sub-steps take more of the flow");
            Assert.That(fewer, Is.GreaterThan(own));
            double g = ImplicitViscosity.StageFraction, exact = Math.Exp(-own * Seconds);
            double solveShare = lambda / own - 1.0;
            foreach (int steps in new[] { 32, 8, 4 })
            {
                var run = Decay(steps);
                double x = own * Seconds / steps;
                double twoStages = Math.Pow((1.0 - (1.0 - 2.0 * g) * x) / Math.Pow(1.0 + g * x, 2), steps);
                double euler = Math.Pow(1.0 + x, -steps);
                double rate = -Math.Log(run.amplitude) / Seconds;
                TestContext.Progress.WriteLine($"  {steps} steps: decay rate {rate:F3}/s ({rate / own - 1:+0.0%;-0.0%} against the operator's, " +
                    $"{rate / lambda - 1:+0.0%;-0.0%} against the explicit force's); amplitude {run.amplitude:F4} U against the two " +
                    $"stages' {twoStages:F4} U at the operator's rate ({run.amplitude / twoStages - 1:+0.0%;-0.0%}), exp's {exact:F4} U, " +
                    $"backward Euler's {euler:F4} U");
                Assert.That(run.rounds, Is.GreaterThan(0), "the step is beyond the explicit limit");
                Assert.That(Math.Abs(rate / own - 1.0), Is.LessThan(solveShare), "within the explicit force's difference");
                if (steps == 4)
                    Assert.That(Math.Abs(rate / own - 1.0), Is.LessThan(1.0 + Math.Log(euler) / (own * Seconds)), "nearer than backward Euler");
                Assert.That(run.momentum, Is.LessThan(1e-3), "free-slip walls take no momentum");
            }
        }

        /// <summary>The solve against the step it takes, in double precision on the CPU: Alexander's two stages
        /// (SphViscositySolve.hlsl) with gravity's kick v* - v_n as their forcing, each (I - h a) x = t solved by conjugate
        /// gradients with ReferenceSph's viscous acceleration a as the operator, in the mass-weighted inner product in which
        /// it is symmetric. A block of jittered water with a free surface and no-slip walls, random velocities, one
        /// prediction at ten times the explicit limit. The GPU's velocities must be the CPU's to within each stage's
        /// tolerance of its change, the first stage's error carried into the second's target dt / h - 1 times.</summary>
        [TestCase(false)]
        [TestCase(true)]
        public void ThePredictedVelocitiesAreTheTwoStageStepToItsTolerance(bool oilOnWater)
        {
            var settings = Weightless();
            settings.Gravity = new Vector3(0f, -9.81f, 0f);
            Assert.That(settings.VelocityDamping, Is.EqualTo(0f), "v* = v_n + g dt");
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
            var before = particles.ToDictionary(p => p.Id, p => new Double3(p.Velocity));
            float dt = (float)(10.0 * sim.TimeStep.ViscousTimeStep);
            sim.PredictVelocities(dt);
            var solved = new Particle[particles.Length];
            sim.Particles.GetData(solved);
            particles = solved; // the CPU's stages in the order the GPU's sort left
            var start = particles.Select(p => before[p.Id]).ToArray();
            var predicted = start.Select(v => v + new Double3(settings.Gravity) * dt).ToArray();

            var reference = new ReferenceSph(scene);
            var masses = particles.Select(p => (double)reference.PhaseTable[(int)p.Phase].ParticleMass).ToArray();
            double h = ImplicitViscosity.StageFraction * dt;
            var firstTarget = start.Select((v, i) => v + (predicted[i] - v) * (h / dt)).ToArray();
            var first = StageOnTheCpu(reference, particles, masses, firstTarget, h, settings.Gravity);
            var secondTarget = predicted.Select((v, i) => v + (first[i] - firstTarget[i]) * (dt / h - 1.0)).ToArray();
            var step = StageOnTheCpu(reference, particles, masses, secondTarget, h, settings.Gravity);

            double error = 0.0, change = 0.0, firstChange = 0.0, secondChange = 0.0;
            for (int i = 0; i < particles.Length; i++)
            {
                error += masses[i] * (new Double3(solved[i].Velocity) - step[i]).LengthSquared();
                change += masses[i] * (step[i] - predicted[i]).LengthSquared();
                firstChange += masses[i] * (first[i] - firstTarget[i]).LengthSquared();
                secondChange += masses[i] * (step[i] - secondTarget[i]).LengthSquared();
            }
            double relative = Math.Sqrt(error / change);
            double bound = ImplicitViscosity.Tolerance * ((dt / h - 1.0) * Math.Sqrt(firstChange) + Math.Sqrt(secondChange)) / Math.Sqrt(change);
            TestContext.Progress.WriteLine($"{particles.Length} particles, {dt / sim.TimeStep.ViscousTimeStep:F1} explicit limits, " +
                $"{sim.ViscositySolveRounds} rounds: the GPU's velocities are the CPU's two stages to {relative:E2} of the change " +
                $"(mass-weighted RMS; bound {bound:E2})");
            Assert.That(Math.Sqrt(change / masses.Sum()), Is.GreaterThan(0.005), "the viscosity changed the velocities");
            Assert.That(relative, Is.LessThan(bound));
        }

        /// <summary>x with (I - h a) x = target, a the CPU reference's viscous acceleration at the particles' places
        /// (its acceleration less gravity: linear in the velocities, with no tension and still walls), by conjugate gradients in the inner product
        /// sum m_i x_i . y_i, to 1e-6 of the target (the particles carry their velocities in single precision).</summary>
        static Double3[] StageOnTheCpu(ReferenceSph reference, Particle[] particles, double[] masses, Double3[] target, double h,
            Vector3 gravity)
        {
            int n = particles.Length;
            var moving = (Particle[])particles.Clone();
            Double3[] Apply(Double3[] x)
            {
                for (int i = 0; i < n; i++) moving[i].Velocity = x[i].ToVector3();
                var a = reference.Evaluate(moving, false).Acceleration;
                return x.Select((xi, i) => xi - (a[i] - new Double3(gravity)) * h).ToArray();
            }
            double Inner(Double3[] u, Double3[] w)
            {
                double sum = 0.0;
                for (int i = 0; i < n; i++) sum += masses[i] * Double3.Dot(u[i], w[i]);
                return sum;
            }
            var x = (Double3[])target.Clone();
            var applied = Apply(x);
            var r = target.Select((t, i) => t - applied[i]).ToArray();
            var p = (Double3[])r.Clone();
            double rr = Inner(r, r), stop = 1e-12 * Inner(target, target);
            for (int k = 0; k < 200 && rr > stop; k++)
            {
                var bp = Apply(p);
                double alpha = rr / Inner(p, bp);
                for (int i = 0; i < n; i++) { x[i] += p[i] * alpha; r[i] -= bp[i] * alpha; }
                double next = Inner(r, r);
                for (int i = 0; i < n; i++) p[i] = r[i] + p[i] * (next / rr);
                rr = next;
            }
            Assert.That(rr, Is.LessThanOrEqualTo(stop), "the CPU's conjugate gradients converged");
            return x;
        }

        /// <summary>A viscous liquid's flow that buoyancy drives: OilAndWater with its oil at 100 Pa s, whose explicit limit
        /// is 0.64 ms. Solved implicitly at the scene's own 4.17 ms steps, its kinetic energy at 0.1 s must stay near the
        /// explicit force's at 0.64 ms steps. With the viscosity solved before the constant-density solve instead, each
        /// step's pressure kick went undamped into the drift, a flow that viscosity holds ran 1 + lambda dt times its speed,
        /// and the fluid had 7.3 times the kinetic energy; with the two stages taking that kick before them instead of as
        /// their forcing, 2.6 times (SphViscositySolve.hlsl).</summary>
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
