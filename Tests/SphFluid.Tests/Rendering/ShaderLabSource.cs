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
        public string Name { get; set; }
        public string Type { get; set; }        // Range, Float, Int, Integer, Color, Vector, 2D, 3D, Cube, ...
        public string Default { get; set; }     // text after '=' as written
        public float? RangeMin { get; set; }
        public float? RangeMax { get; set; }
        public int Line { get; set; }

        public bool IsNumber => Type == "Range" || Type == "Float" || Type == "Int" || Type == "Integer";
        public bool IsVector => Type == "Color" || Type == "Vector";
    }

    /// <summary>One HLSLPROGRAM/CGPROGRAM block with the line its first source line has in the .shader file.</summary>
    public sealed class ShaderLabProgram
    {
        public string Source { get; set; }
        public int FirstLine { get; set; }
        public string VertexEntry { get; set; }
        public string FragmentEntry { get; set; }
        public string Target { get; set; }

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
                return Inline(File.ReadAllText(file).Replace("\r\n", "\n"), System.IO.Path.GetDirectoryName(file), seen);
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

        public string Path { get; private set; }
        public string Name { get; private set; }
        public IReadOnlyList<ShaderLabProperty> Properties { get; private set; }
        public IReadOnlyList<ShaderLabProgram> Programs { get; private set; }
        public string Text { get; private set; }

        public static ShaderLabSource Load(string path) => Parse(File.ReadAllText(path), path);

        public static ShaderLabSource Parse(string text, string path)
        {
            string[] lines = text.Replace("\r\n", "\n").Split('\n');
            var result = new ShaderLabSource { Path = path, Text = text };
            var properties = new List<ShaderLabProperty>();
            var programs = new List<ShaderLabProgram>();

            bool inProperties = false;
            int propertiesDepth = 0;
            for (int i = 0; i < lines.Length; i++)
            {
                string line = StripLineComment(lines[i]);
                string trimmed = line.Trim();
                if (result.Name == null)
                {
                    var name = NameLine.Match(line);
                    if (name.Success) result.Name = name.Groups[1].Value;
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
                        properties.Add(new ShaderLabProperty
                        {
                            Name = property.Groups[1].Value,
                            Type = isRange ? "Range" : property.Groups[2].Value,
                            RangeMin = isRange ? float.Parse(property.Groups[3].Value, CultureInfo.InvariantCulture) : (float?)null,
                            RangeMax = isRange ? float.Parse(property.Groups[4].Value, CultureInfo.InvariantCulture) : (float?)null,
                            Default = property.Groups[5].Value,
                            Line = i + 1,
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
                    var program = new ShaderLabProgram { FirstLine = first + 1 };
                    var source = new StringBuilder();
                    for (int k = first; k < last; k++)
                    {
                        source.Append(lines[k]).Append('\n');
                        var pragma = PragmaLine.Match(lines[k]);
                        if (!pragma.Success) continue;
                        if (pragma.Groups[1].Value == "vertex") program.VertexEntry = pragma.Groups[2].Value;
                        else if (pragma.Groups[1].Value == "fragment") program.FragmentEntry = pragma.Groups[2].Value;
                        else program.Target = pragma.Groups[2].Value;
                    }
                    program.Source = source.ToString();
                    programs.Add(program);
                    i = last;
                }
            }
            result.Properties = properties;
            result.Programs = programs;
            return result;
        }

        static string StripLineComment(string line)
        {
            int comment = line.IndexOf("//", StringComparison.Ordinal);
            return comment >= 0 ? line.Substring(0, comment) : line;
        }
    }
}
