using System.Collections.Generic;

namespace SphFluid.Headless.Cli;

/// <summary>The arguments of <c>sphfluid bench</c>.</summary>
public sealed class BenchOptions
{
    public string ScenePath { get; set; }

    /// <summary>Particle counts to measure (the spawn spacing is scaled to reach each); empty = the scene as it is.</summary>
    public List<int> Particles { get; } = new();

    /// <summary>Timed sub-steps per particle count.</summary>
    public int Steps { get; set; } = 20;

    /// <summary>Untimed sub-steps first (shader compilation, caches, the fluid leaving its lattice).</summary>
    public int Warmup { get; set; } = 5;

    public string DeviceName { get; set; }
    public bool Help { get; set; }

    public const string HelpText =
@"sphfluid bench <scene.unity> [options]

Times the SPH pipeline on the scene: milliseconds per sub-step in total (wall clock and GPU) and per
pass (GPU timestamp ranges), as a Markdown table. The scene is checked as by simulate (a regular file
of at most 16 MiB that passes the integrity check), and every --particles count before the device opens.

Options:
  --particles N [N ...]    particle counts to measure, each in [64, 16777216] (also N,N,...);
                           the scene's spawn spacing and support radius are scaled to reach them
                           (default: the scene as it is)
  --steps N                timed sub-steps per count, in [1, 100000] (default 20)
  --warmup N               untimed sub-steps before timing, in [0, 100000] (default 5)
  --device NAME            Vulkan adapter whose name contains NAME (default: SPHFLUID_VULKAN_DEVICE, else the best)
  --help                   this text

Exit codes: 0 ok, 1 no Vulkan device or unexpected failure, 2 bad arguments, 3 scene errors,
4 the simulation went non-finite.";

    public static BenchOptions Parse(string[] args)
    {
        const string command = "bench";
        var options = new BenchOptions();
        var reader = new ArgumentReader(command, args);
        while (reader.MoveNext(out string token))
        {
            switch (token)
            {
                case "--help": case "-h": options.Help = true; break;
                case "--particles":
                    foreach (string v in reader.Values(token))
                        options.Particles.Add(ArgumentReader.ParseInt(command, token, v, 64, 16_777_216));
                    break;
                case "--steps": options.Steps = reader.Int(token, 1, 100_000); break;
                case "--warmup": options.Warmup = reader.Int(token, 0, 100_000); break;
                case "--device": options.DeviceName = reader.Value(token); break;
                default:
                    if (ArgumentReader.IsOption(token)) throw reader.Unknown(token);
                    if (options.ScenePath != null) throw reader.Unknown(token);
                    options.ScenePath = token;
                    break;
            }
        }
        reader.Finish();
        if (!options.Help && string.IsNullOrWhiteSpace(options.ScenePath))
            throw new UsageException($"{command}: the scene file argument is missing (e.g. sphfluid bench Assets/FluidDemo/Scenes/DamBreak.unity)");
        return options;
    }
}
