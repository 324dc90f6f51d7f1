using System;
using System.Collections.Generic;
using System.CommandLine;
using System.CommandLine.Help;
using System.CommandLine.Invocation;
using System.CommandLine.Parsing;
using System.IO;
using System.Linq;

namespace SphFluid.Headless.Cli;

/// <summary>
/// The <c>sphfluid</c> command line on System.CommandLine: the commands, their generated help and <c>--version</c>.
/// Parse errors are not printed by the library: the first one becomes a <see cref="UsageException"/> worded as the
/// project words its refusals (command, option, allowed range, what was given), so every mistake exits 2 with one line.
/// </summary>
public sealed class SphfluidCommandLine
{
    public const string ExitCodesText =
@"Exit codes: 0 ok, 1 no Vulkan device, a file error (a full disk) or an unexpected failure,
2 bad arguments, 3 scene errors, 4 the run became unhealthy: non-finite, particles lost, or
faster, more compressed or more energetic than the scene allows (the message names the time,
phase and figure).";

    public const string DeviceHelp = "Vulkan adapter whose name contains NAME; lavapipe finds Mesa's CPU adapter, llvmpipe (default: SPHFLUID_VULKAN_DEVICE, else the best)";

    const string About =
@"sphfluid: the SPH fluid of a Unity scene, run headless on Vulkan (lavapipe or a GPU)

  sphfluid simulate <scene.unity> [--seconds S | --steps N] [--out DIR] [--frames-every S] ...
  sphfluid bench <scene.unity> [--particles N ...] [--steps N] ...
  sphfluid study <scene.unity> [--quick] [--out DIR] ...
  sphfluid <command> --help

" + ExitCodesText;

    /// <summary>Help lines are wrapped here whatever the terminal (and in redirected output).</summary>
    const int HelpWidth = 120;

    public RootCommand Root { get; }
    public SimulateCommand Simulate { get; } = new();
    public BenchCommand Bench { get; } = new();
    public StudyCommand Study { get; } = new();

    public SphfluidCommandLine()
    {
        Root = new RootCommand(About) { Simulate, Bench, Study };
        foreach (var help in Root.Options.OfType<HelpOption>())
            if (help.Action is HelpAction action)
            {
                action.MaxWidth = HelpWidth;
                help.Action = new DetailedHelp(action, Details);
            }
    }

    IEnumerable<Command> Commands => Root.Subcommands;

    /// <summary>Each command's long text, printed after its generated help; the command list shows its one-line description.</summary>
    IReadOnlyDictionary<Command, string> Details => new Dictionary<Command, string>
    {
        [Simulate] = SimulateCommand.Details,
        [Bench] = BenchCommand.Details,
        [Study] = StudyCommand.Details,
    };

    /// <summary>The library's help, then the command's details (what it reads, measures and writes; exit codes).</summary>
    sealed class DetailedHelp(HelpAction generated, IReadOnlyDictionary<Command, string> details) : SynchronousCommandLineAction
    {
        public override int Invoke(ParseResult parseResult)
        {
            generated.Invoke(parseResult);
            var output = parseResult.InvocationConfiguration.Output;
            if (details.TryGetValue(parseResult.CommandResult.Command, out string? text))
            {
                output.WriteLine(text);
                output.WriteLine();
            }
            return ExitCodes.Ok;
        }
    }

    /// <summary>Parses a whole command line. Help is returned even beside other mistakes (the reader asked for it);
    /// otherwise the first mistake is thrown.</summary>
    public ParseResult Parse(string[] args)
    {
        RefuseFlagValues(args);
        var result = Root.Parse(args);
        if (result.Action is DetailedHelp) return result;
        string? error = FirstError(result);
        if (error != null) throw new UsageException(error);
        return result;
    }

    /// <summary>The options of one command without running it (tests and scripts that build runs themselves).</summary>
    public static T ParseOnly<T>(string command, string[] args) where T : class
    {
        var cli = new SphfluidCommandLine();
        var result = cli.Parse(new[] { command }.Concat(args).ToArray());
        // A help request is answered before the options are checked, so it holds none to read (a mistake beside it stays).
        if (result.Action is DetailedHelp)
            throw new UsageException($"{command}: --help asks for the help text, which has no options to read (see sphfluid {command} --help)");
        return cli.Read(result) as T
            ?? throw new ArgumentException($"'{command}' is not the sphfluid command that reads {typeof(T).Name}", nameof(command));
    }

    /// <summary>The options object of the parsed command (SimulateOptions, BenchOptions ...), null for the root.</summary>
    public object? Read(ParseResult result)
    {
        var command = result.CommandResult.Command;
        if (command == Simulate) return Simulate.Read(result);
        if (command == Bench) return Bench.Read(result);
        if (command == Study) return Study.Read(result);
        return null;
    }

    public int WriteHelp(TextWriter writer, params string[] path)
    {
        var result = Root.Parse(path.Append("--help").ToArray());
        return result.Invoke(new InvocationConfiguration { Output = writer, Error = writer, EnableDefaultExceptionHandler = false });
    }

    /// <summary>A switch given a value (<c>--quiet=yes</c>, <c>--help=all</c>) is refused by name; the library would only
    /// see an odd token, or show the help as if no value were there. Past <c>--</c> every token is an argument.</summary>
    void RefuseFlagValues(string[] args)
    {
        var command = Commands.FirstOrDefault(c => args.Length > 0 && c.Name == args[0]);
        // Before a command only the root's switches stand (sphfluid --help=x); the command's own come after it.
        var given = command == null ? args.TakeWhile(a => Commands.All(c => c.Name != a)) : args.Skip(1);
        // The help option is the root's, inherited by every command (Recursive), so not among the command's own options.
        var switches = (command?.Options ?? Enumerable.Empty<Option>()).Concat(Root.Options.Where(o => command == null || o.Recursive))
            .Where(o => o.Arity.MaximumNumberOfValues == 0).ToList();
        foreach (string arg in given.TakeWhile(a => a != "--"))
        {
            int eq = arg.StartsWith("--", System.StringComparison.Ordinal) ? arg.IndexOfAny(new[] { '=', ':' }) : -1;
            if (eq < 0) continue;
            string name = arg[..eq];
            if (switches.Any(o => o.Name == name))
                throw new UsageException(command == null
                    ? $"refuses a value for {name}, which takes none (was '{arg[(eq + 1)..]}')"
                    : $"{command.Name}: option {name} takes no value (was '{arg[(eq + 1)..]}')");
        }
    }

    string? FirstError(ParseResult result)
    {
        var command = result.CommandResult.Command;
        string? name = command == Root ? null : command.Name;
        // The project's own refusals first (they name the option and range), then unknown tokens: the library's
        // "Unrecognized command or argument" says less than what the token is.
        var own = result.Errors.FirstOrDefault(e => name != null && e.Message.StartsWith(name + ":", System.StringComparison.Ordinal));
        if (own != null) return own.Message;
        if (name != null && OptionTakenForTheScene(result) is string stranger)
            return stranger.EndsWith(".unity", StringComparison.OrdinalIgnoreCase)
                ? $"{name}: unknown option {stranger}; a scene file whose name starts with '-' goes after '--' (sphfluid {name} [options] -- {stranger})"
                : UnknownOption.Message(command, stranger);
        if (result.UnmatchedTokens.Count > 0)
        {
            // An unknown option before the scene is taken for the scene, and the scene then is the odd one out.
            string token = result.Tokens.FirstOrDefault(t => t.Type == TokenType.Argument && Ranges.LooksLikeOption(t.Value) && !Literal(result, t))?.Value
                ?? result.UnmatchedTokens[0];
            // Past "--" every token is an argument, an option's name too (sphfluid simulate -- scene.unity --seconds 1).
            if (name != null && result.Tokens.Any(t => t.Value == token && Literal(result, t)))
                return $"{name}: unexpected argument '{token}' after '--', which makes every later token an argument; " +
                    $"give options before it (see sphfluid {name} --help)";
            // Past a "--" before any command, a command's name is an argument too (sphfluid -- simulate x.unity).
            if (name == null && Commands.Any(c => c.Name == token) && result.Tokens.Any(t => t.Value == token && Literal(result, t)))
                return $"has no command before '--', which makes every later token an argument, '{token}' too; " +
                    $"write the command first (sphfluid {token} [options] -- scene.unity)";
            // An option before the command (sphfluid --seconds 1 simulate) is the root's to refuse: the command has it.
            if (name == null || BeforeTheCommand(result, token))
                return Ranges.LooksLikeOption(token)
                    ? $"has no option {token} of its own; a command's options follow the command (commands: {string.Join(", ", Commands.Select(c => c.Name))}; see sphfluid --help)"
                    : $"has no command '{token}' (commands: {string.Join(", ", Commands.Select(c => c.Name))}; see sphfluid --help)";
            return Ranges.LooksLikeOption(token)
                ? UnknownOption.Message(command, token)
                : $"{name}: unexpected argument '{token}' (see sphfluid {name} --help)";
        }
        if (result.Errors.Count == 0) return null;
        // The library's "Option '--out' expects a single argument but 2 were provided" does not say which were given.
        var repeated = result.CommandResult.Children.OfType<OptionResult>()
            .FirstOrDefault(o => o.Option.Arity.MaximumNumberOfValues == 1 && o.Tokens.Count > 1);
        if (name != null && repeated != null)
        {
            string values = string.Join(", ", repeated.Tokens.Select(t => $"'{t.Value}'"));
            return $"{name}: {repeated.Option.Name} was given {repeated.Tokens.Count} times ({values}); give it once";
        }
        string message = result.Errors[0].Message;
        if (name == null) return $"refuses the command line: {message} (commands: {string.Join(", ", Commands.Select(c => c.Name))}; see sphfluid --help)";
        return message.StartsWith(name + ":", System.StringComparison.Ordinal) ? message : $"{name}: {message}";
    }

    /// <summary>The token read as the scene that reads as an option (an unknown one takes the scene's place), or null.
    /// After <c>--</c> every token is an argument, so a scene file named <c>-take2.unity</c> can be given there.</summary>
    static string? OptionTakenForTheScene(ParseResult result)
    {
        var scene = result.CommandResult.Children.OfType<ArgumentResult>().FirstOrDefault()?.Tokens.FirstOrDefault();
        return scene != null && Ranges.LooksLikeOption(scene.Value) && !Literal(result, scene) ? scene.Value : null;
    }

    /// <summary>Whether <paramref name="token"/> comes after <c>--</c>, and so is an argument whatever it reads as.</summary>
    static bool Literal(ParseResult result, Token token) =>
        result.Tokens.TakeWhile(t => !ReferenceEquals(t, token)).Any(t => t.Type == TokenType.DoubleDash);

    static bool BeforeTheCommand(ParseResult result, string token)
    {
        var tokens = result.Tokens.ToList();
        int command = tokens.FindIndex(t => t.Type == TokenType.Command);
        int at = tokens.FindIndex(t => t.Value == token);
        return command >= 0 && at >= 0 && at < command;
    }
}
