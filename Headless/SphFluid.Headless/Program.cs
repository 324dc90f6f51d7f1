using System;
using System.IO;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Vulkan;

namespace SphFluid.Headless;

/// <summary>The <c>sphfluid</c> command line: simulate a Unity scene file headlessly, or benchmark it.</summary>
public static class Program
{
    public const string HelpText =
@"sphfluid: the SPH fluid of a Unity scene, run headless on Vulkan (lavapipe or a GPU)

  sphfluid simulate <scene.unity> [--seconds S | --steps N] [--out DIR] [--frames-every S] ...
  sphfluid bench <scene.unity> [--particles N ...] [--steps N] ...
  sphfluid <command> --help

Exit codes: 0 ok, 1 no Vulkan device or unexpected failure, 2 bad arguments, 3 scene errors,
4 the run became unhealthy: non-finite, particles lost, or faster, more compressed or more
energetic than the scene allows (the message names the time, phase and figure).";

    public static int Main(string[] args) => Run(args, Console.Out, Console.Error);

    /// <summary>Runs one command; every failure becomes a message on <paramref name="stderr"/> and an exit code.</summary>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        try
        {
            if (args.Length == 0 || args[0] is "--help" or "-h" or "help")
            {
                (args.Length == 0 ? stderr : stdout).WriteLine(HelpText);
                return args.Length == 0 ? ExitCodes.BadArguments : ExitCodes.Ok;
            }
            string[] rest = args[1..];
            switch (args[0])
            {
                case "simulate":
                {
                    var options = SimulateOptions.Parse(rest);
                    if (options.Help) { stdout.WriteLine(SimulateOptions.HelpText); return ExitCodes.Ok; }
                    return new SimulateRun(options, stdout, stderr).Execute();
                }
                case "bench":
                {
                    var options = BenchOptions.Parse(rest);
                    if (options.Help) { stdout.WriteLine(BenchOptions.HelpText); return ExitCodes.Ok; }
                    return new BenchRun(options, stdout, stderr).Execute();
                }
                default:
                    throw new UsageException($"unknown command '{args[0]}' (commands: simulate, bench; see sphfluid --help)");
            }
        }
        catch (UsageException e)
        {
            stderr.WriteLine($"sphfluid {e.Message}");
            return ExitCodes.BadArguments;
        }
        catch (SceneException e)
        {
            stderr.WriteLine($"sphfluid: scene error: {e.Message}");
            return ExitCodes.BadScene;
        }
        catch (VulkanUnavailableException e)
        {
            stderr.WriteLine($"sphfluid: no Vulkan device: {e.Message} (install Mesa's lavapipe: Headless/install-deps.sh, or set VK_LOADER_DRIVERS_SELECT)");
            return ExitCodes.Failure;
        }
        catch (Exception e)
        {
            // A message for the reader, not a type name; the exit code says it was not their input's fault.
            stderr.WriteLine($"sphfluid: unexpected failure: {e.Message}");
            return ExitCodes.Failure;
        }
    }
}
