using System;
using System.Collections.Generic;
using System.Globalization;

namespace SphFluid.Headless.Cli;

/// <summary>
/// Walks the arguments of one command: <c>--name value</c> or <c>--name=value</c> options, flags and
/// positionals. Every refusal is a <see cref="UsageException"/> naming the argument and its allowed range.
/// </summary>
public sealed class ArgumentReader
{
    readonly string _command;
    readonly string[] _args;
    int _next;
    string _inlineValue;

    public ArgumentReader(string command, string[] args)
    {
        _command = command;
        _args = args ?? Array.Empty<string>();
    }

    /// <summary>Advances to the next argument; false at the end.</summary>
    public bool MoveNext(out string token)
    {
        if (_inlineValue != null)
            throw new UsageException($"{_command}: option {_args[_next - 1].Split('=')[0]} takes no value (was '{_inlineValue}')");
        if (_next >= _args.Length)
        {
            token = null;
            return false;
        }
        token = _args[_next++];
        int eq = token.StartsWith("--", StringComparison.Ordinal) ? token.IndexOf('=') : -1;
        if (eq > 0)
        {
            _inlineValue = token[(eq + 1)..];
            token = token[..eq];
        }
        return true;
    }

    /// <summary>Refuses a value left over from the last <c>--flag=value</c> of a flag that takes none.</summary>
    public void Finish()
    {
        if (_inlineValue != null)
            throw new UsageException($"{_command}: option {_args[_next - 1].Split('=')[0]} takes no value (was '{_inlineValue}')");
    }

    public static bool IsOption(string token) => token.StartsWith('-') && token.Length > 1 && !double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out _);

    public string Value(string option)
    {
        if (_inlineValue != null)
        {
            string v = _inlineValue;
            _inlineValue = null;
            return v;
        }
        if (_next >= _args.Length || IsOption(_args[_next]))
            throw new UsageException($"{_command}: option {option} needs a value");
        return _args[_next++];
    }

    /// <summary>Values up to the next option (at least one): <c>--particles 4000 16000</c> or <c>--particles 4000,16000</c>.
    /// Empty entries (<c>--particles ""</c>, <c>4000,,16000</c>) are kept, so the caller refuses them by name instead of
    /// silently running with fewer values or none.</summary>
    public List<string> Values(string option)
    {
        var values = new List<string>();
        foreach (string v in Value(option).Split(',', StringSplitOptions.TrimEntries)) values.Add(v);
        while (_next < _args.Length && !IsOption(_args[_next]))
            foreach (string v in _args[_next++].Split(',', StringSplitOptions.TrimEntries)) values.Add(v);
        return values;
    }

    public double Double(string option, double min, double max, bool minExclusive, string unit) =>
        ParseDouble(_command, option, Value(option), min, max, minExclusive, unit);

    public int Int(string option, int min, int max) => ParseInt(_command, option, Value(option), min, max);

    public static double ParseDouble(string command, string option, string text, double min, double max, bool minExclusive, string unit)
    {
        string range = $"{(minExclusive ? "(" : "[")}{Format(min)}, {Format(max)}]{(unit.Length > 0 ? " " + unit : "")}";
        if (!double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) || !double.IsFinite(value))
            throw new UsageException($"{command}: {option} must be a number in {range} (was '{text}')");
        if (value < min || value > max || (minExclusive && value == min))
            throw new UsageException($"{command}: {option} must be in {range} (was {Format(value)})");
        return value;
    }

    public static int ParseInt(string command, string option, string text, int min, int max)
    {
        if (!long.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, out long value))
            throw new UsageException($"{command}: {option} must be a whole number in [{min}, {max}] (was '{text}')");
        if (value < min || value > max)
            throw new UsageException($"{command}: {option} must be in [{min}, {max}] (was {value})");
        return (int)value;
    }

    public UsageException Unknown(string token) => new(IsOption(token)
        ? $"{_command}: unknown option {token} (see sphfluid {_command} --help)"
        : $"{_command}: unexpected argument '{token}' (see sphfluid {_command} --help)");

    static string Format(double v) => v.ToString("G6", CultureInfo.InvariantCulture);
}
