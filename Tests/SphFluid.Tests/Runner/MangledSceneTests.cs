using System;
using System.Collections;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using NUnit.Framework;
using SphFluid.Headless.Scenes;

namespace SphFluid.Tests.Runner
{
    /// <summary>
    /// Hand-edited and broken scene files, made by the hundred: each shipped scene with lines deleted, repeated,
    /// swapped or cut short, a control character of YAML typed in, or a value of a component or Transform replaced
    /// by hostile text (NaN, a number past float or int, a quote left open, an alias, a tag). The loader must
    /// either read the scene with every number finite, or refuse it with a <see cref="SceneException"/> that names the
    /// file; no other exception and no hang. The mutations are seeded, so a failure names the edits that reproduce it.
    /// </summary>
    public class MangledSceneTests
    {
        const int MangledPerScene = 60;

        static readonly string[] HostileValues =
        {
            "nan", "NaN", "inf", "-Infinity", "-0", "0", "-1", "1e38", "3.4e39", "1e-45", "", "abc", "0x10", "1,5",
            "99999999999999999999", "-2147483649", "4294967296", "{}", "[]", "~", "null", "true", "'", "\"x", "&a", "*a",
            "!!int 3", "|", ">", "- 1", "{x: 1}", "{x: nan, y: 0, z: 0}",
        };

        static readonly string[] YamlMarks = { ":", "{", "}", "[", "]", "&", "*", "!!", "---", "\t", "#", "%", "\"", "'", "\u00e9", "\u0001" };

        [TestCaseSource(typeof(RunnerPaths), nameof(RunnerPaths.ShippedScenes))]
        public void AMangledSceneIsReadOrRefusedByName(string name)
        {
            string[] original = File.ReadAllLines(RunnerPaths.Scene(name));
            string folder = RunnerPaths.ScratchFolder("mangled");
            var random = new Random(Array.IndexOf(RunnerPaths.ShippedScenes, name) + 1); // string hashes differ from run to run
            var wrong = new List<string>();
            for (int n = 0; n < MangledPerScene; n++)
            {
                var lines = original.ToList();
                var edits = new List<string>();
                int count = 1 + random.Next(3);
                for (int e = 0; e < count; e++) edits.Add(Mangle(lines, random));
                string path = Path.Combine(folder, $"{name}-{n}.unity");
                File.WriteAllLines(path, lines);

                var (scene, thrown) = Deadline.Within(10, () =>
                {
                    try { return (SceneLoader.Load(path, RunnerPaths.Project), (Exception?)null); }
                    catch (Exception ex) { return ((LoadedScene?)null, ex); }
                }, $"loading {path} ({string.Join("; ", edits)})");

                string what = $"{Path.GetFileName(path)} ({string.Join("; ", edits)})";
                if (thrown is SceneException refusal)
                {
                    if (!refusal.Message.StartsWith(path, StringComparison.Ordinal))
                        wrong.Add($"{what}: the refusal does not start with the file: {refusal.Message}");
                }
                else if (thrown != null)
                    wrong.Add($"{what}: {thrown.GetType().Name}: {thrown.Message}");
                else if (NotFinite(scene!.Description, "Description", 0) is string field)
                    wrong.Add($"{what}: read, with {field}");
            }
            Assert.That(wrong, Is.Empty, string.Join("\n", wrong));
        }

        /// <summary>One edit of <paramref name="lines"/>, described.</summary>
        internal static string Mangle(List<string> lines, Random random)
        {
            int at = random.Next(lines.Count);
            switch (random.Next(6))
            {
                case 0:
                    lines.RemoveAt(at);
                    if (lines.Count == 0) lines.Add("");
                    return $"line {at + 1} deleted";
                case 1:
                    lines.Insert(at, lines[at]);
                    return $"line {at + 1} repeated";
                case 2:
                {
                    int other = random.Next(lines.Count);
                    (lines[at], lines[other]) = (lines[other], lines[at]);
                    return $"lines {at + 1} and {other + 1} swapped";
                }
                case 3:
                    lines.RemoveRange(Math.Max(1, at), lines.Count - Math.Max(1, at));
                    return $"cut after line {Math.Max(1, at)}";
                case 4:
                {
                    string mark = YamlMarks[random.Next(YamlMarks.Length)];
                    int column = random.Next(lines[at].Length + 1);
                    lines[at] = lines[at].Insert(column, mark);
                    return $"'{mark}' typed into line {at + 1} at column {column + 1}";
                }
                default:
                {
                    // A value the fluid reads: a field of a component or a Transform.
                    var values = ComponentValueLines(lines);
                    int line = values[random.Next(values.Count)];
                    string value = HostileValues[random.Next(HostileValues.Length)];
                    int colon = lines[line].IndexOf(": ", StringComparison.Ordinal);
                    lines[line] = lines[line].Substring(0, colon + 2) + value;
                    return $"line {line + 1}'s value set to '{value}'";
                }
            }
        }

        /// <summary>The lines holding "key: value" inside a MonoBehaviour or Transform document.</summary>
        static List<int> ComponentValueLines(List<string> lines)
        {
            var found = new List<int>();
            bool inComponent = false;
            for (int i = 0; i < lines.Count; i++)
            {
                if (lines[i].StartsWith("--- ", StringComparison.Ordinal))
                    inComponent = i + 1 < lines.Count && (lines[i + 1].StartsWith("MonoBehaviour:", StringComparison.Ordinal) || lines[i + 1].StartsWith("Transform:", StringComparison.Ordinal));
                else if (inComponent && lines[i].Contains(": ", StringComparison.Ordinal))
                    found.Add(i);
            }
            if (found.Count == 0) found.Add(0); // every component already cut away: type over the header
            return found;
        }

        /// <summary>The path of the first float or double in <paramref name="value"/>'s public fields and properties that is
        /// not finite, or null.</summary>
        internal static string? NotFinite(object? value, string path, int depth)
        {
            if (depth > 8) return null;
            switch (value)
            {
                case null:
                    return null;
                case float f:
                    return float.IsFinite(f) ? null : $"{path} = {f}";
                case double d:
                    return double.IsFinite(d) ? null : $"{path} = {d}";
                case string:
                    return null;
                case IEnumerable items:
                {
                    int i = 0;
                    foreach (object? item in items)
                        if (NotFinite(item, $"{path}[{i++}]", depth + 1) is string found) return found;
                    return null;
                }
            }
            Type type = value.GetType();
            if (type.IsPrimitive || type.IsEnum) return null;
            foreach (FieldInfo field in type.GetFields(BindingFlags.Public | BindingFlags.Instance))
                if (NotFinite(field.GetValue(value), $"{path}.{field.Name}", depth + 1) is string found) return found;
            foreach (PropertyInfo property in type.GetProperties(BindingFlags.Public | BindingFlags.Instance))
                if (property.GetIndexParameters().Length == 0 && NotFinite(property.GetValue(value), $"{path}.{property.Name}", depth + 1) is string found)
                    return found;
            return null;
        }
    }
}
