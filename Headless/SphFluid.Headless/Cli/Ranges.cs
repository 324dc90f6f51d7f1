using System.Globalization;

namespace SphFluid.Headless.Cli;

/// <summary>
/// The numeric ranges of the command line, one wording for all: a refusal names the command, the option, the
/// allowed range (with its unit) and what was given, so the reader can fix the call without reading the help.
/// </summary>
public static class Ranges
{
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

    /// <summary>True for a token that reads as an option rather than a value (a negative number is a value).</summary>
    public static bool LooksLikeOption(string token) =>
        token.StartsWith('-') && token.Length > 1 && !double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out _);

    public static string Format(double v) => v.ToString("G6", CultureInfo.InvariantCulture);
}
