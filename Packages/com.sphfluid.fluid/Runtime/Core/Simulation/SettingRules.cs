using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;

namespace SphFluid.Simulation
{
    /// <summary>A declared setting: the field and its <see cref="SettingAttribute"/>.</summary>
    public readonly struct DeclaredSetting
    {
        public DeclaredSetting(FieldInfo field, SettingAttribute declaration)
        {
            Field = field;
            Declaration = declaration;
        }

        public FieldInfo Field { get; }

        public SettingAttribute Declaration { get; }
    }

    /// <summary>
    /// Reads <see cref="SettingAttribute"/> declarations: lists a settings class's declared fields in declaration order
    /// and checks a value against its declared range, with the wording every other validation uses.
    /// </summary>
    public static class SettingRules
    {
        static readonly Dictionary<Type, DeclaredSetting[]> Cache = new Dictionary<Type, DeclaredSetting[]>();

        /// <summary>Every public field of <paramref name="type"/> with a declaration, in source order.</summary>
        public static IReadOnlyList<DeclaredSetting> Declared(Type type)
        {
            lock (Cache)
            {
                if (!Cache.TryGetValue(type, out var fields))
                {
                    fields = type.GetFields(BindingFlags.Public | BindingFlags.Instance)
                        .OrderBy(f => f.MetadataToken)
                        .Select(f => new DeclaredSetting(f, f.GetCustomAttribute<SettingAttribute>()))
                        .Where(s => s.Declaration != null)
                        .ToArray();
                    Cache[type] = fields;
                }
                return fields;
            }
        }

        /// <summary>The declaration of <paramref name="field"/> of <paramref name="type"/>, or null.</summary>
        public static SettingAttribute Of(Type type, string field)
        {
            foreach (var s in Declared(type))
                if (s.Field.Name == field) return s.Declaration;
            return null;
        }

        /// <summary>Checks one declared field of <paramref name="settings"/>; false (and an error) when out of range.</summary>
        public static bool Validate(object settings, List<ValidationError> errors, string owner, string path, string field)
        {
            var info = settings.GetType().GetField(field, BindingFlags.Public | BindingFlags.Instance);
            var d = info?.GetCustomAttribute<SettingAttribute>();
            if (d == null) throw new ArgumentException($"{settings.GetType().Name}.{field} has no [Setting] declaration", nameof(field));
            object value = info.GetValue(settings);
            switch (value)
            {
                case float f:
                    if (d.MinExclusive && d.Min == 0) return ValidationRules.Positive(errors, owner, path, field, f, (float)d.Max, d.Unit);
                    if (d.MinExclusive) throw new NotSupportedException($"{settings.GetType().Name}.{field}: an exclusive minimum must be 0");
                    return ValidationRules.InRange(errors, owner, path, field, f, (float)d.Min, (float)d.Max, d.Unit);
                case int i:
                    return ValidationRules.InRange(errors, owner, path, field, i, (int)d.Min, (int)d.Max, d.Unit);
                case SettingVector v:
                    if (d.Min == 0 && !d.MinExclusive) return ValidationRules.Finite(errors, owner, path, field, v, (float)d.Max, d.Unit);
                    float length = v.Length();
                    if (ValidationRules.IsFinite(length) && (d.MinExclusive ? length > d.Min : length >= d.Min) && length <= d.Max) return true;
                    errors.Add(new ValidationError(path + field, $"{owner}: {field} must be finite with magnitude in {d.RangeText} (was {v})"));
                    return false;
                case Enum e:
                    if (Enum.IsDefined(e.GetType(), e)) return true;
                    errors.Add(new ValidationError(path + field, $"{owner}: {field} must be one of {string.Join(", ", Names(e.GetType()))} (was {Convert.ToInt64(e)})"));
                    return false;
                default:
                    throw new NotSupportedException($"{settings.GetType().Name}.{field}: settings of type {info.FieldType.Name} are not supported");
            }
        }

        static IEnumerable<string> Names(Type enumType) =>
            Enum.GetValues(enumType).Cast<object>().Select(v => $"{Convert.ToInt64(v)} ({v})");
    }
}
