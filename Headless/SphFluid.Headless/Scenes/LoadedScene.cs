using System.Collections.Generic;
using SphFluid.Simulation;

namespace SphFluid.Headless.Scenes;

/// <summary>A Unity scene file read into what the solver needs, plus where each piece came from.</summary>
public sealed class LoadedScene
{
    /// <summary>The scene file as given.</summary>
    public required string Path { get; init; }

    /// <summary>The fluid package the scene's project uses (<see cref="FluidPackage.FolderFor"/>), whose Shaders/ the run compiles.</summary>
    public required string PackageFolder { get; init; }

    /// <summary>File name without extension ("OilAndWater").</summary>
    public required string Name { get; init; }

    /// <summary>Settings, spawn boxes, container and obstacles at time 0.</summary>
    public required FluidSceneDescription Description { get; init; }

    public SceneMotion Motion { get; init; } = new();

    /// <summary>GameObject holding the Fluid.</summary>
    public required string SimulatorObject { get; init; }

    /// <summary>GameObject of each spawn box, in spawn order.</summary>
    public required IReadOnlyList<string> SpawnBoxObjects { get; init; }

    public required string ContainerObject { get; init; }

    public required IReadOnlyList<string> ObstacleObjects { get; init; }
}
