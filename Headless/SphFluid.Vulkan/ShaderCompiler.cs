using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using System.Text.RegularExpressions;
using System.Threading;
using SphFluid.Compute;

namespace SphFluid.Vulkan;

/// <summary>
/// Turns one kernel variant of a <c>.compute</c> file into validated SPIR-V with glslang's HLSL front
/// end, and keeps the result on disk under a hash of everything that can change it (source, includes,
/// kernel, defines, tool binaries), so a rerun never recompiles.
/// </summary>
public sealed class ShaderCompiler
{
    // 2: sources prepared by GlslangSourceTree, structured buffers repacked by StructuredBufferPacking.
    const string CacheFormat = "sphfluid-spirv-2";
    int _compileCount;
    readonly string? _glslang;
    readonly string? _spirvVal;
    readonly Lazy<string> _toolFingerprint;

    /// <summary>Where compiled variants live: SPHFLUID_SHADER_CACHE, else $XDG_CACHE_HOME/sphfluid-spirv, else ~/.cache/sphfluid-spirv.</summary>
    public string CacheDirectory { get; }

    /// <summary>How many times glslang has run in this process (cache misses).</summary>
    public int CompileCount => Volatile.Read(ref _compileCount);

    public ShaderCompiler(string? cacheDirectory = null)
    {
        CacheDirectory = cacheDirectory ?? DefaultCacheDirectory();
        _glslang = FindTool("glslangValidator", "glslang-tools");
        _spirvVal = FindTool("spirv-val", "spirv-tools");
        _toolFingerprint = new Lazy<string>(() => Fingerprint(_glslang) + "|" + Fingerprint(_spirvVal));
    }

    /// <summary>Why compiled kernels cannot be kept in <see cref="CacheDirectory"/> (it is a file, or cannot be made or
    /// written), or null where they can. Compile passes such a cache over without a word, since it costs only time;
    /// this says so before a run pays it. Writes and removes one empty probe file of its own there.</summary>
    public string? CacheProblem()
    {
        try
        {
            Directory.CreateDirectory(CacheDirectory);
            string probe = Path.Combine(CacheDirectory, $".probe-{Guid.NewGuid():N}.tmp");
            File.WriteAllBytes(probe, Array.Empty<byte>());
            File.Delete(probe);
            return null;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            return e.Message;
        }
    }

    public static string DefaultCacheDirectory() => CacheDirectoryFrom(Environment.GetEnvironmentVariable("SPHFLUID_SHADER_CACHE"),
        Environment.GetEnvironmentVariable("XDG_CACHE_HOME"), Environment.GetFolderPath(Environment.SpecialFolder.UserProfile));

    /// <summary>The cache folder the variables name: <paramref name="shaderCache"/> (SPHFLUID_SHADER_CACHE), else
    /// <paramref name="xdgCacheHome"/>/sphfluid-spirv, else <paramref name="home"/>/.cache/sphfluid-spirv. A blank value
    /// counts as unset, as a blank SPHFLUID_VULKAN_DEVICE does: taken as a path it made a folder named by the blanks
    /// in the working folder. A relative XDG_CACHE_HOME is passed over, as the XDG base directory specification asks.</summary>
    public static string CacheDirectoryFrom(string? shaderCache, string? xdgCacheHome, string home)
    {
        if (!string.IsNullOrWhiteSpace(shaderCache)) return shaderCache;
        if (!string.IsNullOrWhiteSpace(xdgCacheHome) && Path.IsPathRooted(xdgCacheHome)) return Path.Combine(xdgCacheHome, "sphfluid-spirv");
        return Path.Combine(home, ".cache", "sphfluid-spirv");
    }

    static string? FindTool(string name, string package)
    {
        foreach (var dir in (Environment.GetEnvironmentVariable("PATH") ?? "").Split(Path.PathSeparator))
        {
            if (dir.Length == 0) continue;
            string candidate = Path.Combine(dir, name);
            if (File.Exists(candidate)) return candidate;
        }
        return null;
    }

    static string Fingerprint(string? tool)
    {
        if (tool == null) return "missing";
        var info = new FileInfo(tool);
        return $"{tool}:{info.Length}:{info.LastWriteTimeUtc.Ticks}";
    }

    static string[] Arguments(string kernel, IReadOnlyList<string> defines) =>
        new[] { "-D", "-V", "--target-env", "vulkan1.1", "--auto-map-bindings", "-S", "comp", "-e", kernel }
            .Concat(defines.Select(d => "-D" + (d.Contains('=') ? d : d + "=1"))).ToArray();

    /// <summary>The cache key of a variant: every input that can change the SPIR-V.</summary>
    public string Key(ComputeSource source, string kernel, IReadOnlyList<string> defines)
    {
        var sb = new StringBuilder();
        sb.Append(CacheFormat).Append('\n').Append(_toolFingerprint.Value).Append('\n');
        sb.Append(string.Join(" ", Arguments(kernel, defines))).Append('\n');
        string root = Path.GetDirectoryName(source.Path) ?? ".";
        foreach (var (path, text) in source.Files)
            sb.Append(Path.GetRelativePath(root, path)).Append('\n').Append(text.Length).Append('\n').Append(text).Append('\n');
        return Convert.ToHexString(SHA256.HashData(Encoding.UTF8.GetBytes(sb.ToString()))).ToLowerInvariant();
    }

    /// <summary>SPIR-V words of the variant, from the cache or freshly compiled and validated.</summary>
    public uint[] Compile(ComputeSource source, string kernel, IReadOnlyList<string> defines, IReadOnlyList<string> includeDirs)
    {
        string key = Key(source, kernel, defines);
        string cached = Path.Combine(CacheDirectory, key + ".spv");
        if (File.Exists(cached))
        {
            try
            {
                var bytes = File.ReadAllBytes(cached);
                if (bytes.Length >= 20 && bytes.Length % 4 == 0 && BitConverter.ToUInt32(bytes, 0) == 0x07230203)
                    return ToWords(bytes);
            }
            catch (IOException) { }
        }

        if (_glslang == null) throw new ComputeException("glslangValidator was not found on PATH (Debian package glslang-tools); it compiles the .compute kernels");
        if (_spirvVal == null) throw new ComputeException("spirv-val was not found on PATH (Debian package spirv-tools); it validates the compiled kernels");
        Interlocked.Increment(ref _compileCount);
        // One uniquely named output file and one source folder per compile, both deleted below: a per-process
        // folder would be left behind empty by every run.
        string output = Path.Combine(Path.GetTempPath(), $"sphfluid-spirv-{key}.{Guid.NewGuid():N}.spv");
        using var tree = GlslangSourceTree.Write(source, Path.GetTempPath());
        try
        {
            var args = Arguments(kernel, defines).ToList();
            args.Add("-I" + Path.GetDirectoryName(source.Path));
            args.AddRange(includeDirs.Select(d => "-I" + d));
            args.Add(tree.MainFile);
            args.Add("-o");
            args.Add(output);
            var (code, text) = Run(_glslang, args);
            if (code != 0 || !File.Exists(output))
                throw new ComputeException(DescribeErrors(source, tree.MainFile, kernel, defines, text));
            var changed = MeaningChangingWarnings(text);
            if (changed.Count > 0)
                throw new ComputeException($"HLSL that glslang would compile differently from Unity in {source.Path}, kernel '{kernel}'{DefinesText(defines)}:\n  " + string.Join("\n  ", changed));
            uint[] packed;
            try { packed = StructuredBufferPacking.Apply(ToWords(File.ReadAllBytes(output))); }
            catch (FormatException e) { throw new ComputeException($"{source.Path}: kernel '{kernel}'{DefinesText(defines)}: its structured buffers cannot be laid out as Unity does: {e.Message}", e); }
            var bytes = new byte[packed.Length * 4];
            Buffer.BlockCopy(packed, 0, bytes, 0, bytes.Length);
            File.WriteAllBytes(output, bytes);
            var (valCode, valText) = Run(_spirvVal, new[] { "--target-env", "vulkan1.1", "--scalar-block-layout", output });
            if (valCode != 0)
                throw new ComputeException($"{source.Path}: kernel '{kernel}'{DefinesText(defines)} compiled to invalid SPIR-V (spirv-val): {valText.Trim()}");
            string staging = cached + "." + Guid.NewGuid().ToString("N") + ".tmp";
            try
            {
                Directory.CreateDirectory(CacheDirectory);
                File.WriteAllBytes(staging, bytes);
                File.Move(staging, cached, overwrite: true);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                // A read-only or full cache only costs time; a full one must not keep the part it took.
                try { File.Delete(staging); } catch (Exception cleanup) when (cleanup is IOException || cleanup is UnauthorizedAccessException) { }
            }
            return ToWords(bytes);
        }
        finally
        {
            try { File.Delete(output); } catch (IOException) { }
        }
    }

    /// <summary>glslang warnings after which the kernel would not do what the same HLSL does in Unity; each is
    /// reported as an error (file:line: message) instead of compiling something else in silence.</summary>
    static readonly (string Warning, string Advice)[] MeaningChanging =
    {
        ("not initialized; zero initializing", "give the constant a value (static const) or drop const to make it a global the host sets"),
        ("struct-member initializers ignored", "HLSL ignores struct member initializers too; remove them"),
        ("mul() matrix size mismatch", "the operands of mul() do not fit; glslang would multiply something else"),
        ("unknown pack_matrix pragma value", "use #pragma pack_matrix(row_major) or (column_major)"),
        ("unknown requalification", "glslang dropped a qualifier"),
    };

    static List<string> MeaningChangingWarnings(string output)
    {
        var found = new List<string>();
        foreach (Match m in ErrorLine.Matches(output))
        {
            if (!m.Value.StartsWith("WARNING", StringComparison.Ordinal)) continue;
            string message = m.Groups[3].Value.Trim();
            foreach (var (warning, advice) in MeaningChanging)
                if (message.Contains(warning, StringComparison.Ordinal))
                    found.Add($"{m.Groups[1].Value.Trim()}:{m.Groups[2].Value}: {message} ({advice})");
        }
        return found;
    }

    static string DefinesText(IReadOnlyList<string> defines) => defines.Count == 0 ? "" : $" [{string.Join(" ", defines)}]";

    static readonly Regex ErrorLine = new(@"^(?:ERROR|WARNING):\s*(.+?):(\d+):\s*(.*)$", RegexOptions.Multiline);

    /// <summary>glslang's errors as <c>file:line: message</c>, the file path first so an editor can jump to it; the
    /// prepared copy glslang read (<paramref name="compiledCopy"/>) never appears, as its #line names the original.</summary>
    static string DescribeErrors(ComputeSource source, string compiledCopy, string kernel, IReadOnlyList<string> defines, string output)
    {
        var lines = new List<string>();
        foreach (Match m in ErrorLine.Matches(output))
        {
            if (!m.Value.StartsWith("ERROR", StringComparison.Ordinal)) continue;
            string file = m.Groups[1].Value.Trim();
            lines.Add($"{file}:{m.Groups[2].Value}: {m.Groups[3].Value.Trim()}");
        }
        if (lines.Count == 0)
            lines.AddRange(output.Split('\n').Select(l => l.Trim()).Where(l => l.Length > 0 && l != source.Path && l != compiledCopy && !l.EndsWith("No code generated.", StringComparison.Ordinal)));
        return $"HLSL compile error in {source.Path}, kernel '{kernel}'{DefinesText(defines)}:\n  " + string.Join("\n  ", lines);
    }

    static (int code, string output) Run(string exe, IEnumerable<string> args)
    {
        var psi = new ProcessStartInfo(exe) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (var a in args) psi.ArgumentList.Add(a);
        using var p = Process.Start(psi) ?? throw new ComputeException($"{exe} could not be started");
        var stderr = p.StandardError.ReadToEndAsync();
        string stdout = p.StandardOutput.ReadToEnd();
        p.WaitForExit();
        return (p.ExitCode, stdout + stderr.Result);
    }

    static uint[] ToWords(byte[] bytes)
    {
        var words = new uint[bytes.Length / 4];
        Buffer.BlockCopy(bytes, 0, words, 0, words.Length * 4);
        return words;
    }
}
