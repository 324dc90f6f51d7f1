using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.RegularExpressions;
using SphFluid.Compute;

namespace SphFluid.Vulkan;

/// <summary>A <c>#pragma kernel</c> entry: its name and the defines Unity adds for it (<c>#pragma kernel K FOO=2</c>).</summary>
public sealed record KernelDeclaration(string Name, IReadOnlyList<string> Defines);

/// <summary>
/// What Unity reads from a <c>.compute</c> file before any compiler sees it: the kernels, the
/// <c>multi_compile</c> keyword sets and the included files. glslang ignores these pragmas, so the
/// host parses them itself.
/// </summary>
public sealed class ComputeSource
{
    public string Path { get; }
    public string Text { get; }
    public IReadOnlyList<KernelDeclaration> Kernels { get; }

    /// <summary>One list per <c>multi_compile</c> line; <c>null</c> stands for the "off" variant (<c>_</c> or <c>__</c>).</summary>
    public IReadOnlyList<IReadOnlyList<string?>> KeywordSets { get; }

    /// <summary>Every keyword the file declares, in declaration order.</summary>
    public IReadOnlyList<string> Keywords { get; }

    /// <summary>The file itself and every file it includes, directly or not, with their texts.</summary>
    public IReadOnlyList<(string Path, string Text)> Files { get; }

    /// <summary>Where each <c>#include</c> was found: (including file, name as written) to the full path.</summary>
    public IReadOnlyDictionary<(string File, string Name), string> ResolvedIncludes { get; }

    /// <summary>An <c>#include "name"</c> or <c>#include &lt;name&gt;</c> line; group 1 is the name.</summary>
    internal static readonly Regex IncludeRegex = new(@"^\s*#\s*include\s*[""<]([^"">]+)["">]", RegexOptions.Multiline);
    static readonly Regex Identifier = new(@"^[A-Za-z_][A-Za-z0-9_]*$");
    static readonly Regex DefineWord = new(@"^[A-Za-z_][A-Za-z0-9_]*(=\S+)?$");
    static readonly Regex PragmaRegex = new(@"^\s*#\s*pragma\s+(kernel|multi_compile|multi_compile_local|shader_feature|shader_feature_local)\b([^\r\n]*)", RegexOptions.Multiline);

    ComputeSource(string path, string text, List<KernelDeclaration> kernels, List<IReadOnlyList<string?>> sets, List<(string, string)> files,
        Dictionary<(string, string), string> includes)
    {
        ResolvedIncludes = includes;
        Path = path;
        Text = text;
        Kernels = kernels;
        KeywordSets = sets;
        Keywords = sets.SelectMany(s => s).OfType<string>().Distinct().ToList();
        Files = files;
    }

    public static ComputeSource Load(string path, IReadOnlyList<string> includeDirs)
    {
        string text = File.ReadAllText(path);
        string code = StripComments(text);
        var kernels = new List<KernelDeclaration>();
        var sets = new List<IReadOnlyList<string?>>();
        foreach (Match m in PragmaRegex.Matches(code))
        {
            var tokens = m.Groups[2].Value.Split((char[]?)null, StringSplitOptions.RemoveEmptyEntries);
            if (m.Groups[1].Value == "kernel")
            {
                // Unity reads the pragma up to a ';' and ignores the rest, so "#pragma kernel K;" names K.
                string declaration = m.Groups[2].Value.Split(';')[0];
                var words = declaration.Split((char[]?)null, StringSplitOptions.RemoveEmptyEntries);
                int line = code.Take(m.Index).Count(c => c == '\n') + 1;
                if (words.Length == 0)
                    throw new ComputeException($"{path}:{line}: #pragma kernel needs a kernel name (#pragma kernel Name [DEFINE or DEFINE=value ...])");
                if (!Identifier.IsMatch(words[0]))
                    throw new ComputeException($"{path}:{line}: '{words[0]}' is not a kernel name; #pragma kernel takes an HLSL function name, then optional DEFINE or DEFINE=value words");
                foreach (string define in words.Skip(1))
                    if (!DefineWord.IsMatch(define))
                        throw new ComputeException($"{path}:{line}: '{define}' after kernel '{words[0]}' is not a define; write DEFINE or DEFINE=value");
                kernels.Add(new KernelDeclaration(words[0], words.Skip(1).ToList()));
            }
            else
            {
                // shader_feature without an explicit off variant implies one, as in Unity.
                bool feature = m.Groups[1].Value.StartsWith("shader_feature", StringComparison.Ordinal);
                var set = tokens.Select(t => t.Trim('_').Length == 0 ? null : (string?)t).ToList();
                if (feature && set.Count == 1 && set[0] != null) set.Insert(0, null);
                if (set.Count > 0) sets.Add(set);
            }
        }

        var files = new List<(string, string)>();
        var includes = new Dictionary<(string, string), string>();
        var seen = new HashSet<string>(StringComparer.Ordinal);
        void Visit(string file, string content)
        {
            if (!seen.Add(file)) return;
            files.Add((file, content));
            foreach (Match inc in IncludeRegex.Matches(StripComments(content)))
            {
                string? resolved = ResolveInclude(inc.Groups[1].Value, System.IO.Path.GetDirectoryName(file) ?? ".", includeDirs);
                if (resolved == null) continue;
                includes[(file, inc.Groups[1].Value)] = resolved;
                Visit(resolved, File.ReadAllText(resolved));
            }
        }
        Visit(System.IO.Path.GetFullPath(path), text);
        return new ComputeSource(System.IO.Path.GetFullPath(path), text, kernels, sets, files, includes);
    }

    static string? ResolveInclude(string name, string fromDir, IReadOnlyList<string> includeDirs)
    {
        foreach (var dir in new[] { fromDir }.Concat(includeDirs))
        {
            string candidate = System.IO.Path.GetFullPath(System.IO.Path.Combine(dir, name));
            if (File.Exists(candidate)) return candidate;
        }
        return null;
    }

    /// <summary>True when any of the file's sources declares a buffer with this name (whether or not a kernel uses it).</summary>
    public bool DeclaresBuffer(string name)
    {
        var decl = new Regex(@"(?:Buffer\s*<[^>]*>|ByteAddressBuffer)\s+" + Regex.Escape(name) + @"\b");
        return Files.Any(f => decl.IsMatch(StripComments(f.Text)));
    }

    /// <summary>The defines of the variant selected by <paramref name="enabled"/>: per keyword set the first enabled
    /// keyword, else the off variant, else (a set without one) its first keyword, as Unity does.</summary>
    public List<string> VariantKeywords(IReadOnlyCollection<string> enabled)
    {
        var result = new List<string>();
        foreach (var set in KeywordSets)
        {
            string? chosen = set.FirstOrDefault(k => k != null && enabled.Contains(k));
            if (chosen == null && !set.Contains(null)) chosen = set[0];
            if (chosen != null && !result.Contains(chosen)) result.Add(chosen);
        }
        result.Sort(StringComparer.Ordinal);
        return result;
    }

    static string StripComments(string s)
    {
        // Keeps line breaks so line numbers stay meaningful.
        var sb = new StringBuilder(s.Length);
        for (int i = 0; i < s.Length; i++)
        {
            if (s[i] == '/' && i + 1 < s.Length && s[i + 1] == '/')
            {
                while (i < s.Length && s[i] != '\n') i++;
                if (i < s.Length) sb.Append('\n');
            }
            else if (s[i] == '/' && i + 1 < s.Length && s[i + 1] == '*')
            {
                i += 2;
                while (i < s.Length && !(s[i] == '*' && i + 1 < s.Length && s[i + 1] == '/'))
                {
                    if (s[i] == '\n') sb.Append('\n');
                    i++;
                }
                i++;
            }
            else sb.Append(s[i]);
        }
        return sb.ToString();
    }
}
