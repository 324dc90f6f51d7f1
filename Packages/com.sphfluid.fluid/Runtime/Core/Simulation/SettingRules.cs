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

    /// <summary>A declared setting reached through the declared blocks that hold it (<see cref="SettingRules.DeclaredPaths"/>).</summary>
    public sealed class SettingPath
    {
        readonly FieldInfo[] _chain;

        internal SettingPath(FieldInfo[] chain, SettingAttribute declaration)
        {
            _chain = chain;
            Declaration = declaration;
            Path = string.Join(".", chain.Select(f => f.Name));
        }

        /// <summary>Dotted field names from the root type, e.g. "Phase.RestDensity" or "Jitter".</summary>
        public string Path { get; }

        public FieldInfo Field => _chain[_chain.Length - 1];

        public SettingAttribute Declaration { get; }

        /// <summary>The object of <paramref name="root"/> that holds the field: the root itself or one of its blocks.</summary>
        public object Owner(object root)
        {
            object owner = root;
            for (int i = 0; i < _chain.Length - 1 && owner != null; i++) owner = _chain[i].GetValue(owner);
            return owner;
        }

        public object GetValue(object root) => Field.GetValue(Owner(root));

        public void SetValue(object root, object value) => Field.SetValue(Owner(root), value);
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

        /// <summary>
        /// Every declared setting of <paramref name="type"/> and of the declared blocks it holds (a public field, without
        /// a declaration of its own, whose class declares settings: <see cref="FluidBlock.Phase"/>), depth first
        /// in source order, each with its dotted path from <paramref name="type"/> ("Phase.RestDensity"). The path is the
        /// serialized name Unity writes and the headless scene reader reads.
        /// </summary>
        public static IReadOnlyList<SettingPath> DeclaredPaths(Type type)
        {
            lock (PathCache)
            {
                if (!PathCache.TryGetValue(type, out var paths))
                {
                    var list = new List<SettingPath>();
                    Walk(type, new List<FieldInfo>(), list);
                    paths = list.ToArray();
                    PathCache[type] = paths;
                }
                return paths;
            }
        }

        static readonly Dictionary<Type, SettingPath[]> PathCache = new Dictionary<Type, SettingPath[]>();

        static void Walk(Type type, List<FieldInfo> blocks, List<SettingPath> into)
        {
            foreach (var field in type.GetFields(BindingFlags.Public | BindingFlags.Instance).OrderBy(f => f.MetadataToken))
            {
                var declaration = field.GetCustomAttribute<SettingAttribute>();
                var chain = new List<FieldInfo>(blocks) { field };
                if (declaration != null) into.Add(new SettingPath(chain.ToArray(), declaration));
                else if (IsBlock(field.FieldType)) Walk(field.FieldType, chain, into);
            }
        }

        /// <summary>A class that declares settings of its own, serialized inline where a field holds it.</summary>
        public static bool IsBlock(Type type) => type.IsClass && type != typeof(string) && Declared(type).Count > 0;

        /// <summary>Checks one declared field of <paramref name="settings"/>; false (and an error) when out of range.
        /// The message quotes the declared range as <see cref="SettingAttribute.RangeText"/> writes it.</summary>
        public static bool Validate(object settings, List<ValidationError> errors, string owner, string path, string field)
        {
            var info = settings.GetType().GetField(field, BindingFlags.Public | BindingFlags.Instance);
            var d = info?.GetCustomAttribute<SettingAttribute>();
            if (d == null) throw new ArgumentException($"{settings.GetType().Name}.{field} has no [Setting] declaration", nameof(field));
            object value = info.GetValue(settings);
            if (info.FieldType == typeof(string))
            {
                string text = value as string ?? "";
                int length = text.Length;
                if (length < d.Min || length > d.Max)
                {
                    errors.Add(new ValidationError(path + field, owner, length == 0 && d.Min >= 1
                        ? $"{field} must be non-empty, of length in {d.RangeText} (was empty)"
                        : $"{field} must have a length in {d.RangeText} (was {length})"));
                    return false;
                }
                // A name is printed on consoles, in logs and in the readout: a control character in it would act there.
                int unprintable = PrintableText.FirstUnprintable(text);
                if (unprintable < 0) return true;
                errors.Add(new ValidationError(path + field,
                    owner, $"{field} must be printable text, without control characters (was '{PrintableText.Escape(text)}', " +
                    $"U+{(int)text[unprintable]:X4} at character {unprintable + 1})"));
                return false;
            }
            switch (value)
            {
                case float f:
                    if (ValidationRules.IsFinite(f) && Above(f, d) && f <= (float)d.Max) return true;
                    errors.Add(new ValidationError(path + field, owner, $"{field} must be in {d.RangeText} (was {ValidationRules.Format(f)})"));
                    return false;
                case int i:
                    if ((d.MinExclusive ? i > d.Min : i >= d.Min) && i <= d.Max) return true;
                    errors.Add(new ValidationError(path + field, owner, $"{field} must be in {d.RangeText} (was {i})"));
                    return false;
                case SettingVector v:
                    float length = v.Length();
                    if (ValidationRules.IsFinite(length) && Above(length, d) && length <= d.Max) return true;
                    errors.Add(new ValidationError(path + field, owner, $"{field} must be finite with magnitude in {d.RangeText} (was {v})"));
                    return false;
                case SettingColor c:
                    // One error per channel, each naming its serialized key (Color.r), so that a scene reader can point at it.
                    bool ok = true;
                    foreach (var (name, channel) in new[] { ("r", c.r), ("g", c.g), ("b", c.b), ("a", c.a) })
                    {
                        if (ValidationRules.IsFinite(channel) && Above(channel, d) && channel <= (float)d.Max) continue;
                        errors.Add(new ValidationError(path + field + "." + name,
                            owner, $"{field}.{name} must be in {d.RangeText} (was {ValidationRules.Format(channel)})"));
                        ok = false;
                    }
                    return ok;
                case Enum e:
                    if (Enum.IsDefined(e.GetType(), e)) return true;
                    errors.Add(new ValidationError(path + field, owner, $"{field} must be {Allowed(e.GetType(), d)} (was {Convert.ToInt64(e)})"));
                    return false;
                default:
                    throw new NotSupportedException($"{settings.GetType().Name}.{field}: settings of type {info.FieldType.Name} are not supported");
            }
        }

        /// <summary>Every declared field of <paramref name="settings"/> (not those of the blocks it holds).</summary>
        public static void ValidateAll(object settings, List<ValidationError> errors, string owner, string path)
        {
            foreach (var declared in Declared(settings.GetType()))
                Validate(settings, errors, owner, path, declared.Field.Name);
        }

        /// <summary>What a field of <paramref name="fieldType"/> declared by <paramref name="d"/> accepts, as the messages
        /// write it: "a number in [1, 1E+09] Pa", "a whole number in [1, 1000]", "one of 0 (Wcsph), 1 (Dfsph)". A reader
        /// that cannot parse a value quotes it, so that the user learns what to write instead.</summary>
        public static string Allowed(Type fieldType, SettingAttribute d)
        {
            if (fieldType.IsEnum) return "one of " + EnumValues(fieldType);
            if (fieldType == typeof(int)) return "a whole number in " + d.RangeText;
            if (fieldType == typeof(SettingVector)) return "a vector {x, y, z} with magnitude in " + d.RangeText;
            if (fieldType == typeof(SettingColor)) return "a colour {r, g, b, a} with each channel in " + d.RangeText;
            if (fieldType == typeof(string)) return "a printable text (no control characters) of length in " + d.RangeText;
            return "a number in " + d.RangeText;
        }

        static bool Above(float value, SettingAttribute d) => d.MinExclusive ? value > (float)d.Min : value >= (float)d.Min;

        /// <summary>An enum's values as a scene file holds them, each with its name: "0 (Slip), 1 (NoSlip)".</summary>
        public static string EnumValues(Type enumType) =>
            string.Join(", ", Enum.GetValues(enumType).Cast<object>().Select(v => $"{Convert.ToInt64(v)} ({v})"));
    }
}
