using System;
using System.Collections.Generic;
using System.CommandLine;
using System.CommandLine.Parsing;
using System.Linq;
using SphFluid.Simulation;

namespace SphFluid.Headless.Cli;

/// <summary>
/// The kinds of option <c>sphfluid</c> takes, built on System.CommandLine with the project's own range checks: every
/// value is parsed by <see cref="Ranges"/>, so a bad one is refused with the option's name, range and unit, and a
/// missing value names the option instead of the library's generic arity message.
/// </summary>
public static class OptionKinds
{
    /// <summary>A real number in a range; <paramref name="valueName"/> is the placeholder the help shows.</summary>
    public static Option<double> Number(string command, string name, double min, double max, bool minExclusive, string unit,
        string valueName, string description, double? fallback = null)
    {
        var option = new Option<double>(name) { Description = description, HelpName = valueName, Arity = ArgumentArity.ZeroOrOne };
        option.CustomParser = r => Guard(r, command, name, text => Ranges.ParseDouble(command, name, text, min, max, minExclusive, unit));
        if (fallback.HasValue) option.DefaultValueFactory = _ => fallback.Value;
        return NeedsAValue(option, command, name);
    }

    /// <summary>A number that overrides a declared <see cref="FluidSettings"/> field: its range, unit and
    /// description come from the field's <see cref="SettingAttribute"/>, so the option refuses what the
    /// inspector and the scene reader refuse; <paramref name="note"/> follows in the help.</summary>
    public static Option<double> Setting(string command, string name, string field, string valueName, string note)
    {
        var d = Declaration(field);
        return Number(command, name, d.Min, d.Max, d.MinExclusive, d.Unit, valueName, SettingHelp(d, note, "in "));
    }

    /// <summary>A list of values of a declared <see cref="FluidSettings"/> field (<see cref="Setting"/>).</summary>
    public static Option<List<double>> SettingList(string command, string name, string field, string valueName, string note)
    {
        var d = Declaration(field);
        return List(command, name, valueName, SettingHelp(d, note, "each in "),
            text => Ranges.ParseDouble(command, name, text, d.Min, d.Max, d.MinExclusive, d.Unit));
    }

    static SettingAttribute Declaration(string field) =>
        SettingRules.Of(typeof(FluidSettings), field)
        ?? throw new ArgumentException($"FluidSettings.{field} has no [Setting] declaration", nameof(field));

    static string SettingHelp(SettingAttribute d, string note, string range) =>
        $"{d.Tooltip.TrimEnd('.')}, {range}{(d.MinExclusive ? "(" : "[")}{Ranges.Format(d.Min)}, {Ranges.Format(d.Max)}]{(d.Unit.Length > 0 ? " " + d.Unit : "")} ({note})";

    public static Option<int> Whole(string command, string name, int min, int max, string valueName, string description, int? fallback = null)
    {
        var option = new Option<int>(name) { Description = description, HelpName = valueName, Arity = ArgumentArity.ZeroOrOne };
        option.CustomParser = r => Guard(r, command, name, text => Ranges.ParseInt(command, name, text, min, max));
        if (fallback.HasValue) option.DefaultValueFactory = _ => fallback.Value;
        return NeedsAValue(option, command, name);
    }

    /// <summary>A word or path. A blank one (<c>--device ""</c>) is refused: taken as given, the run went ahead on the
    /// best adapter, as if the option had been left out.</summary>
    public static Option<string> Text(string command, string name, string valueName, string description)
    {
        var option = new Option<string>(name) { Description = description, HelpName = valueName, Arity = ArgumentArity.ZeroOrOne };
        option.CustomParser = r => Guard(r, command, name, text => string.IsNullOrWhiteSpace(text)
            ? throw new UsageException($"{command}: option {name} needs a {valueName} (was {(text.Length == 0 ? "empty" : "blank")})")
            : text);
        return option;
    }

    /// <summary>One of a fixed set of words (case-insensitive); the refusal lists them.</summary>
    public static Option<T> Choice<T>(string command, string name, IReadOnlyDictionary<string, T> words, string description)
    {
        string allowed = string.Join(" | ", words.Keys);
        var option = new Option<T>(name) { Description = description, HelpName = string.Join("|", words.Keys), Arity = ArgumentArity.ZeroOrOne };
        option.CustomParser = r => Guard(r, command, name, text =>
        {
            foreach (var pair in words)
                if (string.Equals(pair.Key, text, StringComparison.OrdinalIgnoreCase)) return pair.Value;
            throw new UsageException($"{command}: {name} must be one of {allowed} (was '{text}')");
        });
        return option;
    }

    /// <summary>A list of values (<c>--particles 4000 16000</c> or <c>4000,16000</c>); an empty entry is refused by
    /// name instead of silently running with fewer values, and a value given twice (<c>1 1.0</c>, or the option repeated)
    /// instead of running its configuration twice.</summary>
    public static Option<List<T>> List<T>(string command, string name, string valueName, string description, Func<string, T> parse)
    {
        var option = new Option<List<T>>(name)
        {
            Description = description, HelpName = valueName, Arity = ArgumentArity.ZeroOrMore, AllowMultipleArgumentsPerToken = true,
        };
        option.CustomParser = r =>
        {
            if (r.Tokens.Count == 0)
            {
                r.AddError($"{command}: option {name} needs a value");
                return null;
            }
            try
            {
                var values = new List<T>();
                foreach (string text in r.Tokens.SelectMany(t => t.Value.Split(',', StringSplitOptions.TrimEntries)))
                {
                    T value = parse(text);
                    if (values.Contains(value))
                        throw new UsageException($"{command}: {name} lists {text} twice; give each value once");
                    values.Add(value);
                }
                return values;
            }
            catch (UsageException e)
            {
                r.AddError(e.Message);
                return null;
            }
        };
        return option;
    }

    /// <summary>The values of a list option, or null when it was not given (the library reads an absent list as an
    /// empty one). A clean parse never leaves a given list without its values: an empty or bad one is refused first.</summary>
    public static List<T>? Given<T>(ParseResult result, Option<List<T>> option) =>
        result.GetResult(option) != null ? result.GetValue(option) : null;

    /// <summary>A switch: takes no value (<c>--quiet=yes</c> is refused before parsing, see <see cref="SphfluidCommandLine"/>).</summary>
    public static Option<bool> Flag(string name, string description) =>
        new(name) { Description = description, Arity = ArgumentArity.Zero };

    /// <summary>The scene file, the one positional argument. An unknown option standing where it goes is named as such
    /// by <see cref="SphfluidCommandLine"/>, which alone sees whether it came after <c>--</c> (a scene file whose name
    /// starts with a dash).</summary>
    public static Argument<string> Scene() =>
        new("scene.unity") { Description = "the Unity scene file (.unity)", Arity = ArgumentArity.ZeroOrOne };

    /// <summary>The scene argument of a parse, refused when it is missing, with an example of the command.</summary>
    public static string RequiredScene(ParseResult r, Argument<string> scene, string command, string example)
    {
        string? path = r.GetValue(scene);
        if (string.IsNullOrWhiteSpace(path))
            throw new UsageException($"{command}: the scene file argument is missing (e.g. sphfluid {command} {example})");
        return path;
    }

    /// <summary>Refuses the option written without its value. The parser below sees that case only for an option
    /// without a default: with one, the library reads a bare <c>--seconds</c> as the default, and the run went ahead
    /// on a value the user never gave.</summary>
    static Option<T> NeedsAValue<T>(Option<T> option, string command, string name)
    {
        option.Validators.Add(r =>
        {
            if (!r.Implicit && r.Tokens.Count == 0 && r.Errors.Count() == 0)
                r.AddError($"{command}: option {name} needs a value");
        });
        return option;
    }

    /// <summary>Parses the option's last token; a refusal is recorded on the result (the parse then fails) and the
    /// value returned with it is never read.</summary>
    static T? Guard<T>(ArgumentResult result, string command, string name, Func<string, T> parse)
    {
        if (result.Tokens.Count == 0)
        {
            result.AddError($"{command}: option {name} needs a value");
            return default;
        }
        try
        {
            return parse(result.Tokens[^1].Value);
        }
        catch (UsageException e)
        {
            result.AddError(e.Message);
            return default;
        }
    }
}
