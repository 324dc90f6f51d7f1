using System;
using System.Globalization;
using System.Linq;
using System.Text.RegularExpressions;
using SphFluid.Compute;
using SphFluid.Headless.Cli;
using SphFluid.Simulation;
using SphFluid.Sorting;

namespace SphFluid.Headless.Scenes;

/// <summary>
/// Whether a fluid scene can be built at all: the core's validation, plus the neighbour grid, whose cell count the
/// validation does not bound (a 1000 m container passes it, then <see cref="CellGrid"/> refuses 3.0e14 cells).
/// Checked before a device is opened, so the refusal names the scene field or the argument that caused it.
/// </summary>
public static partial class SceneFit
{
    [GeneratedRegex(@" \(Parameter '\w+'\)(\r?\nActual value was .*)?$", RegexOptions.Singleline)]
    private static partial Regex ParameterSuffix();

    /// <summary>The neighbour grid's refusal of the container and support radius, or null when the grid fits.</summary>
    public static string? GridProblem(FluidSceneDescription scene)
    {
        try
        {
            _ = CellGrid.ForSupport(scene.Container.Position, scene.Container.Rotation, scene.Container.Size, scene.Settings.SmoothingRadius);
            return null;
        }
        catch (ArgumentOutOfRangeException e)
        {
            // The grid names its constructor parameter for programmers; a reader of the scene needs only the rule.
            return ParameterSuffix().Replace(e.Message, "");
        }
    }

    /// <summary>
    /// Refuses a scene that became impossible by rescaling its particle count: the message names the command-line
    /// <paramref name="option"/> and the rule the rescaled scene breaks (exit 2, not a crash in the solver).
    /// </summary>
    public static void RequireScaled(FluidSceneDescription scene, string command, string option, string value)
    {
        var problems = scene.Validate().Select(e => e.Message).ToList();
        if (problems.Count == 0 && GridProblem(scene) is { } grid) problems.Add(grid);
        if (problems.Count == 0) return;
        throw new UsageException(string.Format(CultureInfo.InvariantCulture,
            "{0}: {1} {2} is out of range for this scene: it needs a particle spacing of {3:G4} m (support {4:G4} m), and then\n  {5}",
            command, option, value, scene.Settings.ParticleSpacing, scene.Settings.SmoothingRadius, string.Join("\n  ", problems)));
    }

    /// <summary>
    /// Refuses a scene whose particles the device cannot hold (<see cref="DeviceCapacity"/>), before any buffer is made:
    /// as a bad argument naming <paramref name="option"/> and <paramref name="value"/> when the run rescaled the scene,
    /// else (<paramref name="option"/> null) as an error of the scene file <paramref name="scenePath"/>.
    /// </summary>
    public static void RequireDevice(FluidSceneDescription scene, IComputeDevice device, string command, string scenePath, string? option, string value)
    {
        if (DeviceCapacity.Problem(scene, device) is not { } problem) return;
        if (option == null)
            throw new SceneException($"{scenePath}: too large for this device: {problem}");
        throw new UsageException($"{command}: {option} {value} is too large for this device: {problem}");
    }
}
