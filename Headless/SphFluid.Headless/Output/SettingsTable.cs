using System;
using System.Globalization;
using System.Linq;
using System.Text;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// The README's table of a settings class, written from its declarations (<see cref="SettingAttribute"/>): field,
/// unit, range, default and meaning. A test holds the README to it, so the table cannot drift from the code.
/// </summary>
public static class SettingsTable
{
    public static string Markdown(Type settingsType)
    {
        object defaults = Activator.CreateInstance(settingsType)
            ?? throw new ArgumentException($"{settingsType.Name} has no instance to read its defaults from", nameof(settingsType));
        var table = new StringBuilder();
        table.Append("| group | field | unit | range | default | meaning |\n|---|---|---|---|---|---|\n");
        foreach (var setting in SettingRules.DeclaredPaths(settingsType))
        {
            var d = setting.Declaration;
            var type = setting.Field.FieldType;
            string range = string.IsNullOrEmpty(d.Unit) ? d.RangeText : d.RangeText[..^(d.Unit.Length + 1)];
            if (type == typeof(SettingVector)) range = "magnitude in " + range;
            else if (type == typeof(SettingColor)) range = "each channel in " + range;
            else if (type == typeof(string)) range = "printable, length in " + range;
            else if (type.IsEnum)
                range = string.Join(", ", Enum.GetValues(type).Cast<object>().Select(v => $"{Convert.ToInt64(v, CultureInfo.InvariantCulture)} = {v}"));
            table.Append($"| {d.Group} | `{setting.Path}` | {d.Unit} | {range} | {Value(setting.GetValue(defaults))} | {d.Tooltip} |\n");
        }
        return table.ToString();
    }

    static string Value(object? value) => value switch
    {
        float f => Number(f),
        int i => i.ToString(CultureInfo.InvariantCulture),
        SettingVector v => $"({Number(v.x)}, {Number(v.y)}, {Number(v.z)})",
        SettingColor c => $"({Number(c.r)}, {Number(c.g)}, {Number(c.b)}, {Number(c.a)})",
        Enum e => $"{Convert.ToInt64(e, CultureInfo.InvariantCulture)} ({e})",
        _ => Convert.ToString(value, CultureInfo.InvariantCulture) ?? "",
    };

    static string Number(double v) => v.ToString("G6", CultureInfo.InvariantCulture);
}
