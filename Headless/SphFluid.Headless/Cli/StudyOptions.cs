using System.Collections.Generic;
using System.CommandLine;
using SphFluid.Headless.Runs;
using SphFluid.Simulation;

namespace SphFluid.Headless.Cli;

/// <summary>The arguments of <c>sphfluid study</c>: the matrix of configurations the accuracy-for-time study runs.</summary>
public sealed class StudyOptions(string scenePath)
{
    public string ScenePath { get; } = scenePath;

    /// <summary>Output folder; null = Output/&lt;scene name&gt;-study.</summary>
    public string? OutputDirectory { get; set; }

    /// <summary>Case-insensitive substring of the Vulkan adapter name; null = SPHFLUID_VULKAN_DEVICE, else the best.</summary>
    public string? DeviceName { get; set; }

    public bool Quick { get; set; }

    /// <summary>Simulated seconds per configuration.</summary>
    public double Seconds { get; set; } = 1.0;

    /// <summary>WCSPH runs: multiples of the scene's Tait stiffness.</summary>
    public List<double> StiffnessFactors { get; set; } = new() { 1, 4 };

    /// <summary>DFSPH runs: density tolerances, %.</summary>
    public List<double> DensityTolerances { get; set; } = new() { 1, 0.1, 0.01 };

    /// <summary>DFSPH runs: divergence tolerances, %/s, each with every density tolerance; empty = the scene's.</summary>
    public List<double> DivergenceTolerances { get; set; } = new();

    /// <summary>Resolutions: particle-count multipliers (ParticleScaling).</summary>
    public List<double> ParticleScales { get; set; } = new() { 0.5, 1 };

    /// <summary>CFL numbers; empty = the scene's.</summary>
    public List<double> CflNumbers { get; set; } = new();

    /// <summary>The pressure solvers to run (default both).</summary>
    public List<SphFluid.Simulation.PressureSolver> Solvers { get; set; } = new() { SphFluid.Simulation.PressureSolver.Wcsph, SphFluid.Simulation.PressureSolver.Dfsph };

    /// <summary>How the DFSPH runs' solves iterate, each a row of its own; empty = the scene's SolverIteration.</summary>
    public List<SphFluid.Simulation.SolverIteration> SolverIterations { get; set; } = new();

    public static StudyOptions Parse(string[] args) => SphfluidCommandLine.ParseOnly<StudyOptions>("study", args);
}

/// <summary>The <c>study</c> command's syntax and generated help.</summary>
public sealed class StudyCommand : Command
{
    const string Verb = "study";

    public const string Details =
@"Details:
Runs the scene once per configuration of a matrix: WCSPH at each --stiffness-factors multiple of the
scene's Tait stiffness and DFSPH at each --density-tolerances value (with each --divergence-tolerances
value and each --solver-iterations scheme), each at every --particles-scales
resolution and every --cfl number, for --seconds of simulated time. For each configuration it reports the
average and max density error per phase (|rho/rho0 - 1|, GPU diagnostics, averaged / maximised over the
samples), the divergence error (DFSPH), the energy drift ((E_end - E_0) / E_0, kinetic + potential), the
scene's observables at the end (layering index, surge front, column height at the back wall) and their
error against the finest configuration run (largest particle scale, smallest CFL, tightest solver), the
pressure-solver iterations per sub-step and the shares of DFSPH density and divergence solves cut off at
the iteration limit (above 0, that error can exceed its tolerance; a line under the table names the rows),
sub-steps, GPU ms and wall ms per simulated second and the real-time factor. Writes study.csv, study.md
(the same table in Markdown) and study-pareto.png/.svg (observable error against wall time per
simulated second, log axes, one series per solver, DFSPH iteration scheme and divergence tolerance given) into --out.
--quick: a small matrix for a check in a few minutes on 2 CPU cores (0.1 s simulated; scales 0.25 and
0.5; the scene's CFL; WCSPH x1; DFSPH 1, 0.1 and 0.01 %). A matrix of more than 1000 configurations is refused.

" + SphfluidCommandLine.ExitCodesText;

    readonly Argument<string> _scene = OptionKinds.Scene();
    readonly Option<string> _out = OptionKinds.Text(Verb, "--out", "DIR",
        "output folder (default Output/<scene name>-study; the same rules as simulate --out: only files sphfluid wrote there are replaced)");
    readonly Option<double> _seconds = OptionKinds.Number(Verb, "--seconds", SimulateOptions.MinInterval, 60, false, "s", "S", "simulated seconds per configuration, in [0.0001, 60] (default 1; --quick 0.1)");
    readonly Option<List<double>> _stiffness = OptionKinds.List(Verb, "--stiffness-factors", "F",
        "WCSPH runs: multiples of the scene's Tait stiffness, each in [0.01, 100] (default 1 4; --quick 1)",
        text => Ranges.ParseDouble(Verb, "--stiffness-factors", text, 0.01, 100, false, ""));
    readonly Option<List<double>> _tolerances = OptionKinds.SettingList(Verb, "--density-tolerances", nameof(FluidSettings.DensityTolerance), "PCT",
        "the DFSPH runs; default 1 0.1 0.01");
    readonly Option<List<double>> _divergenceTolerances = OptionKinds.SettingList(Verb, "--divergence-tolerances", nameof(FluidSettings.DivergenceTolerance), "PCT/S",
        "the DFSPH runs, each with every density tolerance; default: the scene's");
    readonly Option<List<double>> _scales = OptionKinds.List(Verb, "--particles-scales", "F",
        "resolutions: particle-count multipliers, each in [0.01, 4096] (default 0.5 1; --quick 0.25 0.5)",
        text => Ranges.ParseDouble(Verb, "--particles-scales", text, 0.01, ParticleScaling.MaxFactor, false, ""));
    readonly Option<List<double>> _cfl = OptionKinds.SettingList(Verb, "--cfl", nameof(FluidSettings.CflNumber), "C",
        "default: the scene's CflNumber and half of it; --quick the scene's");
    readonly Option<List<SphFluid.Simulation.PressureSolver>> _solvers = OptionKinds.List(Verb, "--solvers", "wcsph|dfsph",
        "the solvers to run (default both)",
        text => SolverChoice.Words.TryGetValue(text.ToLowerInvariant(), out var s) ? s : throw new UsageException($"{Verb}: --solvers must be wcsph and/or dfsph (was '{text}')"));
    readonly Option<List<SphFluid.Simulation.SolverIteration>> _iterations = OptionKinds.List(Verb, "--solver-iterations", "jacobi|chebyshev",
        "how the DFSPH runs' solves iterate, each its own rows and chart series (default: the scene's SolverIteration)",
        text => SolverChoice.IterationWords.TryGetValue(text.ToLowerInvariant(), out var s) ? s
            : throw new UsageException($"{Verb}: --solver-iterations must be jacobi and/or chebyshev (was '{text}')"));
    readonly Option<bool> _quick = OptionKinds.Flag("--quick", "a small matrix that finishes in a few minutes on 2 CPU cores (see Details); explicit options still apply");
    readonly Option<string> _device = OptionKinds.Text(Verb, "--device", "NAME", SphfluidCommandLine.DeviceHelp);

    public StudyCommand() : base(Verb, "accuracy for time: a matrix of solvers, tolerances, resolutions and CFL numbers; CSV, Markdown, Pareto chart")
    {
        Add(_scene);
        foreach (var option in new Option[] { _out, _seconds, _stiffness, _tolerances, _divergenceTolerances, _scales, _cfl, _solvers, _iterations, _quick, _device }) Add(option);
    }

    public StudyOptions Read(ParseResult r)
    {
        bool quick = r.GetValue(_quick);
        string scene = OptionKinds.RequiredScene(r, _scene, Verb, "Assets/FluidDemo/Scenes/DamBreak.unity --quick");
        var options = new StudyOptions(scene)
        {
            OutputDirectory = r.GetValue(_out),
            DeviceName = r.GetValue(_device),
            Quick = quick,
        };
        if (quick)
        {
            options.Seconds = 0.1;
            options.StiffnessFactors = new() { 1 };
            options.ParticleScales = new() { 0.25, 0.5 };
        }
        if (r.GetResult(_seconds) != null) options.Seconds = r.GetValue(_seconds);
        options.StiffnessFactors = OptionKinds.Given(r, _stiffness) ?? options.StiffnessFactors;
        options.DensityTolerances = OptionKinds.Given(r, _tolerances) ?? options.DensityTolerances;
        options.DivergenceTolerances = OptionKinds.Given(r, _divergenceTolerances) ?? options.DivergenceTolerances;
        options.ParticleScales = OptionKinds.Given(r, _scales) ?? options.ParticleScales;
        options.CflNumbers = OptionKinds.Given(r, _cfl) ?? options.CflNumbers;
        options.Solvers = OptionKinds.Given(r, _solvers) ?? options.Solvers;
        options.SolverIterations = OptionKinds.Given(r, _iterations) ?? options.SolverIterations;
        RefuseWithoutRows(r, options.Solvers, PressureSolver.Dfsph, _tolerances, _divergenceTolerances, _iterations);
        RefuseWithoutRows(r, options.Solvers, PressureSolver.Wcsph, _stiffness);
        return options;
    }

    /// <summary>An option that shapes one solver's rows changes nothing when --solvers runs none of them: refused, as
    /// simulate and bench refuse a DFSPH tolerance for a WCSPH run, rather than ignored.</summary>
    static void RefuseWithoutRows(ParseResult r, List<PressureSolver> solvers, PressureSolver solver, params Option[] options)
    {
        if (solvers.Contains(solver)) return;
        string rows = solver == PressureSolver.Dfsph ? "DFSPH" : "WCSPH";
        foreach (var option in options)
            if (r.GetResult(option) != null)
                throw new UsageException($"{Verb}: {option.Name} applies to the {rows} rows, and --solvers runs none (add {rows.ToLowerInvariant()})");
    }
}
