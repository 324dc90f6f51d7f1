using System;
using System.CommandLine;
using SphFluid.Headless.Runs;

namespace SphFluid.Headless.Cli;

/// <summary>The arguments of <c>sphfluid simulate</c>.</summary>
public sealed class SimulateOptions(string scenePath)
{
    public const double DefaultSeconds = 3.0;
    public const double DefaultFrameSeconds = 1.0 / 60.0;

    /// <summary>
    /// Shortest run, frame and output interval, s. The solver steps at least 1 microsecond per frame, and rows and
    /// snapshots come at frame ends: a shorter value would be misreported or would never advance the next output
    /// time (1e-300 added to 0.25 is 0.25), so it is refused rather than run. A run ends within a microsecond of its
    /// --seconds, so a shorter run (once accepted down to anything above 0) ran no frame at all and still exited 0.
    /// </summary>
    public const double MinInterval = 1e-4;

    public string ScenePath { get; } = scenePath;

    /// <summary>Simulated seconds to run (ignored when <see cref="Frames"/> is set).</summary>
    public double Seconds { get; set; } = DefaultSeconds;

    /// <summary>Frames of <see cref="FrameSeconds"/> to run instead of <see cref="Seconds"/>; 0 = use seconds.</summary>
    public int Frames { get; set; }

    /// <summary>Real time given to each frame (as a 60 Hz Unity frame), s; the solver covers it in adaptive sub-steps.</summary>
    public double FrameSeconds { get; set; } = DefaultFrameSeconds;

    /// <summary>Output folder; null = Output/&lt;scene name&gt;.</summary>
    public string? OutputDirectory { get; set; }

    public double SnapshotEvery { get; set; } = 0.25;
    public double DiagnosticsEvery { get; set; } = 0.25;

    /// <summary>Simulated seconds between particle exports (.vtu, .ply, .pvd); 0 = no export.</summary>
    public double ExportEvery { get; set; }

    /// <summary>Multiplies the scene's particle count (the spacing shrinks by its cube root).</summary>
    public double ParticlesScale { get; set; } = 1.0;

    /// <summary>Multiplies the particle count once more when the Vulkan device is a CPU (lavapipe); 1 = the same fluid on
    /// every device. The main job passes 0.5 to finish in under 3 minutes on 2 CPU cores.</summary>
    public double CpuParticlesScale { get; set; } = 1.0;

    /// <summary>Case-insensitive substring of the Vulkan adapter name; null = SPHFLUID_VULKAN_DEVICE, else the best.</summary>
    public string? DeviceName { get; set; }

    public bool TopView { get; set; }
    public int ImageWidth { get; set; } = 640;
    public bool Quiet { get; set; }

    /// <summary>The pressure solver and tolerance given on the command line (default: the scene's).</summary>
    public SolverChoice Solver { get; set; } = new();

    /// <summary>Parses the arguments after <c>simulate</c>; a mistake is a <see cref="UsageException"/>.</summary>
    public static SimulateOptions Parse(string[] args) => SphfluidCommandLine.ParseOnly<SimulateOptions>("simulate", args);

    /// <summary>Frames the run takes.</summary>
    public int FrameCount => Frames > 0 ? Frames : Math.Max(1, (int)Math.Ceiling(Seconds / FrameSeconds - 1e-9));

    /// <summary>Simulated seconds the run takes: --seconds, or --steps frames of --frame-seconds.</summary>
    public double Duration => Frames > 0 ? Frames * FrameSeconds : Seconds;

    /// <summary>How many times an output due every <paramref name="every"/> s comes over the run: at 0, S, 2S ... as the
    /// frames' ends reach them, so at most one at the start and one a frame.</summary>
    public long Looks(double every) => Looks(Duration, FrameCount, every);

    /// <inheritdoc cref="Looks(double)"/>
    public static long Looks(double seconds, int frames, double every) =>
        (long)Math.Min(frames + 1.0, Math.Floor(seconds / every + 1e-9) + 1.0);
}

/// <summary>The <c>simulate</c> command's syntax and generated help.</summary>
public sealed class SimulateCommand : Command
{
    const string Verb = "simulate";

    public const string Details =
@"Details:
Reads a Unity scene file (the Fluid's settings, every SpawnBox with its world transform, the
FluidContainer, SphereObstacles, ContainerSpinner/SphereDriver motion) and simulates it on the headless
Vulkan backend. Writes diagnostics.csv, frame_NNNN.png snapshots, layering.png/.svg (multi-phase scenes)
and summary.txt into the output folder. The scene must be a regular file of at most 16 MiB that passes the
project's integrity check (the same check the test suite runs on every shipped scene).

Measures (console, diagnostics.csv, summary.txt): kinetic and potential energy; per phase the
compression max(0, rho/rho0 - 1) and expansion max(0, 1 - rho/rho0) (mean and max), the mean, bottom
and top height (along gravity from the container's lowest corner) and its share of the floor and wall
layers (particles within one spacing of the face); the layering index over pairs of different density,
(ordered - inverted) / pairs (1 = perfectly layered, 0 = mixed, -1 = upside down); the surge front
(container-local x from the back wall reached within 2 spacings of the floor) and the column height at
the back wall, spray ignored.

" + SphfluidCommandLine.ExitCodesText;

    readonly Argument<string> _scene = OptionKinds.Scene();
    readonly Option<double> _seconds = OptionKinds.Number(Verb, "--seconds", SimulateOptions.MinInterval, 3600, false, "s", "S", "simulated seconds to run, in [0.0001, 3600]", SimulateOptions.DefaultSeconds);
    readonly Option<int> _steps = OptionKinds.Whole(Verb, "--steps", 1, 1_000_000, "N", "run N frames of --frame-seconds instead, N in [1, 1000000]");
    readonly Option<double> _frameSeconds = OptionKinds.Number(Verb, "--frame-seconds", SimulateOptions.MinInterval, 0.1, false, "s", "S",
        "real time per frame, in [0.0001, 0.1] s (default 1/60, as a 60 Hz Unity frame)");
    readonly Option<string> _out = OptionKinds.Text(Verb, "--out", "DIR",
        "output folder (default Output/<scene name>). The run records what it writes in DIR/.sphfluid-outputs and deletes only the files "
        + "an earlier run recorded there; a folder holding frame_NNNN.png, summary.txt ... that sphfluid did not write is refused (exit 2) and left as it was");
    readonly Option<double> _framesEvery = OptionKinds.Number(Verb, "--frames-every", SimulateOptions.MinInterval, 3600, false, "s", "S",
        "simulated seconds between PNG snapshots, in [0.0001, 3600]; snapshots come at frame ends, so at most one per frame", 0.25);
    readonly Option<double> _diagnosticsEvery = OptionKinds.Number(Verb, "--diagnostics-every", SimulateOptions.MinInterval, 3600, false, "s", "S",
        "simulated seconds between diagnostics lines/CSV rows, in [0.0001, 3600]; at most one row per frame", 0.25);
    readonly Option<double> _exportEvery = OptionKinds.Number(Verb, "--export-every", SimulateOptions.MinInterval, 3600, false, "s", "S",
        "simulated seconds between particle exports, in [0.0001, 3600] (default: none). Each writes particles_NNNN.vtu (ParaView; inline "
        + "base64 binary) and particles_NNNN.ply (Blender, MeshLab; binary little-endian) with position, velocity, phase, density and "
        + "pressure, and particles.pvd indexes the .vtu files by time");
    readonly Option<double> _particlesScale = OptionKinds.Number(Verb, "--particles-scale", 0.01, ParticleScaling.MaxFactor, false, "", "F",
        "multiply the particle count by F, in [0.01, 4096] (spacing and support shrink by F^(1/3))", 1.0);
    readonly Option<double> _cpuParticlesScale = OptionKinds.Number(Verb, "--cpu-particles-scale", 0.01, 1, false, "", "F",
        "on a CPU Vulkan device (lavapipe) only, multiply the particle count by F as well, in [0.01, 1]; printed when applied "
        + "(Headless/simulate.sh without arguments passes 0.5)", 1.0);
    readonly Option<string> _device = OptionKinds.Text(Verb, "--device", "NAME", SphfluidCommandLine.DeviceHelp);
    readonly Option<bool> _topView = OptionKinds.Flag("--top-view", "also write top_NNNN.png (looking down)");
    readonly Option<int> _width = OptionKinds.Whole(Verb, "--width", 64, 4096, "PX", "snapshot width in pixels, in [64, 4096]", 640);
    readonly Option<bool> _quiet = OptionKinds.Flag("--quiet", "no progress output");
    readonly SolverOptions _solver = new(Verb);

    public SimulateCommand() : base(Verb, "simulate the scene\'s fluid: diagnostics, snapshots, charts, summary")
    {
        Add(_scene);
        foreach (var option in new Option[] { _seconds, _steps, _frameSeconds, _out, _framesEvery, _diagnosticsEvery, _exportEvery,
                     _particlesScale, _cpuParticlesScale, _device, _topView, _width, _quiet })
            Add(option);
        _solver.AddTo(this);
    }

    /// <summary>The options of a parse without errors; the checks that span options are made here.</summary>
    public SimulateOptions Read(ParseResult r)
    {
        string scene = OptionKinds.RequiredScene(r, _scene, Verb, "Assets/FluidDemo/Scenes/OilAndWater.unity");
        var options = new SimulateOptions(scene)
        {
            Seconds = r.GetValue(_seconds),
            Frames = r.GetValue(_steps),
            OutputDirectory = r.GetValue(_out),
            SnapshotEvery = r.GetValue(_framesEvery),
            DiagnosticsEvery = r.GetValue(_diagnosticsEvery),
            ExportEvery = r.GetValue(_exportEvery),
            ParticlesScale = r.GetValue(_particlesScale),
            CpuParticlesScale = r.GetValue(_cpuParticlesScale),
            DeviceName = r.GetValue(_device),
            TopView = r.GetValue(_topView),
            ImageWidth = r.GetValue(_width),
            Quiet = r.GetValue(_quiet),
            Solver = _solver.Read(r),
        };
        if (r.GetResult(_frameSeconds) != null) options.FrameSeconds = r.GetValue(_frameSeconds);
        if (r.GetResult(_seconds) is { Implicit: false } && options.Frames > 0)
            throw new UsageException($"{Verb}: give either --seconds or --steps, not both");
        return options;
    }
}
