using System.Collections.Generic;
using SphFluid.Simulation;

namespace SphFluid.Headless.Scenes;

/// <summary>A Unity scene file read into what the solver needs, plus where each piece came from.</summary>
public sealed class LoadedScene
{
    /// <summary>The scene file as given.</summary>
    public string Path { get; init; }

    /// <summary>Root of the Unity project the scene belongs to (its shaders are under Packages/com.sphfluid.fluid/Shaders).</summary>
    public string ProjectRoot { get; init; }

    /// <summary>File name without extension ("OilAndWater").</summary>
    public string Name { get; init; }

    /// <summary>Settings, spawn boxes, container and obstacles at time 0.</summary>
    public FluidSceneDescription Description { get; init; }

    public SceneMotion Motion { get; init; } = new();

    /// <summary>GameObject holding the Fluid.</summary>
    public string SimulatorObject { get; init; }

    /// <summary>GameObject of each spawn box, in spawn order.</summary>
    public IReadOnlyList<string> SpawnBoxObjects { get; init; }

    public string ContainerObject { get; init; }

    public IReadOnlyList<string> ObstacleObjects { get; init; }
}
