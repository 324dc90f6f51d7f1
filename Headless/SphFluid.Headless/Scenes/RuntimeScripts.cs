using System.Collections.Generic;
using SphFluid.Simulation;

namespace SphFluid.Headless.Scenes;

/// <summary>The Unity components (the package's Runtime/) the runner reads, by class (= .cs file) name.</summary>
public static class RuntimeScripts
{
    public const string Fluid = "Fluid";
    public const string SpawnBox = "SpawnBox";
    public const string FluidContainer = "FluidContainer";
    public const string SphereObstacle = "SphereObstacle";
    public const string ContainerSpinner = "ContainerSpinner";
    public const string SphereDriver = "SphereDriver";

    /// <summary>Every component of the fluid, which the reader finds by its script's guid.</summary>
    public static readonly IReadOnlyList<string> Components = new[] { Fluid, SpawnBox, FluidContainer, SphereObstacle, ContainerSpinner, SphereDriver };

    /// <summary>Each component's serialized fields, as Unity writes them into a scene (<c>RuntimeScriptTests</c> holds
    /// them to the shipped scenes). A MonoBehaviour whose script is missing but which carries one of them may be a fluid
    /// component whose script reference broke (<see cref="FluidDocuments"/>).</summary>
    public static readonly IReadOnlyDictionary<string, IReadOnlyList<string>> Fields = new Dictionary<string, IReadOnlyList<string>>
    {
        [Fluid] = new[] { "particleRadiusScale", "container", "settings", "maxFrameTime", "requestDiagnostics" },
        [SpawnBox] = new[] { "spawn" },
        [FluidContainer] = new[] { "friction" },
        [SphereObstacle] = new[] { "radius" },
        [ContainerSpinner] = new[] { "spin", "fluid" },
        [SphereDriver] = new[] { "drive", "fluid" },
    };

    /// <summary>Fluid's serialized FluidSettings field, which holds every declared setting by its field name.</summary>
    public const string Settings = "settings";

    /// <summary>SpawnBox's serialized FluidBlock, which holds every declared spawn value and, under Phase, every
    /// declared phase value, by its field name.</summary>
    public const string Spawn = "spawn";

    /// <summary>ContainerSpinner's serialized SpinLaw and SphereDriver's DriveLaw.</summary>
    public const string Spin = "spin", Drive = "drive";

    /// <summary>The package's resources asset (Runtime/Resources), which names every Fluid's shaders and material.</summary>
    public const string ResourcesAsset = "SphFluidResources";

    /// <summary>The resources asset's compute-shader fields and the program each must be (the pipeline loads them by name).</summary>
    public static readonly IReadOnlyList<(string Field, string Program)> ShaderFields = new[]
    {
        ("solverShader", FluidSimulation.SolverProgramName),
        ("diagnosticsShader", FluidSimulation.DiagnosticsProgramName),
        ("sortShader", "ParticleSort"),
        ("prefixSumShader", "PrefixSum"),
    };
}
