using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.RegularExpressions;

namespace SphFluid.Tests.Rendering
{
    /// <summary>One <c>_Name ("Label", Type) = default</c> line of a ShaderLab Properties block.</summary>
    public sealed class ShaderLabProperty
    {
        public ShaderLabProperty(string name, string type, string defaultText, int line)
        {
            Name = name;
            Type = type;
            Default = defaultText;
            Line = line;
        }

        public string Name { get; }
        public string Type { get; }        // Range, Float, Int, Integer, Color, Vector, 2D, 3D, Cube, ...
        public string Default { get; }     // text after '=' as written
        /// <summary>The bounds of a Range property; null for every other type.</summary>
        public float? RangeMin { get; set; }
        public float? RangeMax { get; set; }
        public int Line { get; }

        /// <summary>Both bounds of a Range property (an error for any other type, which has none).</summary>
        public (float Min, float Max) Range => RangeMin is float min && RangeMax is float max
            ? (min, max) : throw new InvalidOperationException(Name + " (" + Type + ") is not a Range property");

        public bool IsNumber => Type == "Range" || Type == "Float" || Type == "Int" || Type == "Integer";
        public bool IsVector => Type == "Color" || Type == "Vector";
    }

    /// <summary>One HLSLPROGRAM/CGPROGRAM block with the line its first source line has in the .shader file.</summary>
    public sealed class ShaderLabProgram
    {
        public ShaderLabProgram(string source, int firstLine)
        {
            Source = source;
            FirstLine = firstLine;
        }

        public string Source { get; }
        public int FirstLine { get; }
        /// <summary>The #pragma vertex, fragment and target values; null where the program has no such line.</summary>
        public string? VertexEntry { get; set; }
        public string? FragmentEntry { get; set; }
        public string? Target { get; set; }

        /// <summary>The program as a standalone HLSL file whose compiler messages name the .shader file and its lines.</summary>
        public string WithLineDirective(string shaderPathForMessages) =>
            "#line " + FirstLine.ToString(CultureInfo.InvariantCulture) + " \"" + shaderPathForMessages.Replace('\\', '/') + "\"\n" + Source;

        /// <summary>
        /// The program with every quoted #include that resolves to a file (beside the including file) inlined,
        /// each file once: the text the compiler sees, short of the pipeline's own includes (UnityCG.cginc...),
        /// which stay as #include lines. For reading the program's declarations, not for compiling.
        /// </summary>
        public string WithLocalIncludes(string shaderDirectory)
        {
            var seen = new HashSet<string>(StringComparer.Ordinal);
            return Inline(Source, shaderDirectory, seen);
        }

        static readonly Regex IncludeLine = new Regex("^[ \\t]*#include\\s+\"([^\"]+)\"[^\\n]*$", RegexOptions.Multiline);

        static string Inline(string text, string directory, HashSet<string> seen) =>
            IncludeLine.Replace(text, m =>
            {
                string file = System.IO.Path.GetFullPath(System.IO.Path.Combine(directory, m.Groups[1].Value));
                if (!File.Exists(file)) return m.Value;
                if (!seen.Add(file)) return "";
                // A full path to an existing file always has a folder.
                string folder = System.IO.Path.GetDirectoryName(file) ?? directory;
                return Inline(File.ReadAllText(file).Replace("\r\n", "\n"), folder, seen);
            });
    }

    /// <summary>
    /// The parts of a ShaderLab .shader file the tests need: its name, Properties block and HLSL programs.
    /// A line-based reading, enough for hand-written shaders in the project's style (one statement per line).
    /// </summary>
    public sealed class ShaderLabSource
    {
        static readonly Regex NameLine = new Regex("^\\s*Shader\\s+\"([^\"]+)\"");
        static readonly Regex PropertyLine = new Regex(
            "^\\s*(?:\\[[^\\]]*\\]\\s*)*(_\\w+)\\s*\\(\\s*\"[^\"]*\"\\s*,\\s*(Range\\s*\\(\\s*([-+0-9.eE]+)\\s*,\\s*([-+0-9.eE]+)\\s*\\)|\\w+)\\s*\\)\\s*=\\s*(.+?)\\s*$");
        static readonly Regex PragmaLine = new Regex("^\\s*#pragma\\s+(vertex|fragment|target)\\s+(\\S+)");

        ShaderLabSource(string path, string? name, IReadOnlyList<ShaderLabProperty> properties, IReadOnlyList<ShaderLabProgram> programs, string text)
        {
            Path = path;
            Name = name;
            Properties = properties;
            Programs = programs;
            Text = text;
        }

        public string Path { get; }
        /// <summary>The name on the <c>Shader "..."</c> line; null where the file has none.</summary>
        public string? Name { get; }
        public IReadOnlyList<ShaderLabProperty> Properties { get; }
        public IReadOnlyList<ShaderLabProgram> Programs { get; }
        public string Text { get; }

        public static ShaderLabSource Load(string path) => Parse(File.ReadAllText(path), path);

        public static ShaderLabSource Parse(string text, string path)
        {
            string[] lines = text.Replace("\r\n", "\n").Split('\n');
            string? shaderName = null;
            var properties = new List<ShaderLabProperty>();
            var programs = new List<ShaderLabProgram>();

            bool inProperties = false;
            int propertiesDepth = 0;
            for (int i = 0; i < lines.Length; i++)
            {
                string line = StripLineComment(lines[i]);
                string trimmed = line.Trim();
                if (shaderName == null)
                {
                    var name = NameLine.Match(line);
                    if (name.Success) shaderName = name.Groups[1].Value;
                }
                if (!inProperties && Regex.IsMatch(trimmed, "^Properties\\b"))
                {
                    inProperties = true;
                    propertiesDepth = 0;
                }
                if (inProperties)
                {
                    var property = PropertyLine.Match(line);
                    if (property.Success)
                    {
                        bool isRange = property.Groups[2].Value.StartsWith("Range", StringComparison.Ordinal);
                        properties.Add(new ShaderLabProperty(property.Groups[1].Value, isRange ? "Range" : property.Groups[2].Value, property.Groups[5].Value, i + 1)
                        {
                            RangeMin = isRange ? float.Parse(property.Groups[3].Value, CultureInfo.InvariantCulture) : (float?)null,
                            RangeMax = isRange ? float.Parse(property.Groups[4].Value, CultureInfo.InvariantCulture) : (float?)null,
                        });
                    }
                    propertiesDepth += line.Count(c => c == '{') - line.Count(c => c == '}');
                    if (propertiesDepth <= 0 && line.Contains('}')) inProperties = false;
                    continue;
                }
                if (trimmed == "HLSLPROGRAM" || trimmed == "CGPROGRAM")
                {
                    string end = trimmed == "HLSLPROGRAM" ? "ENDHLSL" : "ENDCG";
                    int first = i + 1;
                    int last = first;
                    while (last < lines.Length && lines[last].Trim() != end) last++;
                    if (last >= lines.Length) throw new FormatException(path + ":" + (i + 1) + ": " + trimmed + " without " + end);
                    string? vertex = null, fragment = null, target = null;
                    var source = new StringBuilder();
                    for (int k = first; k < last; k++)
                    {
                        source.Append(lines[k]).Append('\n');
                        var pragma = PragmaLine.Match(lines[k]);
                        if (!pragma.Success) continue;
                        if (pragma.Groups[1].Value == "vertex") vertex = pragma.Groups[2].Value;
                        else if (pragma.Groups[1].Value == "fragment") fragment = pragma.Groups[2].Value;
                        else target = pragma.Groups[2].Value;
                    }
                    programs.Add(new ShaderLabProgram(source.ToString(), first + 1) { VertexEntry = vertex, FragmentEntry = fragment, Target = target });
                    i = last;
                }
            }
            return new ShaderLabSource(path, shaderName, properties, programs, text);
        }

        static string StripLineComment(string line)
        {
            int comment = line.IndexOf("//", StringComparison.Ordinal);
            return comment >= 0 ? line.Substring(0, comment) : line;
        }
    }
}
