using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Sorting;

namespace SphFluid.Tests.Runner
{
    /// <summary>Short headless runs of shipped scenes on the shared test device (lavapipe in CI).</summary>
    public sealed class SimulateRunTests
    {
        static SimulateRun Simulate(string scene, out StringWriter stdout, out StringWriter stderr, params string[] extra)
        {
            var args = new[] { RunnerPaths.Scene(scene) }.Concat(extra).ToArray();
            stdout = new StringWriter();
            stderr = new StringWriter();
            return new SimulateRun(SimulateOptions.Parse(args), stdout, stderr) { Device = GpuTestDevice.Shared, InteractiveProgress = false };
        }

        [Test]
        public void AShortRunWritesDiagnosticsSnapshotsAndASummary()
        {
            string outDir = RunnerPaths.ScratchFolder("simulate");
            var run = Simulate("PlayModeTest", out var stdout, out var stderr, "--seconds", "0.05", "--frames-every", "0.025", "--diagnostics-every", "0.025", "--out", outDir);

            int code = run.Execute();

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stdout + "\n" + stderr);
            string[] csv = File.ReadAllLines(Path.Combine(outDir, "diagnostics.csv"));
            Assert.That(csv[0], Does.StartWith("time_s,frame,substeps,dt_s,particles,total_mass_kg,kinetic_energy_J,max_speed_mps,nan_count,outside_count,water_count"));
            Assert.That(csv.Length, Is.GreaterThanOrEqualTo(3), "t = 0, 0.025 and 0.05 s");
            Assert.That(csv[1].Split(',')[4], Is.EqualTo("192"));
            Assert.That(File.Exists(Path.Combine(outDir, "frame_0000.png")), Is.True);
            Assert.That(File.Exists(Path.Combine(outDir, "frame_0001.png")), Is.True);
            byte[] png = File.ReadAllBytes(Path.Combine(outDir, "frame_0000.png"));
            var chunks = PngChunks.Read(png);
            foreach (var c in chunks) Assert.That(c.StoredCrc, Is.EqualTo(c.ComputedCrc), c.Type + " CRC");
            Assert.That(File.ReadAllText(Path.Combine(outDir, "summary.txt")), Does.Contain("result: ok"));
            Assert.That(stdout.ToString(), Does.Contain("plan: 1 phase, 0 obstacles"));
            Assert.That(stdout.ToString(), Does.Contain("device: "));
            var summary = run.Summary.OrFail("the run's summary");
            Assert.That(summary.Ok, Is.True);
            Assert.That(summary.SimulatedSeconds, Is.EqualTo(0.05).Within(1e-4));
            Assert.That(summary.Last.OrFail("the last diagnostics").TotalMass, Is.EqualTo(summary.First.OrFail("the first diagnostics").TotalMass), "mass exactly constant");
        }

        [Test]
        public void AMultiPhaseRunWritesTheLayeringFigure()
        {
            string outDir = RunnerPaths.ScratchFolder("layering");
            var run = Simulate("OilAndWater", out var stdout, out var stderr, "--steps", "2", "--particles-scale", "0.1", "--out", outDir, "--top-view");

            int code = run.Execute();

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stdout + "\n" + stderr);
            WrittenChart.Check(outDir, "layering", "Layering over time: OilAndWater", "simulated time (s)", "mean height above the floor (m)",
                "layering index", "Water mean height", "Oil mean height");
            Assert.That(File.Exists(Path.Combine(outDir, "top_0000.png")), Is.True);
            Assert.That(File.ReadAllLines(Path.Combine(outDir, "diagnostics.csv"))[0], Does.EndWith("oil_mean_height_m,oil_bottom_m,oil_top_m,oil_floor_share,oil_wall_share,layering_index,interface_tilt_m,surge_front_m,back_wall_column_m,potential_energy_J,clamp_hits,density_iterations,divergence_iterations,divergence_error_pct_per_s,density_solves_cut_off,divergence_solves_cut_off"));
            Assert.That(stdout.ToString(), Does.Contain("scaled x0.1"));
            Assert.That(run.Summary.OrFail("the run's summary").Frames, Is.EqualTo(2));
        }

        /// <summary>A DFSPH run whose solves run out of iterations is healthy, but holds its error above the tolerance it
        /// asked for: the summary gives the share of its time cut off, and above a tenth the run warns and says what to
        /// change. At the scene's own tolerance nothing is cut off and nothing is said.</summary>
        [Test]
        public void SolvesCutOffAreSummedAndWarnedOf()
        {
            string outDir = RunnerPaths.ScratchFolder("cut-off");
            var run = Simulate("OilAndWater", out var stdout, out var stderr, "--steps", "3", "--particles-scale", "0.1", "--solver", "dfsph",
                "--divergence-tolerance", "0.01", "--out", outDir);

            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok), stdout + "\n" + stderr);
            var summary = run.Summary.OrFail("the run's summary");
            Assert.That(summary.CutOffs.DivergenceShare, Is.GreaterThan(SolveCutOffs.WarningShare));
            Assert.That(File.ReadAllText(Path.Combine(outDir, "summary.txt")), Does.Contain("solves cut off at MaxSolverIterations: constant density in 0.0 % of the simulated time, divergence-free in "));
            Assert.That(stderr.ToString(), Does.Contain("simulate: warning: DFSPH's solves ran out of their 100 iterations (MaxSolverIterations) in "));
            Assert.That(stderr.ToString(), Does.Contain("a fluid that fills its closed container exactly cannot get below the tolerance"));

            run = Simulate("OilAndWater", out stdout, out stderr, "--steps", "3", "--particles-scale", "0.1", "--solver", "dfsph", "--out", outDir);

            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok), stdout + "\n" + stderr);
            summary = run.Summary.OrFail("the run's summary");
            Assert.That(summary.CutOffs.DensityShare, Is.EqualTo(0.0));
            Assert.That(summary.CutOffs.DivergenceShare, Is.EqualTo(0.0));
            Assert.That(stderr.ToString(), Does.Not.Contain("warning"));
        }

        /// <summary>--cpu-particles-scale scales the fluid only on a CPU device (the main job's half particles on lavapipe)
        /// and says so; on a GPU the scene runs as it is.</summary>
        [Test]
        public void TheCpuScaleAppliesOnlyOnACpuDeviceAndIsPrinted()
        {
            string outDir = RunnerPaths.ScratchFolder("cpu-scale");
            var run = Simulate("OilAndWater", out var stdout, out var stderr, "--steps", "1", "--cpu-particles-scale", "0.5", "--out", outDir);

            int code = run.Execute();

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stdout + "\n" + stderr);
            if (GpuTestDevice.Shared.DeviceType == "Cpu")
                Assert.That(stdout.ToString(), Does.Contain("particles: 2112 (scene: 4160, scaled x0.5 on a CPU device: --cpu-particles-scale)"));
            else
                Assert.That(stdout.ToString(), Does.Contain("particles: 4160 (spacing"));
        }

        /// <summary>The run prints its neighbour grid, whose cell count the README's 60 Hz figures cite: OilAndWater's 7 590
        /// cells of h/2 are past the 2 048 one ScanBlocks dispatch covers and within what ScanSmall does in one.</summary>
        [Test]
        public void TheRunPrintsItsGrid()
        {
            var run = Simulate("OilAndWater", out var stdout, out var stderr, "--steps", "1", "--cpu-particles-scale", "1",
                "--out", RunnerPaths.ScratchFolder("grid-line"));

            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok), stdout + "\n" + stderr);
            var grid = System.Text.RegularExpressions.Regex.Match(stdout.ToString(), @"^grid: 33 x 23 x 10 = (\d+) cells of 0\.02138 m \(h/2, 2 margin cells a side\)$",
                System.Text.RegularExpressions.RegexOptions.Multiline);
            Assert.That(grid.Success, Is.True, stdout.ToString());
            Assert.That(int.Parse(grid.Groups[1].Value), Is.EqualTo(7590).And.GreaterThan(PrefixSum.ElementsPerGroup).And.LessThanOrEqualTo(PrefixSum.SmallLength));
        }

        /// <summary>Unity lets a GameObject's name hold any character; named "\e[2J" the container cleared the terminal
        /// from the run's first line. The run prints and records such names escaped, and a phase's '|' does not part the
        /// summary's columns.</summary>
        [Test]
        public void AGameObjectNameHoldingAnEscapeSequenceIsPrintedEscaped()
        {
            string scene = RunnerPaths.EditedScene("PlayModeTest", ("m_Name: Container", "m_Name: \"Con\\e[2Jtainer\""), ("m_Name: Water", "m_Name: \"Wa\\rter\""),
                ("      Name: Water\n", "      Name: Wa|ter\n"));
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            string outDir = RunnerPaths.ScratchFolder("escaped-name");
            var run = new SimulateRun(SimulateOptions.Parse(new[] { scene, "--steps", "1", "--out", outDir }), stdout, stderr)
                { Device = GpuTestDevice.Shared, InteractiveProgress = false };

            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok), stdout + "\n" + stderr);
            Assert.That(stdout.ToString(), Does.Contain("container 'Con\\u001B[2Jtainer'"));
            string summary = File.ReadAllText(Path.Combine(outDir, "summary.txt"));
            Assert.That(summary, Does.Contain("\n  Wa\\|ter | "));
            Assert.That((stdout.ToString() + stderr + summary).Where(c => c != '\n' && !PrintableText.IsPrintable(c)), Is.Empty);
        }

        /// <summary>RestingTank runs WCSPH at Wendland C2's 2.85 spacings with DFSPH's relaxation left at the papers' full step,
        /// which DFSPH refuses there: --solver dfsph runs it at 2 spacings with the cubic spline and says why, instead of
        /// refusing the scene. OilAndWater's DFSPH settings (relaxed to 0.3) fit: it keeps its kernel and nothing is said.</summary>
        [Test]
        public void SolverDfsphFitsARefusedSupportAndSaysWhy()
        {
            var run = Simulate("RestingTank", out var stdout, out var stderr, "--steps", "1", "--particles-scale", "0.1", "--solver", "dfsph",
                "--out", RunnerPaths.ScratchFolder("dfsph-support"));

            int code = run.Execute();

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stdout + "\n" + stderr);
            Assert.That(stdout.ToString(), Does.Contain("simulate: DFSPH refuses the scene's WendlandC2 at 0.07125 m (FluidSettings: SolverRelaxation " +
                "must be in [0.05, 0.372046] (2 / lambda_max of the Dfsph solve's Jacobi step with WendlandC2 at 2.85 particle spacings: beyond it " +
                "the lattice's stiffest pressure wave grows) (was 1)): 0.05 m with the cubic spline instead"));
            Assert.That(stdout.ToString(), Does.Contain("solver: DFSPH"));

            run = Simulate("OilAndWater", out stdout, out stderr, "--steps", "1", "--particles-scale", "0.1", "--solver", "dfsph",
                "--out", RunnerPaths.ScratchFolder("dfsph-support"));
            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok), stdout + "\n" + stderr);
            Assert.That(stdout.ToString(), Does.Not.Contain("DFSPH refuses").And.Contain("relaxation 0.3"));
            // The printed diagnostics say how the solves went, as diagnostics.csv does.
            Assert.That(stdout.ToString(), Does.Match(@"\| DFSPH iterations density [0-9.]+ \([0-9]+ % cut off\) divergence [0-9.]+ \([0-9]+ % cut off\)"));
        }

        // The GPU figure is the sum of the sub-step's timed ranges. It once listed them by hand and missed the δ-SPH
        // DensityRate pass (a third of WCSPH's GPU time at 1M particles on an H200) and DFSPH's FindNeighbours.
        [TestCase("wcsph", "DensityRate")]
        [TestCase("dfsph", "FindNeighbours")]
        public void BenchGpuTimeCountsEverySubstepPass(string solver, string pass)
        {
            var bench = new BenchRun(BenchOptions.Parse(new[] { RunnerPaths.Scene("OilAndWater"), "--solver", solver, "--steps", "2", "--warmup", "1",
                "--warmup-seconds", "0", "--particles", "300", "--skip-savings", "--out", RunnerPaths.ScratchFolder("bench-" + solver) }), new StringWriter(), new StringWriter())
            {
                Device = GpuTestDevice.Shared,
            };

            Assert.That(bench.Execute(), Is.EqualTo(ExitCodes.Ok));
            var row = bench.Rows[0];
            Assert.That(row.PassMs.Keys, Does.Contain(pass));
            // Every timed pass the planner puts in this scene's sub-step is a column of the GPU figure.
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater")).Description;
            new SolverChoice { Solver = SolverChoice.Words[solver] }.ApplyTo(scene, "bench");
            var timed = PipelinePlanner.Plan(scene, false).SubstepPasses.Where(p => FluidSimulation.SampleNames.Contains(p)).ToList();
            Assert.That(timed, Does.Contain(pass));
            Assert.That(row.PassMs.Keys, Is.SupersetOf(timed));
            // A frame at a time too, DFSPH's wait for the last frame's motion (a submit of its own) notwithstanding.
            Assert.That(row.InFrameGpuMs, Is.GreaterThan(0).And.LessThan(double.PositiveInfinity), "the frame's GPU ms");
            Assert.That(row.InFramePassMs.Keys, Is.EquivalentTo(row.PassMs.Keys));
        }

        [Test]
        public void GrownPassesListTheLargestGrowthFirst_APassTheBaselineLacksFromZero()
        {
            static Dictionary<string, double> Passes(params (string Pass, double Ms)[] passes) => passes.ToDictionary(p => p.Pass, p => p.Ms);
            var baseline = Passes(("Forces", 1.0), ("Sort", 0.5), ("FindNeighbours", 2.0));
            var with = Passes(("Forces", 1.25), ("Sort", 0.25), ("FindNeighbours", 2.0), ("Normals", 0.75));

            Assert.That(BenchRun.GrownPasses(baseline, with), Is.EqualTo("Normals +0.750, Forces +0.250"));
            Assert.That(BenchRun.GrownPasses(baseline, with, 1), Is.EqualTo("Normals +0.750"));
            Assert.That(BenchRun.GrownPasses(with, baseline), Is.EqualTo("Sort +0.250"), "the passes that shrank, Normals to zero among them, are left out");
        }

        /// <summary>Each bench size and study configuration reads the scene, and each read scanned the project's every
        /// .meta twice: a bench of a thousand sizes, its last too fine to run, failed this test's deadline before it was
        /// refused. The file is read and checked once a run, and each size reads its own description of it.</summary>
        [Test]
        public void AThousandBenchSizesAreReadBeforeTheDeadline()
        {
            var sizes = Enumerable.Range(200, 999).Select(n => n.ToString(System.Globalization.CultureInfo.InvariantCulture));
            var bench = new BenchRun(BenchOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--skip-savings", "--out", RunnerPaths.ScratchFolder("bench-sizes"), "--particles" }
                .Concat(sizes).Append("16000000").ToArray()), new StringWriter(), new StringWriter()) { Device = GpuTestDevice.Shared };

            var thrown = Deadline.Within(10, () => Deadline.Thrown(() => bench.Execute()), "reading a thousand sizes");

            Assert.That(thrown, Is.InstanceOf<UsageException>());
            Assert.That(thrown!.Message, Does.StartWith("bench: --particles 16000000 is out of range for this scene"));
            Assert.That(bench.Rows, Is.Empty, "refused before the first row was measured");
        }

        [Test]
        public void BenchPrintsATableWithEveryPass()
        {
            var stdout = new StringWriter();
            string outDir = RunnerPaths.ScratchFolder("bench");
            var bench = new BenchRun(BenchOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--steps", "2", "--warmup", "1", "--particles", "150", "400",
                "--slower-gpus", "10", "--out", outDir }), stdout, new StringWriter())
            {
                Device = GpuTestDevice.Shared,
            };

            int code = bench.Execute();

            Assert.That(code, Is.EqualTo(ExitCodes.Ok));
            Assert.That(bench.Rows.Count, Is.EqualTo(2));
            Assert.That(bench.Rows[0].Particles, Is.EqualTo(150).Within(15));
            Assert.That(stdout.ToString(), Does.Contain("| particles | lanes | dt (ms) | wall ms | GPU ms | wall ms in a frame (sub-steps) | GPU ms in a frame | GPU ms per 60 Hz frame |"));
            Assert.That(stdout.ToString(), Does.Contain("| kernel | dispatches | ran | ms | ms a dispatch that ran | share |"));
            Assert.That(bench.Rows[^1].Kernels.All(k => k.Ran == k.Dispatches), Is.True, "under WCSPH every dispatch runs groups");
            foreach (var row in bench.Rows)
            {
                Assert.That(row.FrameSubsteps, Is.EqualTo((int)Math.Ceiling(1.0 / 60.0 / row.TimeStep)), "a 60 Hz frame's sub-steps");
                Assert.That(row.FrameWallMs, Is.GreaterThan(0).And.LessThan(double.PositiveInfinity));
                Assert.That(row.FrameGpuMs, Is.EqualTo(row.GpuMs * row.FrameSubsteps).Within(1e-9), "a 60 Hz frame's GPU ms");
                Assert.That(stdout.ToString(), Does.Contain(string.Format(System.Globalization.CultureInfo.InvariantCulture,
                    "| {0:F3} ({1}) | {2:F3} | {3:F3} |", row.FrameWallMs, row.FrameSubsteps, row.InFrameGpuMs, row.FrameGpuMs)), "the row's frame columns");
            }
            // A GPU ten times slower per particle fits no more particles in the same budget than this device.
            Assert.That(bench.DeviceFit, Is.Not.Null);
            Assert.That(bench.SlowerGpuFits, Has.Count.EqualTo(1));
            Assert.That(bench.SlowerGpuFits[0].Particles, Is.LessThanOrEqualTo(bench.DeviceFit!.Particles));
            Assert.That(stdout.ToString(), Does.Contain("60 Hz sizing (WCSPH)").And.Contain("- on a GPU 10 times slower per particle"));
            Assert.That(stdout.ToString(), Does.Contain($"| {bench.Rows[1].Particles} |"));
            // Each saving says where its time went, and the plan's row timed again after the forced ones says how far the
            // device drifted meanwhile: on an H200 the savings moved fivefold between sessions with neither printed.
            var tension = bench.Savings.Single(s => s.Forced == new PlanOverrides { SurfaceTension = true }.ToString());
            Assert.That(bench.Rows[^1].PassMs.Keys, Does.Not.Contain(PassNames.Normals), "the plan leaves the normals pass out");
            Assert.That(tension.WithEffect.PassMs.Keys, Does.Contain(PassNames.Normals), "forced tension runs it");
            Assert.That(bench.BaselineAgain, Is.Not.Null);
            Assert.That(bench.BaselineAgain!.PassMs.Keys, Is.EquivalentTo(bench.Rows[^1].PassMs.Keys), "the plan again runs the plan's passes");
            Assert.That(stdout.ToString(), Does.Contain("The plan again after the forced rows: ")
                .And.Contain("| wall ms saved in a frame | GPU ms saved in a frame | passes that grew (GPU ms) | passes that grew in a frame (GPU ms) |"));
            Assert.That(tension.FrameWallMsSaved, Is.EqualTo(tension.WithEffect.FrameWallMs - bench.Rows[^1].FrameWallMs).Within(1e-9));
            // A frame at a time the GPU's own figure too: on an H200 the forced rows cost 2.3 times the wall one sub-step a
            // submit that they cost a frame at a time, which the wall alone could not place.
            foreach (var row in bench.Rows.Append(tension.WithEffect))
            {
                Assert.That(row.InFrameGpuMs, Is.GreaterThan(0).And.LessThan(double.PositiveInfinity), "one submit a frame on lavapipe: timed");
                Assert.That(row.InFramePassMs.Keys, Is.EquivalentTo(row.PassMs.Keys), "the frame times the passes a sub-step times");
                Assert.That(row.InFrameGpuMs, Is.EqualTo(row.InFramePassMs.Values.Sum()).Within(1e-9));
            }
            Assert.That(tension.WithEffect.InFramePassMs[PassNames.Normals], Is.GreaterThan(0), "forced tension's normals pass, timed in a frame");
            Assert.That(tension.FrameGpuMsSaved, Is.EqualTo(tension.WithEffect.InFrameGpuMs - bench.Rows[^1].InFrameGpuMs).Within(1e-9));
            WrittenChart.Check(outDir, "bench-scaling", "Bench scaling: PlayModeTest, WCSPH", "particles", "milliseconds per sub-step (ms)",
                "wall clock per sub-step", "GPU per sub-step");
        }
    }
}
