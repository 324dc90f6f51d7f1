using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using SphFluid.Simulation;

namespace SphFluid.Headless.Cli;

/// <summary>The pressure solver a run asked for on the command line, overriding the scene's FluidSettings.</summary>
public sealed class SolverChoice
{
    static readonly CultureInfo C = CultureInfo.InvariantCulture;

    /// <summary>The solver to run instead of the scene's; null = the scene's.</summary>
    public PressureSolver? Solver { get; init; }

    /// <summary>DFSPH density tolerance, %, instead of the scene's; null = the scene's.</summary>
    public double? DensityTolerance { get; init; }

    /// <summary>DFSPH divergence tolerance, %/s, instead of the scene's; null = the scene's.</summary>
    public double? DivergenceTolerance { get; init; }

    /// <summary>How DFSPH's solves iterate instead of the scene's; null = the scene's.</summary>
    public SolverIteration? Iteration { get; init; }

    /// <summary>How WCSPH finds each particle's density instead of the scene's; null = the scene's.</summary>
    public WcsphDensity? Density { get; init; }

    /// <summary>The physical viscosity's stress instead of the scene's; null = the scene's.</summary>
    public ViscousStress? Stress { get; init; }

    public static readonly IReadOnlyDictionary<string, ViscousStress> StressWords = new Dictionary<string, ViscousStress>
    {
        ["laplacian"] = ViscousStress.Laplacian,
        ["strain-rate"] = ViscousStress.StrainRate,
    };

    public static readonly IReadOnlyDictionary<string, SolverIteration> IterationWords = new Dictionary<string, SolverIteration>
    {
        ["jacobi"] = SolverIteration.Jacobi,
        ["chebyshev"] = SolverIteration.Chebyshev,
    };

    public static readonly IReadOnlyDictionary<string, WcsphDensity> DensityWords = new Dictionary<string, WcsphDensity>
    {
        ["summation"] = WcsphDensity.Summation,
        ["delta-sph"] = WcsphDensity.DeltaSph,
    };

    public static readonly IReadOnlyDictionary<string, PressureSolver> Words = new Dictionary<string, PressureSolver>
    {
        ["wcsph"] = PressureSolver.Wcsph,
        ["dfsph"] = PressureSolver.Dfsph,
    };

    /// <summary>The choice as the change <see cref="Scenes.SceneLoader"/> makes before it validates the scene, so that
    /// the scene is checked as this run will use it; null when the command line chose nothing. <paramref name="noted"/>
    /// receives <see cref="ApplyTo"/>'s line.</summary>
    public Scenes.SceneChange? AsChange(string command, Action<string?> noted) =>
        Arguments() is { } arguments ? new Scenes.SceneChange(command + " " + arguments, scene => noted(ApplyTo(scene, command))) : null;

    /// <summary>The options given, as they are written ("--solver dfsph --density-tolerance 0.1"); null when none was.</summary>
    public string? Arguments()
    {
        var given = new List<string>();
        if (Solver.HasValue) given.Add("--solver " + Word(Words, Solver.Value));
        if (DensityTolerance.HasValue) given.Add("--density-tolerance " + DensityTolerance.Value.ToString("G6", C));
        if (DivergenceTolerance.HasValue) given.Add("--divergence-tolerance " + DivergenceTolerance.Value.ToString("G6", C));
        if (Iteration.HasValue) given.Add("--solver-iteration " + Word(IterationWords, Iteration.Value));
        if (Density.HasValue) given.Add("--wcsph-density " + Word(DensityWords, Density.Value));
        if (Stress.HasValue) given.Add("--viscous-stress " + Word(StressWords, Stress.Value));
        return given.Count > 0 ? string.Join(" ", given) : null;
    }

    static string Word<T>(IReadOnlyDictionary<string, T> words, T value) where T : struct, Enum
    {
        foreach (var pair in words)
            if (pair.Value.Equals(value)) return pair.Key;
        return value.ToString();
    }

    /// <summary>Applies the choice to the scene's settings (a copy, so the loaded scene is untouched). A DFSPH setting
    /// for a run that ends up on WCSPH, or a WCSPH one for a DFSPH run, would be silently ignored, so it is refused by
    /// name. Returns the line that says what <see cref="FitSupport"/> changed, or null.</summary>
    public string? ApplyTo(FluidSceneDescription scene, string command)
    {
        var settings = scene.Settings.Clone();
        if (Solver.HasValue) settings.PressureSolver = Solver.Value;
        if (DensityTolerance.HasValue)
            settings.DensityTolerance = (float)DfsphOnly(settings, command, "--density-tolerance", DensityTolerance.Value);
        if (DivergenceTolerance.HasValue)
            settings.DivergenceTolerance = (float)DfsphOnly(settings, command, "--divergence-tolerance", DivergenceTolerance.Value);
        if (Iteration.HasValue)
            settings.SolverIteration = DfsphOnly(settings, command, "--solver-iteration", Iteration.Value);
        if (Density.HasValue)
            settings.WcsphDensity = settings.PressureSolver == PressureSolver.Wcsph ? Density.Value
                : throw new UsageException($"{command}: --wcsph-density applies to the WCSPH solver only; this run uses DFSPH "
                    + "(add --solver wcsph, or set Fluid.pressureSolver in the scene)");
        if (Stress.HasValue) settings.ViscousStress = Stress.Value;
        scene.Settings = settings;
        return Solver.HasValue ? FitSupport(settings, command) : null;
    }

    static T DfsphOnly<T>(FluidSettings settings, string command, string option, T value) =>
        settings.PressureSolver == PressureSolver.Dfsph ? value
            : throw new UsageException($"{command}: {option} applies to the DFSPH solver only; this run uses WCSPH "
                + "(add --solver dfsph, or set Fluid.pressureSolver in the scene)");

    /// <summary>
    /// DFSPH takes the cubic spline at 2 spacings only, and Wendland C2 up to 2.9 with a relaxed Jacobi step
    /// (<see cref="FluidSettings.MaxDivergenceFreeSupportRatio"/>). A scene set up for WCSPH at a support DFSPH refuses
    /// (RestingTank: Wendland C2 at 2.85 spacings with the papers' full step) and switched to DFSPH from the command line
    /// runs at 2 spacings with the cubic spline, the kernel DFSPH was first measured with and the more accurate of the two
    /// there (linear gradient to 2.0 % against Wendland C2's 5 %); one whose DFSPH settings fit (OilAndWater, relaxed to
    /// 0.3) keeps its own. Returns the line that says what changed, or null when nothing did.
    /// </summary>
    public static string? FitSupport(FluidSettings settings, string command)
    {
        if (settings.PressureSolver != PressureSolver.Dfsph) return null;
        var refused = new List<string>();
        foreach (var error in settings.Validate())
            if (error.Field.EndsWith("." + nameof(FluidSettings.SmoothingRadius)) || error.Field.EndsWith("." + nameof(FluidSettings.SolverRelaxation)))
                refused.Add(error.Message);
        if (refused.Count == 0) return null;
        float support = FluidSettings.MinSupportRatio * settings.ParticleSpacing;
        string note = string.Format(C, "{0}: DFSPH refuses the scene's {1} at {2:G4} m ({3}): {4:G4} m with the cubic spline instead",
            command, settings.SmoothingKernel, settings.SmoothingRadius, string.Join("; ", refused), support);
        settings.SmoothingRadius = support;
        settings.SmoothingKernel = KernelFamily.CubicSpline;
        return note;
    }

    /// <summary>One line for the run header and summary; with <paramref name="simulation"/>, whether its Chebyshev solve
    /// accelerates the constant-density solve too (ChebyshevBounds.AcceleratesDensitySolve).</summary>
    public static string Describe(FluidSettings settings, FluidSimulation? simulation = null) => settings.PressureSolver == PressureSolver.Dfsph
        ? string.Format(C, "solver: DFSPH (density tolerance {0:G3} %, divergence tolerance {1:G3} %/s, at most {2} iterations per solve, {3}, relaxation {4:G3})",
            settings.DensityTolerance, settings.DivergenceTolerance, settings.MaxSolverIterations,
            settings.SolverIteration == SolverIteration.Jacobi ? "Jacobi"
                : simulation == null || simulation.AcceleratesDensitySolve ? "Chebyshev-accelerated"
                : "Chebyshev-accelerated divergence-free solve, Jacobi constant-density solve at this tolerance and depth",
            settings.SolverRelaxation)
        : string.Format(C, "solver: WCSPH (Tait stiffness {0:G4} Pa, gamma {1:G3}, {2})", settings.Stiffness, settings.Gamma,
            settings.WcsphDensity == WcsphDensity.DeltaSph ? "delta-SPH density" : "summation density");

    public static string ShortName(PressureSolver solver) => solver == PressureSolver.Dfsph ? "DFSPH" : "WCSPH";
}

/// <summary>The <c>--solver</c>, <c>--density-tolerance</c>, <c>--divergence-tolerance</c>, <c>--solver-iteration</c>,
/// <c>--wcsph-density</c> and <c>--viscous-stress</c> options, shared by the commands that run the solver.</summary>
public sealed class SolverOptions
{
    readonly Option<PressureSolver> _solver;
    readonly Option<double> _densityTolerance;
    readonly Option<double> _divergenceTolerance;
    readonly Option<SolverIteration> _iteration;
    readonly Option<WcsphDensity> _density;
    readonly Option<ViscousStress> _stress;

    public SolverOptions(string command)
    {
        _solver = OptionKinds.Choice(command, "--solver", SolverChoice.Words,
            "pressure solver, overriding the scene's Fluid.pressureSolver: wcsph (Tait equation of state) or dfsph "
            + "(divergence-free SPH, iterative; default: the scene's)");
        _densityTolerance = OptionKinds.Setting(command, "--density-tolerance", nameof(FluidSettings.DensityTolerance), "PCT",
            "default: the scene's; refused when the run uses WCSPH");
        _divergenceTolerance = OptionKinds.Setting(command, "--divergence-tolerance", nameof(FluidSettings.DivergenceTolerance), "PCT/S",
            "default: the scene's; refused when the run uses WCSPH");
        _iteration = OptionKinds.Choice(command, "--solver-iteration", SolverChoice.IterationWords,
            "DFSPH: how each solve iterates, overriding the scene's Fluid.solverIteration: jacobi (compression-only relaxed "
            + "Jacobi steps) or chebyshev (accelerated, projected steps; default: the scene's; refused when the run uses WCSPH)");
        _density = OptionKinds.Choice(command, "--wcsph-density", SolverChoice.DensityWords,
            "WCSPH: how each particle's density is found, overriding the scene's WcsphDensity: summation (the kernel sum over "
            + "its neighbours, every sub-step) or delta-sph (carried, integrated with delta-SPH's diffusion, started hydrostatic; "
            + "default: the scene's; refused when the run uses DFSPH)");
        _stress = OptionKinds.Choice(command, "--viscous-stress", SolverChoice.StressWords,
            "the physical viscosity's stress, overriding the scene's ViscousStress: laplacian (Morris's pair term; brakes a "
            + "rigid spin) or strain-rate (the Newtonian stress; keeps a spin, one more pass a sub-step; default: the scene's)");
    }

    public void AddTo(Command command)
    {
        command.Add(_solver);
        command.Add(_densityTolerance);
        command.Add(_divergenceTolerance);
        command.Add(_iteration);
        command.Add(_density);
        command.Add(_stress);
    }

    public SolverChoice Read(ParseResult r) => new()
    {
        Solver = r.GetResult(_solver) != null ? r.GetValue(_solver) : null,
        DensityTolerance = r.GetResult(_densityTolerance) != null ? r.GetValue(_densityTolerance) : null,
        DivergenceTolerance = r.GetResult(_divergenceTolerance) != null ? r.GetValue(_divergenceTolerance) : null,
        Iteration = r.GetResult(_iteration) != null ? r.GetValue(_iteration) : null,
        Density = r.GetResult(_density) != null ? r.GetValue(_density) : null,
        Stress = r.GetResult(_stress) != null ? r.GetValue(_stress) : null,
    };
}
