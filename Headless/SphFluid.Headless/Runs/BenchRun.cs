using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using SphFluid.Compute;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Output;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Vulkan;

namespace SphFluid.Headless.Runs;

/// <summary>
/// <c>sphfluid bench</c>: runs single sub-steps of a fixed stable dt (one submit each, so every GPU timing
/// range belongs to exactly one sub-step) and reports mean wall-clock and GPU milliseconds per sub-step
/// and per pass, then per kernel from the backend's per-dispatch timestamps.
/// </summary>
public sealed class BenchRun(BenchOptions options, TextWriter stdout, TextWriter stderr)
{
    static readonly CultureInfo C = CultureInfo.InvariantCulture;
    /// <summary>The timed ranges a sub-step's GPU time sums: every range the simulation records except the frame's
    /// read-back passes. Read from <see cref="FluidSimulation.SampleNames"/> so that a new pass (DensityRate,
    /// FindNeighbours were once left out here, and the GPU figure missed them) is counted without a second list.</summary>
    static readonly string[] Passes = FluidSimulation.SampleNames
        .Where(p => p != PassNames.MotionReduction && p != PassNames.Diagnostics).ToArray();

    /// <summary>A device to use instead of opening one (tests share theirs); not disposed here. Null: the run opens its own.</summary>
    public IComputeDevice? Device { get; init; }

    /// <param name="FrameWallMs">Wall ms per sub-step when a 60 Hz frame's sub-steps are recorded and submitted
    /// together, as the simulation steps a frame: the host cost of a submit and wait is shared by the frame.</param>
    /// <param name="FrameSubsteps">Sub-steps of dt in one 60 Hz frame.</param>
    /// <param name="Kernels">Per kernel, a sub-step: the dispatches recorded, those of them that ran groups (DFSPH's solves
    /// record rounds they may not need, <see cref="SolveBudget.DispatchesThatRun"/>) and their milliseconds.</param>
    /// <param name="Solves">DFSPH: the diagnostics of the timed sub-steps, whose solves' mean corrections and cut-off shares
    /// say which dispatches ran; null under WCSPH.</param>
    /// <param name="InFrameGpuMs">GPU ms per sub-step when a 60 Hz frame's sub-steps are recorded together: the pass
    /// ranges of the frames' submits over their sub-steps. NaN where a frame's recording was split over submits (its
    /// ranges open across a split go untimed) or the device is not Vulkan. On an H200 a forced effect's row cost 2.3
    /// times the wall one sub-step a submit that it cost a frame at a time, and only the GPU's own figure for each can
    /// tell which measure holds the extra work.</param>
    /// <param name="InFramePassMs">Per pass, the GPU ms a sub-step of <paramref name="InFrameGpuMs"/>; empty where it is NaN.</param>
    public sealed record Row(int Particles, string Plan, double WallMs, double GpuMs, IReadOnlyDictionary<string, double> PassMs,
        IReadOnlyList<(string Kernel, int Dispatches, double Ran, double Ms)> Kernels, float TimeStep, bool Finite, double FrameWallMs, int FrameSubsteps, int Lanes,
        DiagnosticsReport? Solves, double InFrameGpuMs, IReadOnlyDictionary<string, double> InFramePassMs)
    {
        /// <summary>GPU ms a 60 Hz frame costs: the sub-step's GPU time times the frame's sub-steps.</summary>
        public double FrameGpuMs => GpuMs * FrameSubsteps;
    }

    public List<Row> Rows { get; } = new();

    /// <summary>What --solver changed besides the solver (<see cref="SolverChoice.FitSupport"/>), printed with the plan.</summary>
    string? _solverNote;

    /// <summary>The solver the rows ran (the scene's, or --solver's).</summary>
    string SolverName { get; set; } = "WCSPH";

    public int Execute()
    {
        var scene = Load();
        // Every requested count is turned into a scene before the device opens, so an impossible one is refused
        // (exit 2, naming --particles) without measuring the others first.
        var descriptions = options.Particles.Count > 0 ? options.Particles.Select(n => ScaledTo(n)).ToList()
            : options.ParticleScales.Count > 0 ? options.ParticleScales.Select(f => ScaledBy(f)).ToList()
            : new List<FluidSceneDescription> { ScaledBy(1) };
        using var output = OutputFolder.Claim(options.OutputDirectory ?? Path.Combine("Output", scene.Name + "-bench"), "--out", "bench");
        IComputeDevice device = DeviceFactory.GivenOrOpen(Device, scene.PackageFolder, options.DeviceName, "bench", stderr, out IDisposable? owned);
        try
        {
            stdout.WriteLine(string.Format(C, "bench: {0} on {1}; {2} warm-up sub-steps (at least {3:G3} s) + {4} timed sub-steps per row, one submit each",
                scene.Path, DeviceFactory.Describe(device), options.Warmup, options.WarmupSeconds, options.Steps));
            stdout.WriteLine(SolverChoice.Describe(descriptions[0].Settings));
            if (_solverNote != null) stdout.WriteLine(_solverNote);
            if (descriptions.Select(FreeVolume.Warning).FirstOrDefault(w => w != null) is string crowded)
                stderr.WriteLine($"bench: warning: {crowded}");
            if (_scene?.UnreadProblems is string unread) stderr.WriteLine($"bench: warning: {unread}");
            SolverName = SolverChoice.ShortName(descriptions[0].Settings.PressureSolver);
            for (int i = 0; i < descriptions.Count; i++)
            {
                var (option, value) = SizeArgument(i);
                SceneFit.RequireDevice(descriptions[i], device, "bench", scene.Path, option, value);
            }
            WarmUpProcess(descriptions[0], device);
            foreach (var description in descriptions)
            {
                using var sim = new FluidSimulation(device, description);
                var row = Measure(sim, device);
                Rows.Add(row);
                stderr.WriteLine(string.Format(C, "bench: {0} particles: {1:F3} ms/sub-step wall, {2:F3} ms GPU", row.Particles, row.WallMs, row.GpuMs));
            }
            stdout.Write(Table(scene.Name, DeviceFactory.Describe(device)));
            stdout.Write(SizingText());
            if (!options.SkipSavings) MeasureSavings(descriptions[^1], device);
            stdout.Write(SavingsTable());
            BenchScalingChart.Build(scene.Name, device.DeviceName, SolverName, Rows.Select(r => (r.Particles, r.WallMs, r.GpuMs)).ToList())
                .Save(output, BenchScalingChart.Stem);
            stdout.WriteLine();
            stdout.WriteLine($"chart: {Path.GetFullPath(output.PathOf(BenchScalingChart.Stem + ".png"))} (and .svg)");
            return Rows.All(r => r.Finite) ? ExitCodes.Ok : ExitCodes.SimulationFailed;
        }
        finally
        {
            owned?.Dispose();
        }
    }

    /// <summary>What one planner decision saves: the same scene with that effect forced on, against the plan's own run.</summary>
    /// <param name="FrameWallMsSaved">The wall ms a sub-step saves when a 60 Hz frame's sub-steps are recorded together, as a
    /// running scene steps them: an effect whose work comes once a frame (a moving container's walls placed at its start)
    /// costs every sub-step of the one-sub-step rows, and only a frame's first here.</param>
    /// <param name="FrameGpuMsSaved">The GPU ms a sub-step saves a frame at a time (<see cref="Row.InFrameGpuMs"/>); NaN where
    /// either row has none.</param>
    public sealed record Saving(string Decision, string Forced, Row WithEffect, double WallMsSaved, double GpuMsSaved, double FrameWallMsSaved,
        double FrameGpuMsSaved);

    public List<Saving> Savings { get; } = new();

    /// <summary>The plan's own row timed again after the forced rows (null until then): how far the device drifted
    /// while they ran, which a saving cannot tell from the effect's cost.</summary>
    public Row? BaselineAgain { get; private set; }

    /// <summary>Each effect the planner left out of this scene, forced on in turn (<see cref="PlanOverrides"/>), timed as
    /// the rows are; the difference to the last row is what leaving it out saves per sub-step.</summary>
    void MeasureSavings(FluidSceneDescription description, IComputeDevice device)
    {
        var baseline = Rows[^1];
        var plan = PipelinePlanner.Plan(description, false);
        var decisions = new List<(string Decision, bool Off, PlanOverrides Forced)>
        {
            ("one phase: no MULTIPHASE variant", !plan.Multiphase, new PlanOverrides { Multiphase = true }),
            ("no surface tension: no normals pass, no SURFACE_TENSION variant", !plan.SurfaceTension, new PlanOverrides { SurfaceTension = true }),
            ("no XSPH: no XSPH variant", !plan.Xsph, new PlanOverrides { Xsph = true }),
            ("no obstacles: no OBSTACLES variant", !plan.Obstacles, new PlanOverrides { Obstacles = true }),
            ("container at rest: no transform upload, no wall re-placement", true, new PlanOverrides { ContainerMoving = true }),
        };
        foreach (var (decision, off, forced) in decisions)
        {
            if (!off) continue;
            using var sim = new FluidSimulation(device, description) { ForcedEffects = forced };
            var row = Measure(sim, device);
            Savings.Add(new Saving(decision, forced.ToString(), row, row.WallMs - baseline.WallMs, row.GpuMs - baseline.GpuMs,
                row.FrameWallMs - baseline.FrameWallMs, row.InFrameGpuMs - baseline.InFrameGpuMs));
            stderr.WriteLine(string.Format(C, "bench: {0} forced on: {1:F3} ms/sub-step wall, {2:F3} ms GPU", forced, row.WallMs, row.GpuMs));
        }
        if (Savings.Count == 0) return;
        // On an H200 at 1M particles the savings moved by up to five times between sessions (obstacles 6.50, 0.78 and
        // 4.36 ms) with nothing timed to tell drift from cost: the plan's row again after the forced ones shows the drift.
        using var again = new FluidSimulation(device, description);
        BaselineAgain = Measure(again, device);
        stderr.WriteLine(string.Format(C, "bench: the plan again: {0:F3} ms/sub-step wall, {1:F3} ms GPU", BaselineAgain.WallMs, BaselineAgain.GpuMs));
    }

    /// <summary>The passes whose GPU time grew most from <paramref name="baseline"/> to <paramref name="with"/>, largest
    /// first, at most <paramref name="count"/>, as "Pass +ms" (a pass the baseline does not run counts from zero).</summary>
    public static string GrownPasses(IReadOnlyDictionary<string, double> baseline, IReadOnlyDictionary<string, double> with, int count = 3) =>
        string.Join(", ", with.Keys.Union(baseline.Keys)
            .Select(p => (Pass: p, Grew: with.GetValueOrDefault(p) - baseline.GetValueOrDefault(p)))
            .Where(d => d.Grew > 0).OrderByDescending(d => d.Grew).Take(count)
            .Select(d => string.Format(C, "{0} +{1:F3}", d.Pass, d.Grew)));

    /// <summary>The planner's savings as a Markdown table (empty without measurements).</summary>
    public string SavingsTable()
    {
        if (Savings.Count == 0) return "";
        var b = new StringBuilder();
        var baseline = Rows[^1];
        b.AppendLine();
        b.AppendLine(string.Format(C, "Planner savings at {0} particles: ms per sub-step the scene's plan saves against the same scene with the effect forced on "
            + "(plan as planned: {1:F3} ms wall, {2:F3} ms GPU; mean of {3}; a negative figure is within the timing noise)", baseline.Particles, baseline.WallMs, baseline.GpuMs, options.Steps));
        if (BaselineAgain is { } again)
            b.AppendLine(string.Format(C, "The plan again after the forced rows: {0:F3} ms wall, {1:F3} ms GPU ({2:+0.0;-0.0;0.0} % GPU: the drift while they ran). "
                + "In a frame: the ms a sub-step saves when a 60 Hz frame's sub-steps are recorded together (GPU: the frame's pass ranges; - where a frame's recording was split over submits). "
                + "The last columns: the passes whose GPU ms grew most with the effect, one sub-step a submit and in a frame.", again.WallMs, again.GpuMs,
                baseline.GpuMs > 0 ? 100 * (again.GpuMs / baseline.GpuMs - 1) : 0));
        b.AppendLine();
        b.AppendLine("| planner decision | forced on | wall ms with it | GPU ms with it | wall ms saved | GPU ms saved | GPU saved % | wall ms saved in a frame | GPU ms saved in a frame | passes that grew (GPU ms) | passes that grew in a frame (GPU ms) |");
        b.AppendLine("|---|---|---:|---:|---:|---:|---:|---:|---:|---|---|");
        foreach (var s in Savings)
            b.AppendLine(string.Format(C, "| {0} | {1} | {2:F3} | {3:F3} | {4:F3} | {5:F3} | {6:P1} | {7:F3} | {8} | {9} | {10} |", s.Decision, s.Forced, s.WithEffect.WallMs, s.WithEffect.GpuMs,
                s.WallMsSaved, s.GpuMsSaved, s.WithEffect.GpuMs > 0 ? s.GpuMsSaved / s.WithEffect.GpuMs : 0, s.FrameWallMsSaved,
                double.IsNaN(s.FrameGpuMsSaved) ? "-" : s.FrameGpuMsSaved.ToString("F3", C), GrownPasses(baseline.PassMs, s.WithEffect.PassMs),
                GrownPasses(baseline.InFramePassMs, s.WithEffect.InFramePassMs)));
        return b.ToString();
    }

    /// <summary>The argument that sized row <paramref name="row"/>: --particles N, --particles-scales F, or none (the scene as it is).</summary>
    (string? Option, string Value) SizeArgument(int row)
    {
        if (options.Particles.Count > 0) return ("--particles", options.Particles[row].ToString(C));
        if (options.ParticleScales.Count > 0) return ("--particles-scales", options.ParticleScales[row].ToString("G6", C));
        return (null, "1");
    }

    /// <summary>The scene's description (a fresh read: each row owns its copy) rescaled to about <paramref name="target"/> particles.</summary>
    FluidSceneDescription ScaledTo(int target)
    {
        var description = Load().Description;
        ParticleScaling.ScaleTo(description, target);
        SceneFit.RequireScaled(description, "bench", "--particles", target.ToString(C));
        return description;
    }

    /// <summary>The scene's description with its particle count multiplied by <paramref name="factor"/> (1: as it is).</summary>
    FluidSceneDescription ScaledBy(double factor)
    {
        var description = Load().Description;
        ParticleScaling.ScaleBy(description, factor);
        SceneFit.RequireScaled(description, "bench", "--particles-scales", factor.ToString("G6", C));
        return description;
    }

    /// <summary>The scene as this bench runs it (--solver and its settings), validated so: the file read and checked
    /// once, each size's description its own.</summary>
    LoadedScene Load() => (_scene ??= SceneLoader.Open(options.ScenePath)).Read(options.Solver.AsChange("bench", note => _solverNote = note));

    SceneLoader.CheckedScene? _scene;

    /// <summary>The largest particle count whose 60 Hz frame fits the GPU budget on this device (<see cref="FrameSizing"/>).</summary>
    public FrameSizing.Fit? DeviceFit { get; private set; }

    /// <summary>The same for each GPU of --slower-gpus, in its order.</summary>
    public List<FrameSizing.Fit> SlowerGpuFits { get; } = new();

    string SizingText()
    {
        if (Rows.Count == 0 || Rows.Any(r => r.GpuMs <= 0)) return "";
        DeviceFit = FrameSizing.Largest(Rows.Select(r => (r.Particles, r.FrameGpuMs)).ToList(), options.FrameBudgetMs);
        var b = new StringBuilder();
        b.AppendLine();
        b.AppendLine(string.Format(C, "60 Hz sizing ({0}): a frame's GPU ms is the GPU ms per sub-step times the sub-steps of 1/60 s; within {1:G3} ms of GPU time a frame",
            SolverName, options.FrameBudgetMs));
        b.AppendLine(string.Format(C, "- on this device: {0}", DeviceFit));
        if (options.SlowerGpus.Count == 0) return b.ToString();
        var cost = FrameSizing.SplitCost(Rows.Select(r => (r.Particles, r.GpuMs)).ToList());
        b.AppendLine(string.Format(C, "- a sub-step here: a fixed {0:F4} ms plus {1:G3} ms per 1000 particles (least squares over the rows)", cost.FixedMs, cost.MsPerParticle * 1000));
        foreach (double ratio in options.SlowerGpus)
        {
            var fit = FrameSizing.Largest(Rows.Select(r => (r.Particles, r.FrameSubsteps * (cost.FixedMs + ratio * cost.MsPerParticle * r.Particles))).ToList(),
                options.FrameBudgetMs);
            SlowerGpuFits.Add(fit);
            var allScaled = FrameSizing.Largest(Rows.Select(r => (r.Particles, r.FrameGpuMs * ratio)).ToList(), options.FrameBudgetMs);
            b.AppendLine(string.Format(C, "- on a GPU {0:G3} times slower per particle: {1} (the same fixed cost, {0:G3} times the cost per particle); {2} if its fixed cost is {0:G3} times this one too",
                ratio, fit, allScaled));
        }
        return b.ToString();
    }

    /// <summary>
    /// One untimed simulation before the first row. The first simulation a process steps runs slower than the same
    /// scene stepped again, however long it warms up: on lavapipe 101 ms a sub-step against 83 and 84 for the next two
    /// (OilAndWater at 960 particles, --particles 1000 1000 1000), and on an H200 the plan's own row at 1M particles
    /// read 1.6 times the later forced-on rows', so every planner saving came out negative.
    /// </summary>
    void WarmUpProcess(FluidSceneDescription description, IComputeDevice device)
    {
        using var sim = new FluidSimulation(device, description);
        WarmUp(sim, device, sim.TimeStep.StableTimeStep(out _));
    }

    void WarmUp(FluidSimulation sim, IComputeDevice device, float dt)
    {
        var warming = Stopwatch.StartNew();
        for (int i = 0; i < options.Warmup || warming.Elapsed.TotalSeconds < options.WarmupSeconds; i++) StepAndWait(sim, device, dt);
    }

    Row Measure(FluidSimulation sim, IComputeDevice device)
    {
        float dt = sim.TimeStep.StableTimeStep(out _);
        WarmUp(sim, device, dt);
        bool dfsph = sim.Plan.PressureSolver == PressureSolver.Dfsph;
        if (dfsph) sim.ReadDiagnostics(); // the solves' counts start again here, so the next report covers the timed sub-steps alone
        var pass = Passes.ToDictionary(p => p, _ => 0.0);
        var kernels = new Dictionary<string, (int Dispatches, double Ms)>();
        double wall = 0, gpu = 0;
        for (int i = 0; i < options.Steps; i++)
        {
            var clock = Stopwatch.StartNew();
            StepAndWait(sim, device, dt);
            wall += clock.Elapsed.TotalMilliseconds;
            foreach (string p in Passes)
                if (sim.Plan.Runs(p) && device.TryGetSampleMilliseconds(p, out double ms))
                {
                    pass[p] += ms;
                    gpu += ms;
                }
            if (device is VulkanComputeDevice vulkan)
                foreach (var (kernel, ms) in vulkan.LastDispatchTimings)
                {
                    kernels.TryGetValue(kernel, out var k);
                    kernels[kernel] = (k.Dispatches + 1, k.Ms + ms);
                }
        }
        DiagnosticsReport? solves = dfsph ? sim.ReadDiagnostics() : null;
        var ran = solves == null ? new Dictionary<string, double>()
            : SolveBudget.DispatchesThatRun(solves.DensitySolveIterations, solves.DensitySolvesCutOff, solves.DivergenceSolveIterations,
                solves.DivergenceSolvesCutOff).ToDictionary(k => k.Kernel, k => k.Dispatches);
        // The same sub-steps again, a frame at a time: what a running simulation pays per sub-step.
        int frameSubsteps = Math.Max(1, (int)Math.Ceiling(FrameSizing.FrameSeconds / dt));
        int frames = Math.Max(1, options.Steps / frameSubsteps);
        var vulkanDevice = device as VulkanComputeDevice;
        var framePass = Passes.ToDictionary(p => p, _ => 0.0);
        bool frameTimed = vulkanDevice != null;
        double frameWallTotal = 0;
        for (int i = 0; i < frames; i++)
        {
            long splits = vulkanDevice?.SplitSubmitCount ?? 0;
            var clock = Stopwatch.StartNew();
            StepAndWait(sim, device, dt, frameSubsteps);
            frameWallTotal += clock.Elapsed.TotalMilliseconds;
            // A pass timed more than once in a submit reads as the sum (VulkanComputeDevice), so the frame's one submit gives
            // the frame's; DFSPH's wait for the last frame's motion is a submit of its own before it, with no pass of these.
            frameTimed &= vulkanDevice != null && vulkanDevice.SplitSubmitCount == splits;
            if (!frameTimed) continue;
            foreach (string p in Passes)
                if (sim.Plan.Runs(p) && device.TryGetSampleMilliseconds(p, out double ms)) framePass[p] += ms;
        }
        int frameSteps = frames * frameSubsteps;
        double frameWall = frameWallTotal / frameSteps;
        var inFramePass = frameTimed
            ? framePass.Where(p => sim.Plan.Runs(p.Key)).ToDictionary(p => p.Key, p => p.Value / frameSteps)
            : new Dictionary<string, double>();
        double inFrameGpu = frameTimed ? inFramePass.Values.Sum() : double.NaN;

        var report = sim.ReadDiagnostics();
        int n = options.Steps;
        return new Row(sim.ParticleCount, sim.Plan.ToString(), wall / n, gpu / n,
            pass.Where(p => sim.Plan.Runs(p.Key)).ToDictionary(p => p.Key, p => p.Value / n),
            kernels.OrderByDescending(k => k.Value.Ms).Select(k =>
            {
                double dispatches = (double)k.Value.Dispatches / n;
                return (k.Key, (int)Math.Round(dispatches), ran.TryGetValue(k.Key, out double r) ? r : dispatches, k.Value.Ms / n);
            }).ToList(),
            dt, report.NanCount == 0 && report.OutsideCount == 0, frameWall, frameSubsteps, sim.LanesPerParticle, solves, inFrameGpu, inFramePass);
    }

    static void StepAndWait(FluidSimulation sim, IComputeDevice device, float dt, int substeps = 1)
    {
        sim.StepFixed(substeps, dt);
        if (device is VulkanComputeDevice vulkan) vulkan.WaitIdle();
        else device.TryGetSampleMilliseconds(PassNames.FullStep, out _);
    }

    /// <summary>The Markdown tables printed on stdout (paste into the README).</summary>
    public string Table(string sceneName, string deviceName)
    {
        var b = new StringBuilder();
        var passes = Passes.Where(p => Rows.Any(r => r.PassMs.ContainsKey(p))).ToList();
        b.AppendLine();
        b.AppendLine($"Scene {sceneName}, device {deviceName}, {SolverName}: milliseconds per sub-step (mean of {options.Steps}; GPU = sum of the pass ranges; "
            + "in a frame: a 60 Hz frame's sub-steps recorded together, - where a frame's recording was split over submits; "
            + "lanes = threads per particle in the neighbour loops, NeighbourLanes)");
        b.AppendLine();
        b.AppendLine("| particles | lanes | dt (ms) | wall ms | GPU ms | wall ms in a frame (sub-steps) | GPU ms in a frame | GPU ms per 60 Hz frame | " + string.Join(" | ", passes) + " |");
        b.AppendLine("|---:|---:|---:|---:|---:|---:|---:|---:|" + string.Concat(passes.Select(_ => "---:|")));
        foreach (var r in Rows)
            b.AppendLine(string.Format(C, "| {0} | {7} | {1:F3} | {2:F3} | {3:F3} | {4:F3} ({5}) | {8} | {6:F3} | ", r.Particles, r.TimeStep * 1000, r.WallMs, r.GpuMs, r.FrameWallMs, r.FrameSubsteps, r.FrameGpuMs, r.Lanes,
                    double.IsNaN(r.InFrameGpuMs) ? "-" : r.InFrameGpuMs.ToString("F3", C))
                + string.Join(" | ", passes.Select(p => r.PassMs.TryGetValue(p, out double ms) ? ms.ToString("F3", C) : "-")) + " |");
        var last = Rows.LastOrDefault();
        if (last != null && last.Kernels.Count > 0)
        {
            b.AppendLine();
            b.AppendLine($"Per kernel at {last.Particles} particles (ms per sub-step, all dispatches of the kernel; ran: the dispatches that ran groups):");
            b.AppendLine();
            b.AppendLine("| kernel | dispatches | ran | ms | ms a dispatch that ran | share |");
            b.AppendLine("|---|---:|---:|---:|---:|---:|");
            double total = last.Kernels.Sum(k => k.Ms);
            foreach (var (kernel, dispatches, ran, ms) in last.Kernels)
                b.AppendLine(string.Format(C, "| {0} | {1} | {2:0.#} | {3:F3} | {4:F3} | {5:P1} |", kernel, dispatches, ran, ms, ran > 0 ? ms / ran : 0,
                    total > 0 ? ms / total : 0));
            if (last.Solves is { } solves)
            {
                b.AppendLine();
                b.AppendLine(string.Format(C, "DFSPH over the timed sub-steps: {0:F1} constant-density and {1:F1} divergence-free corrections a sub-step "
                    + "({2:P0} and {3:P0} of the solves cut off). A round recorded after its solve has converged dispatches no groups: a solve "
                    + "of k corrections runs its error passes k + 1 times (k when cut off) and its correction k + 1 times, the warm start's first.",
                    solves.DensitySolveIterations, solves.DivergenceSolveIterations, solves.DensitySolvesCutOff, solves.DivergenceSolvesCutOff));
            }
        }
        return b.ToString();
    }
}
