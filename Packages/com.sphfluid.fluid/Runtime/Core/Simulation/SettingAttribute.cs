using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The one declaration of a setting's meaning: its range, unit, inspector group and tooltip sit on the field, and
    /// its default is the field's initializer. The validation (<see cref="SettingRules"/>), the inspector's drawer, the
    /// headless scene reader and the README's table all read it, so a new setting is one annotated field.
    /// </summary>
    /// <remarks>Engine-free (the core has no engine references): the Unity inspector reads it through an editor drawer
    /// rather than through Unity's own Range and Tooltip attributes.</remarks>
    [AttributeUsage(AttributeTargets.Field, AllowMultiple = false)]
    public sealed class SettingAttribute : Attribute
    {
        public SettingAttribute(string group, double min, double max, string unit, string tooltip)
        {
            Group = group;
            Min = min;
            Max = max;
            Unit = unit;
            Tooltip = tooltip;
        }

        /// <summary>Inspector header the setting is listed under.</summary>
        public string Group { get; }

        /// <summary>Smallest allowed value (of the magnitude, for a vector; of each channel, for a colour; of the length,
        /// for a text).</summary>
        public double Min { get; }

        /// <summary>Largest allowed value (of the magnitude, for a vector; of each channel, for a colour; of the length,
        /// for a text).</summary>
        public double Max { get; }

        /// <summary>The minimum itself is refused: the range is (Min, Max].</summary>
        public bool MinExclusive { get; set; }

        /// <summary>SI unit, e.g. "m", "Pa", "1/s"; empty for a number without unit.</summary>
        public string Unit { get; }

        /// <summary>What the setting does and when to change it; the inspector's tooltip.</summary>
        public string Tooltip { get; }

        /// <summary>The range as the error messages and the README write it: "[1, 1e+09] Pa", "(0, 1]".</summary>
        public string RangeText
        {
            get
            {
                string range = (MinExclusive ? "(" : "[") + Bound(Min) + ", " + Bound(Max) + "]";
                return string.IsNullOrEmpty(Unit) ? range : range + " " + Unit;
            }
        }

        // Whole bounds written whole (16777216, not 1.67772E+07), and the int limits of an "any whole number" range
        // too; larger ones as the float messages write them (1E+09). The validation's messages quote this text.
        static string Bound(double v) =>
            Math.Floor(v) == v && (Math.Abs(v) < 1e8 || v == int.MinValue || v == int.MaxValue)
                ? ((long)v).ToString(System.Globalization.CultureInfo.InvariantCulture) : ValidationRules.Format(v);
    }
}
