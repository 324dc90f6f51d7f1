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

    public static readonly IReadOnlyDictionary<string, PressureSolver> Words = new Dictionary<string, PressureSolver>
    {
        ["wcsph"] = PressureSolver.Wcsph,
        ["dfsph"] = PressureSolver.Dfsph,
    };

    /// <summary>Applies the choice to the scene's settings (a copy, so the loaded scene is untouched). A density tolerance
    /// for a run that ends up on WCSPH would be silently ignored, so it is refused by name.</summary>
    public void ApplyTo(FluidSceneDescription scene, string command)
    {
        var settings = scene.Settings.Clone();
        if (Solver.HasValue) settings.PressureSolver = Solver.Value;
        if (DensityTolerance.HasValue)
        {
            if (settings.PressureSolver != PressureSolver.Dfsph)
                throw new UsageException($"{command}: --density-tolerance applies to the DFSPH solver only; this run uses WCSPH "
                    + "(add --solver dfsph, or set Fluid.pressureSolver in the scene)");
            settings.DensityTolerance = (float)DensityTolerance.Value;
        }
        scene.Settings = settings;
    }

    /// <summary>One line for the run header and summary.</summary>
    public static string Describe(FluidSettings settings) => settings.PressureSolver == PressureSolver.Dfsph
        ? string.Format(C, "solver: DFSPH (density tolerance {0:G3} %, divergence tolerance {1:G3} %/s, at most {2} iterations per solve)",
            settings.DensityTolerance, settings.DivergenceTolerance, settings.MaxSolverIterations)
        : string.Format(C, "solver: WCSPH (Tait stiffness {0:G4} Pa, gamma {1:G3})", settings.Stiffness, settings.Gamma);

    public static string ShortName(PressureSolver solver) => solver == PressureSolver.Dfsph ? "DFSPH" : "WCSPH";
}

/// <summary>The <c>--solver</c> and <c>--density-tolerance</c> options, shared by the commands that run the solver.</summary>
public sealed class SolverOptions
{
    readonly Option<PressureSolver> _solver;
    readonly Option<double> _densityTolerance;

    public SolverOptions(string command)
    {
        _solver = OptionKinds.Choice(command, "--solver", SolverChoice.Words,
            "pressure solver, overriding the scene's Fluid.pressureSolver: wcsph (Tait equation of state) or dfsph "
            + "(divergence-free SPH, iterative; default: the scene's)");
        _densityTolerance = OptionKinds.Number(command, "--density-tolerance", 0.001, 10, false, "%", "PCT",
            "DFSPH: largest average density error the pressure solve accepts, in [0.001, 10] % (default: the scene's; "
            + "refused when the run uses WCSPH)");
    }

    public void AddTo(Command command)
    {
        command.Add(_solver);
        command.Add(_densityTolerance);
    }

    public SolverChoice Read(ParseResult r) => new()
    {
        Solver = r.GetResult(_solver) != null ? r.GetValue(_solver) : null,
        DensityTolerance = r.GetResult(_densityTolerance) != null ? r.GetValue(_densityTolerance) : null,
    };
}
