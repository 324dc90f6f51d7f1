using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using SphFluid.UnityFiles.Scenes;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Assets;

/// <summary>
/// A Unity project on disk seen through its GUIDs: turns a reference's guid into the asset path (e.g. which .compute a
/// scene component points at), a script class name into its guid, and lists scenes and the build's scene list.
/// Index built once on construction from every .meta under Assets/, under each embedded package (Packages/&lt;name&gt;/
/// with a package.json), where this project's fluid components and shaders live, and under each package Package Manager
/// resolved into Library/PackageCache (a project that added the fluid by git URL finds its scripts there).
/// </summary>
public sealed class UnityProject
{
    readonly Dictionary<string, string> _pathByGuid = new(StringComparer.Ordinal);
    readonly Dictionary<string, string> _guidByPath = new(StringComparer.Ordinal);
    readonly Dictionary<string, UnityMeta> _metaByPath = new(StringComparer.Ordinal);

    public UnityProject(string root)
    {
        Root = Path.GetFullPath(root);
        var assets = Path.Combine(Root, "Assets");
        if (!Directory.Exists(assets)) throw new DirectoryNotFoundException($"'{Root}' has no Assets/ folder");
        foreach (var path in AssetRoots(assets).SelectMany(r => Directory.EnumerateFiles(r, "*.meta", SearchOption.AllDirectories)))
        {
            if (ReadMeta(path) is not { } meta) continue;
            _metaByPath[path] = meta;
            if (meta.Guid is not { } guid) continue;
            var asset = ToProjectPath(path[..^5]);
            _pathByGuid.TryAdd(guid, asset);
            _guidByPath[asset] = guid;
        }
    }

    /// <summary>The .meta, or null where it cannot be read: its asset then resolves nowhere, as in Unity, which logs that
    /// one asset, and the scene's integrity check refuses a scene that refers to it.</summary>
    static UnityMeta? ReadMeta(string path)
    {
        try { return UnityMeta.Load(path); }
        catch (Exception e) when (e is FormatException or IOException or UnauthorizedAccessException) { return null; }
    }

    /// <summary>Assets/, then the embedded packages, then the cached ones: an embedded package is the one Unity uses where
    /// the cache holds the same package too, and the index keeps the first path of a guid.</summary>
    IEnumerable<string> AssetRoots(string assets)
    {
        yield return assets;
        var packages = Path.Combine(Root, "Packages");
        if (Directory.Exists(packages))
            foreach (var dir in Directory.GetDirectories(packages).OrderBy(d => d, StringComparer.Ordinal))
                if (!Integrity.AssetIntegrity.IsHiddenFromUnity(Path.GetFileName(dir)) && File.Exists(Path.Combine(dir, "package.json")))
                    yield return dir;
        foreach (var dir in CachedPackageFolders(Root)) yield return dir;
    }

    /// <summary>The folder of the package <paramref name="name"/> that Unity uses: Packages/<paramref name="name"/> where it is
    /// embedded, else its one copy in Library/PackageCache (<paramref name="name"/>@version); null where neither holds a
    /// package.json, or the cache holds several.</summary>
    public string? PackageFolder(string name)
    {
        var embedded = Path.Combine(Root, "Packages", name);
        if (File.Exists(Path.Combine(embedded, "package.json"))) return embedded;
        var cached = CachedCopies(name);
        return cached.Count == 1 ? cached[0] : null;
    }

    /// <summary>The folders of <paramref name="name"/> in Library/PackageCache (<paramref name="name"/>@version), unless
    /// the project embeds it: one where Package Manager resolved it, several where stale copies were left behind.</summary>
    public IReadOnlyList<string> CachedCopies(string name) =>
        CachedPackageFolders(Root).Where(dir => Path.GetFileName(dir).StartsWith(name + "@", StringComparison.Ordinal)).ToList();

    /// <summary>Library/PackageCache/&lt;name&gt;@&lt;version&gt;/ folders holding a package.json: the packages Package Manager
    /// resolved from a registry or a git URL. A cached copy of a package the project embeds is left out: Unity uses the
    /// embedded one, and the copy's scripts would read as a second script of each name.</summary>
    public static IReadOnlyList<string> CachedPackageFolders(string projectRoot)
    {
        var cache = Path.Combine(projectRoot, "Library", "PackageCache");
        if (!Directory.Exists(cache)) return Array.Empty<string>();
        return Directory.GetDirectories(cache).OrderBy(d => d, StringComparer.Ordinal)
            .Where(dir => File.Exists(Path.Combine(dir, "package.json")))
            .Where(dir => Path.GetFileName(dir).Split('@')[0] is var name &&
                !File.Exists(Path.Combine(projectRoot, "Packages", name, "package.json")))
            .ToList();
    }

    /// <summary>Absolute path of the folder holding Assets/.</summary>
    public string Root { get; }

    /// <summary>Finds the project at or above <paramref name="start"/>.</summary>
    public static UnityProject Find(string start) => new(Integrity.AssetIntegrity.FindProjectRoot(start));

    /// <summary>The .meta at the absolute <paramref name="metaPath"/> as the index read it, else read now. A scene's
    /// integrity check reads every .meta of the project as well; in a project of 30 000 assets, reading each twice was a
    /// quarter of a run's start.</summary>
    public UnityMeta Meta(string metaPath) => _metaByPath.TryGetValue(metaPath, out var meta) ? meta : UnityMeta.Load(metaPath);

    /// <summary>"Assets/…" path of the asset with <paramref name="guid"/>, or null.</summary>
    public string? AssetPathOf(string? guid) => guid != null && _pathByGuid.TryGetValue(guid, out var p) ? p : null;

    /// <summary>"Assets/…" path a reference points at (null for null, local and built-in references).</summary>
    public string? AssetPathOf(UnityReference? reference) => reference == null || !reference.IsExternal ? null : AssetPathOf(reference.Guid);

    /// <summary>Guid of an asset given as "Assets/…" (or absolute) path, or null.</summary>
    public string? GuidOf(string assetPath) => _guidByPath.TryGetValue(ToProjectPath(assetPath), out var g) ? g : null;

    /// <summary>Guid of the script file <c>&lt;className&gt;.cs</c> (Unity binds MonoBehaviours by file name); throws when absent or ambiguous.</summary>
    public string ScriptGuid(string className)
    {
        var matches = _guidByPath.Where(kv => Path.GetFileName(kv.Key) == className + ".cs").ToList();
        if (matches.Count == 1) return matches[0].Value;
        throw new InvalidOperationException(matches.Count == 0
            ? $"no {className}.cs under Assets/, an embedded package or Library/PackageCache"
            : $"{className}.cs exists {matches.Count} times: {string.Join(", ", matches.Select(m => m.Key))}");
    }

    /// <summary>Project path of the asset named <paramref name="fileName"/> directly in a Resources folder (where
    /// Resources.Load finds it), or null; the first in path order when several exist.</summary>
    public string? AssetPathOfResource(string fileName) => _guidByPath.Keys
        .Where(p => p.EndsWith("/Resources/" + fileName, StringComparison.Ordinal))
        .OrderBy(p => p, StringComparer.Ordinal).FirstOrDefault();

    /// <summary>Absolute path for an "Assets/…" path.</summary>
    public string FullPath(string projectPath) => Path.GetFullPath(Path.Combine(Root, projectPath));

    /// <summary>Every .unity scene of the project's own (under Assets/ and the embedded packages), as project paths, sorted.</summary>
    public IReadOnlyList<string> Scenes =>
        _guidByPath.Keys.Where(p => p.EndsWith(".unity", StringComparison.Ordinal) && !p.StartsWith("Library/", StringComparison.Ordinal))
            .OrderBy(p => p, StringComparer.Ordinal).ToList();

    /// <summary>Enabled scenes of ProjectSettings/EditorBuildSettings.asset in build order (empty when the file is absent).</summary>
    public IReadOnlyList<string> BuildScenes
    {
        get
        {
            var file = Path.Combine(Root, "ProjectSettings", "EditorBuildSettings.asset");
            if (!File.Exists(file)) return Array.Empty<string>();
            var scenes = UnityYamlFile.Load(file).Documents.FirstOrDefault()?.Root["m_Scenes"];
            return scenes?.Items.Where(s => s.GetBool("enabled", true)).Select(s => s.GetString("path")).OfType<string>().ToList() ?? new List<string>();
        }
    }

    /// <summary>Loads a scene given as "Assets/…" path, absolute path, or bare scene name ("DamBreak").</summary>
    public UnityScene LoadScene(string scene)
    {
        var path = scene.EndsWith(".unity", StringComparison.Ordinal)
            ? ToProjectPath(scene)
            : Scenes.FirstOrDefault(s => Path.GetFileNameWithoutExtension(s) == scene)
              ?? throw new FileNotFoundException($"no scene named '{scene}' under Assets/ (have: {string.Join(", ", Scenes.Select(Path.GetFileNameWithoutExtension))})");
        return UnityScene.Load(FullPath(path));
    }

    string ToProjectPath(string path)
    {
        var full = Path.GetFullPath(Path.IsPathRooted(path) ? path : Path.Combine(Root, path));
        return Path.GetRelativePath(Root, full).Replace('\\', '/');
    }
}
