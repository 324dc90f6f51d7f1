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
        object defaults = Activator.CreateInstance(settingsType);
        var table = new StringBuilder();
        table.Append("| group | field | unit | range | default | meaning |\n|---|---|---|---|---|---|\n");
        foreach (var setting in SettingRules.Declared(settingsType))
        {
            var d = setting.Declaration;
            string range = string.IsNullOrEmpty(d.Unit) ? d.RangeText : d.RangeText[..^(d.Unit.Length + 1)];
            if (setting.Field.FieldType == typeof(SettingVector)) range = "magnitude in " + range;
            if (setting.Field.FieldType.IsEnum)
                range = string.Join(", ", Enum.GetValues(setting.Field.FieldType).Cast<object>().Select(v => $"{Convert.ToInt64(v, CultureInfo.InvariantCulture)} = {v}"));
            table.Append($"| {d.Group} | `{setting.Field.Name}` | {d.Unit} | {range} | {Value(setting.Field.GetValue(defaults))} | {d.Tooltip} |\n");
        }
        return table.ToString();
    }

    static string Value(object value) => value switch
    {
        float f => Number(f),
        int i => i.ToString(CultureInfo.InvariantCulture),
        SettingVector v => $"({Number(v.x)}, {Number(v.y)}, {Number(v.z)})",
        Enum e => $"{Convert.ToInt64(e, CultureInfo.InvariantCulture)} ({e})",
        _ => Convert.ToString(value, CultureInfo.InvariantCulture),
    };

    static string Number(double v) => v.ToString("G6", CultureInfo.InvariantCulture);
}
