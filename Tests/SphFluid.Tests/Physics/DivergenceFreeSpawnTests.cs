using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// A DFSPH spawn settled by moving its particles, not by kicking them (FluidSimulation.SettledSpawn). The spawn's jitter
    /// packs some particles above rest density (OilAndWater: 0.38 % on average, 3.08 % at most), and the first
    /// constant-density solve removed that within one sub-step, so the velocity it left went as one over the step. At the
    /// 0.64 ms steps that oil of 100 Pa s asks for (ViscousStepLimit), OilAndWater's fluid had 0.31 J of kinetic energy
    /// and a fastest particle at 1.03 m/s at 0.05 s, 70 times the kinetic energy of its own 4.17 ms steps; the fluid rose
    /// (1.39 J of potential energy) and stood 7.3 % expanded. A fluid let go at rest can only turn potential energy into
    /// kinetic energy and heat, so its mechanical energy must not rise, and the step must not decide how it starts.
    /// </summary>
    public sealed class DivergenceFreeSpawnTests
    {
        const float Frame = 1f / 60f;
        const float ShortStep = 0.00064f;

        static FluidSceneDescription OilAndWater(string path)
        {
            var scene = SceneLoader.Load(path, RunnerPaths.Project).Description;
            Assert.That(new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH OilAndWater"), Is.Null);
            return scene;
        }

        /// <summary>The spawn's average and greatest compression and its mechanical energy, and, once whole frames have run
        /// past <paramref name="seconds"/> (one at least), the kinetic energy, the fastest particle and the mechanical energy.</summary>
        static (double compression, double spawnEnergy, double kinetic, float fastest, double energy, float step, double time)
            Start(FluidSceneDescription scene, double seconds)
        {
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            var gravity = scene.Settings.Gravity;
            double spawnEnergy = FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity);
            var spawn = sim.ReadDiagnostics().Phases;
            double compression = spawn.Max(p => p.AverageDensityError), mostCompressed = spawn.Max(p => p.MaxDensityError);
            do sim.Step(Frame);
            while (sim.SimulatedTime < seconds - 1e-6);
            var report = sim.ReadDiagnostics();
            sim.Particles.GetData(particles);
            double energy = FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity);
            TestContext.Progress.WriteLine($"DFSPH OilAndWater, steps of {1000 * sim.LastStep.TimeStep:F4} ms: spawn compressed " +
                $"{100 * compression:F3} % on average and {100 * mostCompressed:F3} % at most, {spawnEnergy:F5} J; at " +
                $"{1000 * sim.SimulatedTime:F2} ms kinetic {report.KineticEnergy:F6} J, fastest {report.MaxSpeed:F4} m/s, mechanical " +
                $"{energy:F5} J ({energy - spawnEnergy:+0.00000;-0.00000} J)");
            return (compression, spawnEnergy, report.KineticEnergy, report.MaxSpeed, energy, sim.LastStep.TimeStep, sim.SimulatedTime);
        }

        [Test]
        public void AShortStepDoesNotKickTheSpawn()
        {
            var scene = OilAndWater(RunnerPaths.Scene("OilAndWater"));
            var own = Start(scene, 0.05);
            var shortScene = OilAndWater(RunnerPaths.EditedScene("OilAndWater", "MaxTimeStep: 0.005\n", $"MaxTimeStep: {ShortStep}\n"));
            var shortSteps = Start(shortScene, 0.05);

            Assert.That(shortSteps.step, Is.LessThanOrEqualTo(ShortStep), "the edited scene runs the short step");
            Assert.That(own.step, Is.GreaterThan(5 * ShortStep), "the scene's own step is the long one");
            // Settled below a quarter of the solve's tolerance (the jittered spawn: 0.38 %).
            Assert.That(own.compression, Is.LessThanOrEqualTo(0.25 * 0.01 * scene.Settings.DensityTolerance));
            Assert.That(shortSteps.kinetic, Is.LessThanOrEqualTo(2.0 * own.kinetic), "the kick does not grow as the step shrinks");
            foreach (var run in new[] { own, shortSteps })
                Assert.That(run.energy - run.spawnEnergy, Is.LessThanOrEqualTo(0.0), "no work is done on a fluid let go at rest");
        }

        /// <summary>
        /// Far below the scene's step the settling's own leftover is a kick: at 0.039 ms (MaxTimeStep allows down to
        /// 0.01 ms) two settling solves left OilAndWater 0.26 % compressed at most, and its first 1.25 ms took 0.85 J of
        /// kinetic energy, its fastest particle at 0.895 m/s, and raised the fluid, which then boiled (both liquids 4 %
        /// expanded at 0.1 s). The settling now goes on while that leftover would kick the first step harder than gravity
        /// does, whether MaxTimeStep or the CFL condition (the gravity wave's, at a Courant number of 0.01) makes that step
        /// short. From rest, over the first frame (32 sub-steps), the fluid's mechanical energy must not rise, and
        /// no particle may outrun free fall, g t: the only pressure that could push one harder is the interface's, which
        /// drives the lock exchange at a tenth of g.
        /// </summary>
        [TestCase("MaxTimeStep: 0.005", "MaxTimeStep: 0.0000390625", 0.0000391f)]
        [TestCase("CflNumber: 0.3", "CflNumber: 0.01", 0.00032f)]
        public void AStepFarBelowTheScenesStartsAtRest(string line, string edited, float shortStep)
        {
            var scene = OilAndWater(RunnerPaths.EditedScene("OilAndWater", line + "\n", edited + "\n"));
            var firstFrame = Start(scene, 0.0);

            Assert.That(firstFrame.step, Is.LessThanOrEqualTo(shortStep), "the edited scene runs the short step");
            Assert.That(firstFrame.energy - firstFrame.spawnEnergy, Is.LessThanOrEqualTo(0.0), "no work is done on a fluid let go at rest");
            Assert.That(firstFrame.fastest, Is.LessThanOrEqualTo(scene.Settings.Gravity.Length() * firstFrame.time), "no particle outruns free fall");
        }

        /// <summary>
        /// Without gravity the settling's bound from gravity, g dt² / s, is zero, so whatever compression the solves left
        /// ran all twenty of them at construction, each up to MaxSolverIterations rounds and a blocking read-back. A kick
        /// within what the divergence-free solve tolerates at every step, a density change of its tolerance over the step,
        /// moves a particle at most that tolerance times the spacing a second, which the solve would allow the fluid
        /// anyway, so the settling stops there too. A weightless jittered block must settle in fewer solves than the cap
        /// and start at rest: over the first frame no particle faster than the divergence-free tolerance times the spacing.
        /// </summary>
        [Test]
        public void AWeightlessSpawnSettlesWithinTheDivergenceFreeTolerance()
        {
            var settings = SolverScenes.Coarse(0.04f);
            settings.PressureSolver = PressureSolver.Dfsph;
            settings.Gravity = Vector3.Zero;
            var water = SolverScenes.Box("Water", SolverScenes.Water(), Vector3.Zero, new Vector3(0.4f), jitter: 0.25f);
            var scene = SolverScenes.Scene(settings, new Vector3(0.8f), water);

            var device = new DriftCountingDevice(GpuTestDevice.Unvalidated);
            using var sim = new FluidSimulation(device, scene);
            int settlingSolves = device.Drifts; // each settling solve ends in one drift; nothing else drifts before a step
            sim.Step(Frame);
            var report = sim.ReadDiagnostics();
            float kick = 0.01f * settings.DivergenceTolerance * settings.ParticleSpacing;
            TestContext.Progress.WriteLine($"weightless DFSPH block of {sim.ParticleCount} particles: settled in {settlingSolves} " +
                $"solves; after {1000 * sim.SimulatedTime:F2} ms the fastest particle {1000 * report.MaxSpeed:F3} mm/s " +
                $"(the tolerance's {1000 * kick:F3} mm/s), the most compressed {100 * report.Phases.Max(p => p.MaxDensityError):F4} %");

            Assert.That(settlingSolves, Is.LessThan(20), "the settling stops before its cap");
            Assert.That(report.MaxSpeed, Is.LessThanOrEqualTo(kick), "the spawn starts at rest, within the solve's tolerance");
        }

        /// <summary>Forwards to a real device and counts the solver program's Drift dispatches.</summary>
        sealed class DriftCountingDevice : ForwardingDevice
        {
            public DriftCountingDevice(IComputeDevice inner) : base(inner) { }

            public int Drifts { get; private set; }

            public override void Dispatch(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ)
            {
                if (program.Name.Contains(FluidSimulation.SolverProgramName) && kernel == program.FindKernel("Drift")) Drifts++;
                Inner.Dispatch(program, kernel, groupsX, groupsY, groupsZ);
            }
        }

        /// <summary>Settling moves particles and nothing else: every particle is kept, with its phase and its box's velocity,
        /// and none moves further than its jitter displaced it from the lattice.</summary>
        [Test]
        public void SettlingKeepsEveryParticleItsPhaseAndItsBoxVelocity()
        {
            var settings = SolverScenes.Coarse(0.04f);
            settings.PressureSolver = PressureSolver.Dfsph;
            const float jitter = 0.25f;
            var water = SolverScenes.Box("Water", SolverScenes.Water(), new Vector3(-0.1f, 0f, 0f), new Vector3(0.4f), jitter: jitter);
            water.InitialVelocity = new Vector3(0.5f, 0f, 0f);
            var oil = SolverScenes.Box("Oil", SolverScenes.Oil(), new Vector3(0.3f, 0f, 0f), new Vector3(0.32f, 0.4f, 0.4f), seed: 2, jitter: jitter);
            oil.InitialVelocity = new Vector3(0f, 0f, -0.25f);
            var scene = SolverScenes.Scene(settings, new Vector3(1.2f, 0.8f, 0.8f), water, oil);
            var spawn = SpawnLayout.Generate(scene);

            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            Assert.That(particles.Select(p => p.Id).OrderBy(id => id), Is.EqualTo(Enumerable.Range(0, spawn.Length).Select(i => (uint)i)));
            double furthest = 0.0;
            foreach (var p in particles)
            {
                var born = spawn[p.Id];
                Assert.That(p.Phase, Is.EqualTo(born.Phase));
                Assert.That(p.Velocity, Is.EqualTo(born.Velocity));
                furthest = Math.Max(furthest, (p.Position - born.Position).Length());
            }
            TestContext.Progress.WriteLine($"settled {particles.Length} particles: the furthest moved {furthest / settings.ParticleSpacing:F3} spacings");
            Assert.That(furthest, Is.GreaterThan(0.0), "settling moved the jittered spawn");
            Assert.That(furthest, Is.LessThanOrEqualTo(jitter * Math.Sqrt(3.0) * settings.ParticleSpacing));
        }
    }
}
