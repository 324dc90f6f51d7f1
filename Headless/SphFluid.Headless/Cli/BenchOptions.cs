using System.Collections.Generic;
using System.CommandLine;

namespace SphFluid.Headless.Cli;

/// <summary>The arguments of <c>sphfluid bench</c>.</summary>
public sealed class BenchOptions(string scenePath)
{
    public string ScenePath { get; } = scenePath;

    /// <summary>Particle counts to measure (the spawn spacing is scaled to reach each); empty = the scene as it is.</summary>
    public List<int> Particles { get; } = new();

    /// <summary>Particle-count multipliers of the scene's own count to measure instead (1 = the scene as it is).</summary>
    public List<double> ParticleScales { get; } = new();

    /// <summary>Other GPUs whose 60 Hz sizing is estimated besides this device's, each as how many times longer it takes
    /// per particle (<see cref="Runs.FrameSizing"/>); empty: this device's sizing only.</summary>
    public List<double> SlowerGpus { get; } = new();

    /// <summary>GPU milliseconds of a 60 Hz frame the simulation may spend (<see cref="Runs.FrameSizing"/>).</summary>
    public double FrameBudgetMs { get; set; } = Runs.FrameSizing.DefaultBudgetMs;

    /// <summary>Timed sub-steps per particle count.</summary>
    public int Steps { get; set; } = 20;

    /// <summary>Untimed sub-steps first (shader compilation, caches, the fluid leaving its lattice).</summary>
    public int Warmup { get; set; } = 5;

    /// <summary>Wall seconds the untimed sub-steps last at least: a GPU idling at a low clock takes a while under load
    /// to reach its working clock, and rows timed before it did read slower than the rows after them.</summary>
    public double WarmupSeconds { get; set; } = DefaultWarmupSeconds;

    public const double DefaultWarmupSeconds = 0.5;

    /// <summary>Case-insensitive substring of the Vulkan adapter name; null = SPHFLUID_VULKAN_DEVICE, else the best.</summary>
    public string? DeviceName { get; set; }

    /// <summary>Leave out the planner-savings runs (one per effect the scene's plan leaves out).</summary>
    public bool SkipSavings { get; set; }

    /// <summary>Folder for the scaling chart; default Output/&lt;scene name&gt;-bench.</summary>
    public string? OutputDirectory { get; set; }

    /// <summary>The pressure solver and tolerance given on the command line (default: the scene's).</summary>
    public SolverChoice Solver { get; set; } = new();

    /// <summary>Parses the arguments after <c>bench</c>; a mistake is a <see cref="UsageException"/>.</summary>
    public static BenchOptions Parse(string[] args) => SphfluidCommandLine.ParseOnly<BenchOptions>("bench", args);
}

/// <summary>The <c>bench</c> command's syntax and generated help.</summary>
public sealed class BenchCommand : Command
{
    const string Verb = "bench";

    public const string Details =
@"Details:
Times the SPH pipeline on the scene: milliseconds per sub-step in total (wall clock and GPU) and per
pass (GPU timestamp ranges), as a Markdown table. The scene is checked as by simulate (a regular file
of at most 16 MiB that passes the integrity check), and every --particles count before the device opens.

" + SphfluidCommandLine.ExitCodesText;

    readonly Argument<string> _scene = OptionKinds.Scene();
    readonly Option<List<int>> _particles = OptionKinds.List(Verb, "--particles", "N",
        "particle counts to measure, each in [64, 16777216] (also N,N,...); the scene's spawn spacing and support radius are scaled "
        + "to reach them (default: the scene as it is)",
        text => Ranges.ParseInt(Verb, "--particles", text, 64, 16_777_216));
    readonly Option<List<double>> _scales = OptionKinds.List(Verb, "--particles-scales", "F",
        "particle-count multipliers of the scene's own count to measure instead of --particles, each in [0.01, "
        + Runs.ParticleScaling.MaxFactor.ToString(System.Globalization.CultureInfo.InvariantCulture) + "]; 1 is the scene as it is",
        text => Ranges.ParseDouble(Verb, "--particles-scales", text, 0.01, Runs.ParticleScaling.MaxFactor, false, ""));
    readonly Option<double> _frameBudget = OptionKinds.Number(Verb, "--frame-budget", 0.1, 1000, false, "ms", "MS",
        "GPU milliseconds of a 60 Hz frame the simulation may spend; the bench prints the largest particle count whose frame "
        + "(GPU ms per sub-step x the sub-steps of 1/60 s) fits, interpolated between the counts measured, in [0.1, 1000] "
        + "(default: half of the frame's 16.7 ms, the rest left to drawing)", Runs.FrameSizing.DefaultBudgetMs);
    readonly Option<List<double>> _slowerGpus = OptionKinds.List(Verb, "--slower-gpus", "R",
        "also estimate that particle count for GPUs R times slower than this device per particle (its throughput over "
        + "theirs), each in [1, 1000]: a sub-step is taken as this device's fixed cost plus R times its cost per particle",
        text => Ranges.ParseDouble(Verb, "--slower-gpus", text, 1, 1000, false, ""));
    readonly Option<int> _steps = OptionKinds.Whole(Verb, "--steps", 1, 100_000, "N", "timed sub-steps per count, in [1, 100000]", 20);
    readonly Option<int> _warmup = OptionKinds.Whole(Verb, "--warmup", 0, 100_000, "N", "untimed sub-steps before timing, in [0, 100000]", 5);
    readonly Option<double> _warmupSeconds = OptionKinds.Number(Verb, "--warmup-seconds", 0, 60, false, "s", "S",
        "keep warming up until at least S wall seconds have passed (a GPU reaches its working clock under load), in [0, 60]",
        BenchOptions.DefaultWarmupSeconds);
    readonly Option<string> _device = OptionKinds.Text(Verb, "--device", "NAME", SphfluidCommandLine.DeviceHelp);
    readonly Option<string> _out = OptionKinds.Text(Verb, "--out", "DIR",
        "folder for bench-scaling.png/.svg, milliseconds per sub-step against particles (default Output/<scene name>-bench; "
        + "the same rules as simulate --out: only files sphfluid wrote there are replaced)");
    readonly Option<bool> _skipSavings = OptionKinds.Flag("--skip-savings",
        "leave out the planner savings: by default each effect the scene's plan leaves out (MULTIPHASE for one phase, surface "
        + "tension, XSPH, obstacles, a moving container) is forced on at the last particle count, and the ms per sub-step it "
        + "costs is printed as what the planner saves");
    readonly SolverOptions _solver = new(Verb);

    public BenchCommand() : base(Verb, "time the pipeline per sub-step, pass and kernel, and what each planner decision saves")
    {
        Add(_scene);
        Add(_particles);
        Add(_scales);
        Add(_frameBudget);
        Add(_slowerGpus);
        Add(_steps);
        Add(_warmup);
        Add(_warmupSeconds);
        Add(_device);
        Add(_out);
        Add(_skipSavings);
        _solver.AddTo(this);
    }

    public BenchOptions Read(ParseResult r)
    {
        string scene = OptionKinds.RequiredScene(r, _scene, Verb, "Assets/FluidDemo/Scenes/DamBreak.unity");
        var options = new BenchOptions(scene)
        {
            Steps = r.GetValue(_steps),
            Warmup = r.GetValue(_warmup),
            WarmupSeconds = r.GetValue(_warmupSeconds),
            DeviceName = r.GetValue(_device),
            OutputDirectory = r.GetValue(_out),
            SkipSavings = r.GetValue(_skipSavings),
            Solver = _solver.Read(r),
            FrameBudgetMs = r.GetValue(_frameBudget),
        };
        if (OptionKinds.Given(r, _particles) is { } particles) options.Particles.AddRange(particles);
        if (OptionKinds.Given(r, _scales) is { } scales) options.ParticleScales.AddRange(scales);
        if (options.Particles.Count > 0 && options.ParticleScales.Count > 0)
            throw new UsageException($"{Verb}: give either --particles or --particles-scales, not both");
        if (OptionKinds.Given(r, _slowerGpus) is { } slower) options.SlowerGpus.AddRange(slower);
        return options;
    }
}
