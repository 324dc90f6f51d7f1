using System;
using System.CommandLine;
using System.IO;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Vulkan;

namespace SphFluid.Headless;

/// <summary>The <c>sphfluid</c> command line: simulate a Unity scene file headlessly, or benchmark it.</summary>
public static class Program
{
    public static int Main(string[] args) => Run(args, Console.Out, Console.Error);

    /// <summary>Runs one command; every failure becomes a message on <paramref name="stderr"/> and an exit code.</summary>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        try
        {
            var cli = new SphfluidCommandLine();
            if (args.Length == 0)
            {
                cli.WriteHelp(stderr);
                return ExitCodes.BadArguments;
            }
            var result = cli.Parse(args);
            // Help and --version: the library's own actions.
            if (result.Action != null)
                return result.Invoke(new InvocationConfiguration { Output = stdout, Error = stderr, EnableDefaultExceptionHandler = false });
            switch (cli.Read(result))
            {
                case SimulateOptions simulate: return new SimulateRun(simulate, stdout, stderr).Execute();
                case BenchOptions bench: return new BenchRun(bench, stdout, stderr).Execute();
                case StudyOptions study: return new StudyRun(study, stdout, stderr).Execute();
                default: throw new UsageException("needs a command (commands: simulate, bench, study; see sphfluid --help)");
            }
        }
        catch (UsageException e)
        {
            // A command's message starts with its name ("simulate: --seconds must be ..."), the root's with a verb
            // ("has no command 'render'"): either follows the program's name.
            stderr.WriteLine($"sphfluid {Shown(e)}");
            return ExitCodes.BadArguments;
        }
        catch (SceneException e)
        {
            stderr.WriteLine($"sphfluid: scene error: {Shown(e)}");
            return ExitCodes.BadScene;
        }
        catch (VulkanUnavailableException e)
        {
            // Where adapters were found but none by the name asked for, installing one would not help.
            stderr.WriteLine($"sphfluid: no Vulkan device: {Shown(e)}" +
                (e.Adapters == null ? " (install Mesa's lavapipe: Headless/install-deps.sh, or set VK_LOADER_DRIVERS_SELECT)" : ""));
            return ExitCodes.Failure;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // A full disk, or a folder taken away or made read-only mid-run: the environment's failure, not the
            // program's, and the message names the file.
            stderr.WriteLine($"sphfluid: file error, the command stopped: {Shown(e)}");
            return ExitCodes.Failure;
        }
        catch (Exception e)
        {
            // A message for the reader, not a type name; the exit code says it was not their input's fault.
            stderr.WriteLine($"sphfluid: unexpected failure: {Shown(e)}");
            return ExitCodes.Failure;
        }
    }

    /// <summary>A message quotes what the user gave (a scene's names and values, a binary file's first bytes, an
    /// argument, a path) and so may hold control characters; they are shown escaped, and only the message's own line
    /// breaks stay.</summary>
    static string Shown(Exception e) => PrintableText.Escape(e.Message, keepLineBreaks: true);
}
