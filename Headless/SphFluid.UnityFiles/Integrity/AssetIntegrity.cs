using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Integrity;

/// <summary>
/// Checks a hand-written Unity project the way the editor would see it on first open: metas and GUIDs, references
/// from scenes and assets, scripts behind <c>m_Script</c>, asmdef references, the manifest, ProjectSettings and
/// scene structure. Never throws for bad content: every finding is an <see cref="IntegrityProblem"/> naming its file.
/// </summary>
public sealed partial class AssetIntegrity
{
    readonly string _root;
    readonly List<IntegrityProblem> _problems = new();
    readonly List<string> _assetFolders = new();
    readonly List<string> _assetFiles = new();
    readonly List<string> _metaFiles = new();
    readonly Dictionary<string, UnityMeta> _metaByAsset = new(StringComparer.Ordinal);
    readonly Dictionary<string, string> _assetByGuid = new(StringComparer.Ordinal);
    readonly Func<string, UnityMeta> _loadMeta;
    PackageManifest? _manifest;

    AssetIntegrity(string root, Func<string, UnityMeta> loadMeta) => (_root, _loadMeta) = (Path.GetFullPath(root), loadMeta);

    /// <summary>Runs every check on the Unity project at <paramref name="projectRoot"/> (the folder holding Assets/).</summary>
    public static IReadOnlyList<IntegrityProblem> Check(string projectRoot)
    {
        var check = new AssetIntegrity(projectRoot, UnityMeta.Load);
        check.Run();
        return check._problems;
    }

    /// <summary>
    /// The checks one scene (or prefab) gets in <see cref="Check"/>, for a runner about to simulate it: its documents,
    /// anchors, references and scripts against the project's .metas, its GameObject/Transform structure and parent
    /// cycles. The file may lie outside the project (an edited copy); problems of other files are not reported. The
    /// .metas are those <paramref name="project"/> read for its index.
    /// </summary>
    public static IReadOnlyList<IntegrityProblem> CheckScene(UnityProject project, string scenePath, UnityYamlFile yaml) =>
        CheckScenes(project, new[] { (scenePath, yaml) });

    /// <summary><see cref="CheckScene"/> for several scenes or prefabs, at one reading of the project.</summary>
    public static IReadOnlyList<IntegrityProblem> CheckScenes(UnityProject project, IReadOnlyList<(string Path, UnityYamlFile Yaml)> files)
    {
        var check = new AssetIntegrity(project.Root, project.Meta);
        check.Guarded("Assets", check.ScanAssetRoots);
        check.Guarded("Assets", check.CheckMetas);
        check.Guarded("ProjectSettings", check.CheckProjectSettings);
        check.Guarded("Library/PackageCache", check.IndexCachedPackages);
        check._problems.Clear();
        foreach (var (path, yaml) in files)
        {
            string file = Path.GetFullPath(path);
            check.Guarded(check.Rel(file), () => check.CheckSerializedFile(file, yaml));
        }
        return check._problems;
    }

    /// <summary>Formats problems one per line, for test failure messages and the CLI.</summary>
    public static string Describe(IReadOnlyList<IntegrityProblem> problems) =>
        problems.Count == 0 ? "no problems" : $"{problems.Count} problem(s):\n  " + string.Join("\n  ", problems);

    /// <summary>The closest folder at or above <paramref name="start"/> that holds both Assets/ and ProjectSettings/ (or Packages/).</summary>
    public static string FindProjectRoot(string start)
    {
        for (var dir = new DirectoryInfo(Path.GetFullPath(start)); dir != null; dir = dir.Parent)
            if (Directory.Exists(Path.Combine(dir.FullName, "Assets")) &&
                (Directory.Exists(Path.Combine(dir.FullName, "ProjectSettings")) || Directory.Exists(Path.Combine(dir.FullName, "Packages"))))
                return dir.FullName;
        throw new DirectoryNotFoundException($"no Unity project (Assets/ + ProjectSettings/) at or above '{start}'");
    }

    void Run()
    {
        if (!Directory.Exists(Path.Combine(_root, "Assets")))
        {
            Report("Assets", "folder is missing");
            return;
        }
        Guarded("Assets", ScanAssetRoots);
        Guarded("Assets", CheckMetas);
        Guarded("Packages/manifest.json", CheckManifest);
        Guarded("ProjectSettings", CheckProjectSettings);
        Guarded("Assets", CheckAssemblies);
        Guarded("Assets", CheckSerializedFiles);
        Guarded("Assets", CheckLegacyInput);
        Guarded("ProjectSettings/EditorBuildSettings.asset", CheckBuildSettings);
    }

    void Guarded(string path, Action check)
    {
        try { check(); }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // Bad content must become a finding, never a crash: the other checks still run.
            // The runner prints these to people who edit scenes: the reason, never an exception type name.
            Report(path, $"check stopped: {e.Message}");
        }
    }

    void Report(string path, string message, int line = 0) => _problems.Add(new IntegrityProblem(path, message, line));

    void ReportAt(string absolutePath, string message, int line = 0) => Report(Rel(absolutePath), message, line);

    string Rel(string absolutePath) => Path.GetRelativePath(_root, absolutePath).Replace('\\', '/');

    string Abs(string relativePath) => Path.GetFullPath(Path.Combine(_root, relativePath));

    string ReadText(string absolutePath) => UnityTextFile.ReadMayBeEmpty(absolutePath);

    /// <summary>Names Unity never imports: dot-files, <c>name~</c>, <c>cvs</c>, <c>*.tmp</c>.</summary>
    public static bool IsHiddenFromUnity(string name) =>
        name.StartsWith('.') || name.EndsWith('~') || name.Equals("cvs", StringComparison.OrdinalIgnoreCase) ||
        name.EndsWith(".tmp", StringComparison.OrdinalIgnoreCase);

    static string Extension(string path) => Path.GetExtension(path);

    /// <summary>Assets/, each embedded package, and each sample the packages declare: a sample is checked as it will
    /// be once Package Manager has copied it into a project (its folder gets no .meta; everything inside has one).</summary>
    IEnumerable<string> ScannedRoots()
    {
        yield return Abs("Assets");
        foreach (var package in EmbeddedPackageFolders())
        {
            yield return package;
            foreach (var sample in DeclaredSampleFolders(package).Where(Directory.Exists))
            {
                _sampleRoots.Add(sample);
                yield return sample;
            }
        }
    }

    readonly List<string> _sampleRoots = new();

    IEnumerable<string> EmbeddedPackageFolders()
    {
        var packages = Abs("Packages");
        if (!Directory.Exists(packages)) return Enumerable.Empty<string>();
        return Directory.GetDirectories(packages).OrderBy(d => d, StringComparer.Ordinal)
            .Where(dir => !IsHiddenFromUnity(Path.GetFileName(dir)) && File.Exists(Path.Combine(dir, "package.json")));
    }

    /// <summary>Absolute folders of the package's "samples" entries that lie under Samples~ (a package.json that does
    /// not parse, or a sample path outside Samples~, is reported by CheckEmbeddedPackages).</summary>
    static IEnumerable<string> DeclaredSampleFolders(string packageFolder)
    {
        EmbeddedPackage package;
        try { package = EmbeddedPackage.Load(Path.Combine(packageFolder, "package.json")); }
        catch (Exception e) when (e is System.Text.Json.JsonException or FormatException) { return Enumerable.Empty<string>(); }
        return package.Samples.Where(s => s.IsUnderSamplesFolder).Select(s => s.Path).OfType<string>()
            .Select(path => Path.GetFullPath(Path.Combine(packageFolder, path))).Distinct(StringComparer.Ordinal).ToList();
    }

    /// <summary>A file of a package sample: it lands in other projects, so it may use packages this project lacks.</summary>
    bool InSample(string absolutePath) =>
        _sampleRoots.Any(root => absolutePath.StartsWith(root + Path.DirectorySeparatorChar, StringComparison.Ordinal));
}
