using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// The planner: each effect that is off dispatches none of its kernels. Every dispatch is recorded with the kernel's
    /// name and the keywords enabled at that moment; a scene needing nothing runs no variant, no normals pass and, once its
    /// container is placed, no wall placement. Each effect forced on (PlanOverrides, the benchmark's switch) shows up in the
    /// same count, so the counter is seen to catch what it is asked about.
    /// </summary>
    public sealed class PlannerDispatchTests
    {
        sealed class Dispatch
        {
            public readonly string Kernel;
            public readonly HashSet<string> Keywords;

            public Dispatch(string kernel, HashSet<string> keywords)
            {
                Kernel = kernel;
                Keywords = keywords;
            }
        }

        /// <summary>Forwards to the shared device and records each dispatch of the solver program.</summary>
        sealed class DispatchCountingDevice : ForwardingDevice
        {
            readonly Dictionary<IComputeProgram, HashSet<string>> _keywords = new Dictionary<IComputeProgram, HashSet<string>>();
            readonly Dictionary<(IComputeProgram, int), string> _names = new Dictionary<(IComputeProgram, int), string>();

            public DispatchCountingDevice(IComputeDevice inner) : base(inner) { }

            public List<Dispatch> Dispatches { get; } = new List<Dispatch>();

            public override IComputeProgram LoadProgram(string name)
            {
                var program = Inner.LoadProgram(name);
                _keywords[program] = new HashSet<string>();
                return program;
            }

            public override void SetKeyword(IComputeProgram program, string keyword, bool enabled)
            {
                if (enabled) _keywords[program].Add(keyword);
                else _keywords[program].Remove(keyword);
                Inner.SetKeyword(program, keyword, enabled);
            }

            public override void Dispatch(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ)
            {
                Record(program, kernel);
                Inner.Dispatch(program, kernel, groupsX, groupsY, groupsZ);
            }

            public override void DispatchIndirect(IComputeProgram program, int kernel, IComputeBuffer arguments, int byteOffset)
            {
                Record(program, kernel);
                Inner.DispatchIndirect(program, kernel, arguments, byteOffset);
            }

            void Record(IComputeProgram program, int kernel)
            {
                if (program.Name.Contains(FluidSimulation.SolverProgramName))
                    Dispatches.Add(new Dispatch(NameOf(program, kernel), new HashSet<string>(_keywords[program])));
            }

            string NameOf(IComputeProgram program, int kernel)
            {
                if (_names.Count == 0 || !_names.Keys.Any(k => k.Item1 == program))
                    foreach (string name in new[] { "HalfStep", "PlaceBoundary", "DensityPressure", "WallPressure", "Normals", "Rotations", "Forces", "FullStep",
                                                      "FindNeighbours", "DensityRate", "BeginDensitySolve", "BeginDivergenceSolve",
                                                      "DensitySolveError", "DivergenceSolveError", "BoundarySolveError",
                                                      "ApplyStiffness" })
                        _names[(program, program.FindKernel(name))] = name;
                return _names.TryGetValue((program, kernel), out string? known) ? known : "kernel " + kernel;
            }
        }

        /// <summary>The small shipped tank with XSPH off: one phase, no tension, no XSPH, no obstacles, a container at rest.</summary>
        static FluidSceneDescription PlainScene(ViscousStress stress = ViscousStress.Laplacian)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("PlayModeTest")).Description;
            var settings = scene.Settings.Clone();
            settings.XsphEpsilon = 0f;
            settings.ViscousStress = stress;
            scene.Settings = settings;
            return scene;
        }

        /// <summary>The dispatches of frames after the first (the first places the container's walls once).</summary>
        static List<Dispatch> LaterFrames(PlanOverrides? forced, ViscousStress stress = ViscousStress.Laplacian)
        {
            var device = new DispatchCountingDevice(GpuTestDevice.Shared);
            using (var sim = new FluidSimulation(device, PlainScene(stress)) { ForcedEffects = forced })
            {
                sim.StepFixed(1, 1e-4f);
                device.Dispatches.Clear();
                sim.StepFixed(2, 1e-4f);
                sim.StepFixed(2, 1e-4f);
            }
            return device.Dispatches;
        }

        [Test]
        public void EachEffectThatIsOffDispatchesNoneOfItsKernels()
        {
            var plan = PipelinePlanner.Plan(PlainScene(), false);
            Assert.That(plan.Keywords, Is.Empty, plan.ToString());

            var dispatches = LaterFrames(null);

            Assert.That(dispatches.Count, Is.GreaterThan(0));
            foreach (string keyword in SolverKeywords.All)
                Assert.That(dispatches.Count(d => d.Keywords.Contains(keyword)), Is.EqualTo(0), keyword + " variant dispatched");
            Assert.That(dispatches.Count(d => d.Kernel == "Normals"), Is.EqualTo(0), "normals pass without surface tension");
            Assert.That(dispatches.Count(d => d.Kernel == "Rotations"), Is.EqualTo(0), "rotations pass under the Laplacian viscous stress");
            Assert.That(dispatches.Count(d => d.Kernel == "PlaceBoundary"), Is.EqualTo(0), "walls placed again for a container at rest");
            Assert.That(dispatches.Count(d => d.Kernel == "Forces"), Is.EqualTo(4), "one force pass per sub-step");
        }

        /// <summary>WCSPH's neighbour lists (NeighbourCapacity.InUse): in one lane they are found once after each sort, and
        /// again before delta-SPH's rate only when a shift moved the particles since; with lanes the passes walk the grid
        /// and nothing searches. The plan lists the search exactly when it runs, so the bench's GPU time counts it.</summary>
        [TestCase(1, false, false, 4)]
        [TestCase(1, true, false, 4)]
        [TestCase(1, true, true, 8)]
        [TestCase(8, false, false, 0)]
        [TestCase(8, true, true, 0)]
        public void WcsphSearchesOncePerSortInOneLaneAndNeverWithLanes(int lanes, bool deltaSph, bool shifting, int searches)
        {
            var scene = PlainScene();
            scene.Settings.WcsphDensity = deltaSph ? WcsphDensity.DeltaSph : WcsphDensity.Summation;
            scene.Settings.ParticleShifting = shifting ? 2f : 0f;
            var device = new DispatchCountingDevice(GpuTestDevice.Shared);
            using (var sim = new FluidSimulation(device, scene) { LanesPerParticle = lanes })
            {
                sim.StepFixed(1, 1e-4f);
                device.Dispatches.Clear();
                sim.StepFixed(2, 1e-4f);
                sim.StepFixed(2, 1e-4f);
                Assert.That(sim.ReadsNeighbourLists, Is.EqualTo(lanes == 1));
                Assert.That(sim.Plan.SubstepPasses, lanes == 1 ? Does.Contain(PassNames.FindNeighbours) : Does.Not.Contain(PassNames.FindNeighbours));
            }
            var dispatches = device.Dispatches;
            Assert.That(dispatches.Count(d => d.Kernel == "Forces"), Is.EqualTo(4), "one force pass per sub-step");
            Assert.That(dispatches.Count(d => d.Kernel == "DensityRate"), Is.EqualTo(deltaSph ? 4 : 0));
            Assert.That(dispatches.Count(d => d.Kernel == "FindNeighbours"), Is.EqualTo(searches));
        }

        [Test]
        public void TheStrainRatesStressDispatchesOneRotationsPassPerSubStep()
        {
            var dispatches = LaterFrames(null, ViscousStress.StrainRate);
            Assert.That(dispatches.Count(d => d.Kernel == "Rotations"), Is.EqualTo(4));
            Assert.That(dispatches.Count(d => d.Kernel == "Forces"), Is.EqualTo(4));
        }

        /// <summary>A DFSPH solve opens in one dispatch and its round is three: the fluid's error pass, the walls' (whose last
        /// group folds the round's errors and stops the solve, FoldSolveErrors) and the correction. The round was four, with
        /// the fold a dispatch of its own between the walls' pass and the correction, and the opening two, with the walls'
        /// warm start a dispatch of its own, run empty in the divergence-free solve; each dispatch fewer is one barrier
        /// fewer, which a small scene's sub-step, made mostly of solves, pays for on a GPU ("Real time at 60 Hz" in the
        /// README).</summary>
        [Test]
        public void ADfsphSolveOpensInOneDispatchAndItsRoundIsThree()
        {
            var scene = PlainScene();
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            var device = new DispatchCountingDevice(GpuTestDevice.Shared);
            using (var sim = new FluidSimulation(device, scene))
            {
                sim.StepFixed(1, 1e-3f);
                device.Dispatches.Clear();
                sim.StepFixed(1, 1e-3f);
            }
            var names = device.Dispatches.Select(d => d.Kernel).ToList();
            string[] solves = { "BeginDensitySolve", "BeginDivergenceSolve" };
            string[] errorPasses = { "DensitySolveError", "DivergenceSolveError" };
            string[] solveKernels = errorPasses.Concat(new[] { "BoundarySolveError", "ApplyStiffness" }).ToArray();
            for (int solve = 0; solve < 2; solve++)
            {
                int begin = names.IndexOf(solves[solve]);
                Assert.That(begin, Is.GreaterThanOrEqualTo(0), solves[solve] + " recorded");
                Assert.That(names.Skip(begin + 1).Take(1), Is.EqualTo(new[] { "ApplyStiffness" }), "the warm start's correction, right after the opening");
                var round = new[] { errorPasses[solve], "BoundarySolveError", "ApplyStiffness" };
                int at = begin + 2, rounds = 0;
                for (; at < names.Count && names[at] == errorPasses[solve]; at += 3, rounds++)
                    Assert.That(names.Skip(at).Take(3), Is.EqualTo(round), $"{solves[solve]}'s round {rounds}");
                Assert.That(rounds, Is.GreaterThanOrEqualTo(3), "rounds recorded (SolveBudget: never fewer than three)");
                Assert.That(solveKernels, Does.Not.Contain(at < names.Count ? names[at] : ""), "the dispatch after the solve's last round");
            }
        }

        [TestCase("multiphase")]
        [TestCase("tension")]
        [TestCase("xsph")]
        [TestCase("obstacles")]
        [TestCase("container")]
        public void EachEffectForcedOnIsCounted(string effect)
        {
            var forced = new PlanOverrides
            {
                Multiphase = effect == "multiphase", SurfaceTension = effect == "tension", Xsph = effect == "xsph",
                Obstacles = effect == "obstacles", ContainerMoving = effect == "container",
            };

            var dispatches = LaterFrames(forced);

            switch (effect)
            {
                case "multiphase": Assert.That(dispatches.Count(d => d.Kernel == "Forces" && d.Keywords.Contains(SolverKeywords.Multiphase)), Is.EqualTo(4)); break;
                case "tension":
                    Assert.That(dispatches.Count(d => d.Kernel == "Normals"), Is.EqualTo(4));
                    Assert.That(dispatches.Count(d => d.Kernel == "Forces" && d.Keywords.Contains(SolverKeywords.SurfaceTension)), Is.EqualTo(4));
                    break;
                case "xsph": Assert.That(dispatches.Count(d => d.Kernel == "Forces" && d.Keywords.Contains(SolverKeywords.Xsph)), Is.EqualTo(4)); break;
                case "obstacles": Assert.That(dispatches.Count(d => d.Keywords.Contains(SolverKeywords.Obstacles)), Is.GreaterThanOrEqualTo(4)); break;
                default: Assert.That(dispatches.Count(d => d.Kernel == "PlaceBoundary"), Is.EqualTo(2), "once per frame"); break;
            }
        }
    }
}
