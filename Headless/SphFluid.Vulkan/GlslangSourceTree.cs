using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using System.Text.RegularExpressions;

namespace SphFluid.Vulkan;

/// <summary>
/// The <c>.compute</c> file and every file it includes, written to a private folder as glslang must see
/// them to compile what Unity compiles: UTF-8 without a byte-order mark (glslang reads one as a bad token),
/// uninitialised <c>const</c> globals made settable (<see cref="ConstGlobals"/>), each <c>#include</c>
/// pointing at the prepared copy, and a <c>#line 1 "original path"</c> first line so that errors name
/// the original files and lines. The folder is deleted on <see cref="Dispose"/>.
/// </summary>
public sealed class GlslangSourceTree : IDisposable
{
    readonly string _root;

    /// <summary>The prepared copy of the <c>.compute</c> file, to pass to glslang.</summary>
    public string MainFile { get; }

    GlslangSourceTree(string root, string mainFile)
    {
        _root = root;
        MainFile = mainFile;
    }

    /// <summary>Writes the prepared copies into a new folder under <paramref name="parent"/>.</summary>
    public static GlslangSourceTree Write(ComputeSource source, string parent)
    {
        string root = Path.Combine(parent, "sphfluid-src-" + Guid.NewGuid().ToString("N"));
        // One folder per file keeps same-named includes from different folders apart.
        var copies = new Dictionary<string, (int Folder, string Path)>(StringComparer.Ordinal);
        for (int i = 0; i < source.Files.Count; i++)
        {
            string original = source.Files[i].Path;
            copies[original] = (i, Path.Combine(root, i.ToString(), Path.GetFileName(original)));
        }
        var tree = new GlslangSourceTree(root, copies[source.Path].Path);
        try
        {
            var utf8 = new UTF8Encoding(false);
            foreach (var (original, text) in source.Files)
            {
                string body = ConstGlobals.MakeSettable(text.TrimStart('\uFEFF'));
                body = ComputeSource.IncludeRegex.Replace(body, m =>
                {
                    if (!source.ResolvedIncludes.TryGetValue((original, m.Groups[1].Value), out string? target)) return m.Value;
                    string relative = "../" + copies[target].Folder + "/" + Path.GetFileName(target);
                    return m.Value.Substring(0, m.Groups[1].Index - m.Index - 1) + "\"" + relative + "\"";
                });
                string copy = copies[original].Path;
                Directory.CreateDirectory(Path.GetDirectoryName(copy)!); // copy is a file path under the tree's root
                File.WriteAllText(copy, $"#line 1 \"{original.Replace('\\', '/').Replace("\"", "")}\"\n{body}", utf8);
            }
        }
        catch
        {
            tree.Dispose();
            throw;
        }
        return tree;
    }

    public void Dispose()
    {
        try
        {
            if (Directory.Exists(_root)) Directory.Delete(_root, true);
        }
        catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
        {
            // A leftover temporary folder only costs disk space.
        }
    }
}
