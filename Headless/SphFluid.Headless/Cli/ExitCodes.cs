namespace SphFluid.Headless.Cli;

/// <summary>What <c>sphfluid</c> returns to the shell.</summary>
public static class ExitCodes
{
    public const int Ok = 0;

    /// <summary>No usable Vulkan device, a file that cannot be written (a full disk), or an unexpected failure (the
    /// message says which).</summary>
    public const int Failure = 1;

    /// <summary>A command-line argument is unknown, missing or out of range.</summary>
    public const int BadArguments = 2;

    /// <summary>The scene file cannot be read (not a regular file of at most 16 MiB, not Unity's YAML), fails the
    /// project's integrity check (a duplicated fileID, an unknown script guid, a parent cycle...), or describes an
    /// impossible fluid.</summary>
    public const int BadScene = 3;

    /// <summary>The run became unhealthy (SphFluid.Simulation.HealthCheck): non-finite, particles lost, or faster,
    /// more compressed or more energetic than the scene allows.</summary>
    public const int SimulationFailed = 4;
}
