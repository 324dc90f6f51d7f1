using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Integrity;

public sealed partial class AssetIntegrity
{
    /// <summary>Packages the project cannot work without (issue 2, unity-kit §2.1).</summary>
    public static readonly string[] RequiredPackages =
        { "com.unity.mathematics", "com.unity.test-framework", "com.unity.inputsystem", "com.unity.ugui" };

    long _activeInputHandler = -1;

    void CheckManifest()
    {
        const string path = "Packages/manifest.json";
        if (!File.Exists(Abs(path)))
        {
            Report(path, "is missing");
            return;
        }
        try { _manifest = PackageManifest.Load(Abs(path)); }
        catch (Exception e) when (e is JsonException or FormatException)
        {
            Report(path, $"does not parse: {e.Message}");
            return;
        }
        foreach (var package in RequiredPackages.Where(p => !_manifest.Has(p)))
            Report(path, $"does not name {package}");
        var embedded = CheckEmbeddedPackages(_manifest);
        foreach (var t in _manifest.Testables.Where(t => !_manifest.Has(t) && !embedded.Contains(t)))
            Report(path, $"testable '{t}' is neither a dependency nor an embedded package");
        foreach (var (name, version) in _manifest.Dependencies)
            if (string.IsNullOrWhiteSpace(version)) Report(path, $"'{name}' has no version");
        var stream = TryProjectVersion()?.Stream;
        if (stream == "2022.3" && _manifest.Has("com.unity.modules.accessibility"))
            Report(path, "com.unity.modules.accessibility does not exist for 2022.3 (package resolution would fail)");
    }

    /// <summary>
    /// Each <c>Packages/&lt;name&gt;/package.json</c>: the fields the Package Manager needs, a Unity release the
    /// project's editor satisfies, and dependencies the manifest resolves at the same version (so a project that adds
    /// the package by git URL gets what this one tests with). Returns the embedded packages' names.
    /// </summary>
    HashSet<string> CheckEmbeddedPackages(PackageManifest manifest)
    {
        var names = new HashSet<string>(StringComparer.Ordinal);
        var packages = Abs("Packages");
        foreach (var dir in Directory.GetDirectories(packages).OrderBy(d => d, StringComparer.Ordinal))
        {
            var file = Path.Combine(dir, "package.json");
            if (IsHiddenFromUnity(Path.GetFileName(dir)) || !File.Exists(file)) continue;
            string rel = Rel(file);
            EmbeddedPackage package;
            try { package = EmbeddedPackage.Load(file); }
            catch (Exception e) when (e is JsonException or FormatException)
            {
                Report(rel, $"does not parse: {e.Message}");
                continue;
            }
            foreach (var problem in package.Problems(Path.GetFileName(dir))) Report(rel, problem);
            if (package.Name != null) names.Add(package.Name);
            var stream = TryProjectVersion()?.Stream;
            if (Version.TryParse(stream, out var editor) && Version.TryParse(package.Unity, out var wanted) && wanted > editor)
                Report(rel, $"\"unity\" {package.Unity} is newer than the project's editor {stream}");
            foreach (var (dependency, version) in package.Dependencies)
            {
                var resolved = manifest.VersionOf(dependency);
                if (resolved == null) Report(rel, $"dependency '{dependency}' is not in Packages/manifest.json");
                else if (resolved != version) Report(rel, $"dependency '{dependency}' {version} differs from Packages/manifest.json's {resolved}");
            }
            CheckSamples(dir, rel, package);
        }
        return names;
    }

    /// <summary>Every "samples" entry names a folder that exists, and every folder under Samples~ is offered by one:
    /// Package Manager shows only declared samples, so an undeclared folder is dead weight in every install.</summary>
    void CheckSamples(string packageFolder, string rel, EmbeddedPackage package)
    {
        var declared = new HashSet<string>(StringComparer.Ordinal);
        foreach (var sample in package.Samples)
        {
            if (!sample.IsUnderSamplesFolder) continue;
            var folder = Path.GetFullPath(Path.Combine(packageFolder, sample.Path));
            declared.Add(folder);
            if (!Directory.Exists(folder)) Report(rel, $"sample '{sample.DisplayName}' has \"path\" '{sample.Path}', which is no folder in the package");
            else if (!Directory.EnumerateFileSystemEntries(folder).Any()) Report(rel, $"sample '{sample.DisplayName}' folder '{sample.Path}' is empty");
        }
        var samples = Path.Combine(packageFolder, EmbeddedPackage.SamplesFolder);
        if (!Directory.Exists(samples)) return;
        foreach (var folder in Directory.GetDirectories(samples).OrderBy(d => d, StringComparer.Ordinal))
            if (!declared.Contains(Path.GetFullPath(folder)))
                ReportAt(folder, "is under Samples~ but no \"samples\" entry of package.json names it (Package Manager would never offer it)");
        if (File.Exists(samples + ".meta"))
            ReportAt(samples + ".meta", "Samples~ is hidden from Unity, so it takes no .meta");
    }

    ProjectVersion? TryProjectVersion()
    {
        var file = Abs("ProjectSettings/ProjectVersion.txt");
        try { return File.Exists(file) ? ProjectVersion.Load(file) : null; }
        catch (FormatException) { return null; }
    }

    void CheckProjectSettings()
    {
        var dir = Abs("ProjectSettings");
        if (!Directory.Exists(dir))
        {
            Report("ProjectSettings", "folder is missing");
            return;
        }
        const string versionPath = "ProjectSettings/ProjectVersion.txt";
        if (!File.Exists(Abs(versionPath))) Report(versionPath, "is missing (the Hub cannot tell which editor to open)");
        else
        {
            try
            {
                var v = ProjectVersion.Load(Abs(versionPath));
                if (string.IsNullOrEmpty(v.EditorVersion)) Report(versionPath, "has no m_EditorVersion");
            }
            catch (FormatException e) { Report(versionPath, $"does not parse: {e.Message}"); }
        }
        foreach (var file in Directory.GetFiles(dir, "*.asset").OrderBy(f => f, StringComparer.Ordinal))
            CheckSettingsFile(file);
        if (!File.Exists(Path.Combine(dir, "ProjectSettings.asset"))) Report("ProjectSettings/ProjectSettings.asset", "is missing (activeInputHandler, names and graphics APIs)");
        if (!File.Exists(Path.Combine(dir, "EditorSettings.asset"))) Report("ProjectSettings/EditorSettings.asset", "is missing (Force Text serialization)");
    }

    void CheckSettingsFile(string file)
    {
        var name = Path.GetFileName(file);
        UnityYamlFile yaml;
        try { yaml = UnityYamlFile.Load(file); }
        catch (Exception e) when (e is FormatException or IOException)
        {
            ReportAt(file, $"does not parse: {e.Message}");
            return;
        }
        if (!yaml.HasUnityHeader) ReportAt(file, $"must start with '{UnityYamlFile.YamlHeader}' and '{UnityYamlFile.TagHeader}'");
        if (yaml.Documents.Count == 0)
        {
            ReportAt(file, "has no document");
            return;
        }
        var doc = yaml.Documents[0];
        if (doc.FileId != 1) ReportAt(file, $"settings object must be '&1' (was &{doc.FileId})");
        if (UnityKnownIds.SettingsFiles.TryGetValue(name, out var expected) && (doc.ClassId != expected.ClassId || doc.TypeName != expected.TypeName))
            ReportAt(file, $"must be '--- !u!{expected.ClassId} &1' with root '{expected.TypeName}:' (was !u!{doc.ClassId} {doc.TypeName})");
        CheckReferences(file, yaml);
        var root = doc.Root;
        switch (name)
        {
            case "ProjectSettings.asset":
                var handler = root.GetLong("activeInputHandler", 0);
                _activeInputHandler = handler;
                if (handler != 1 && handler != 2)
                    ReportAt(file, $"activeInputHandler must be 1 (Input System) or 2 (both), was {handler}: the Input System would prompt to restart the editor");
                break;
            case "EditorSettings.asset":
                if (root.GetLong("m_SerializationMode", 2) != 2) ReportAt(file, "m_SerializationMode must be 2 (Force Text)");
                break;
            case "VersionControlSettings.asset":
                if (root.GetString("m_Mode") != "Visible Meta Files") ReportAt(file, $"m_Mode must be 'Visible Meta Files' (was '{root.GetString("m_Mode")}')");
                break;
        }
    }

    void CheckBuildSettings()
    {
        var file = Abs("ProjectSettings/EditorBuildSettings.asset");
        if (!File.Exists(file)) return;
        UnityYamlFile yaml;
        try { yaml = UnityYamlFile.Load(file); }
        catch (FormatException) { return; } // already reported by CheckSettingsFile
        var scenes = yaml.Documents.FirstOrDefault()?.Root["m_Scenes"];
        if (scenes == null) return;
        foreach (var entry in scenes.Items)
        {
            var scenePath = entry.GetString("path");
            var guid = entry.GetString("guid");
            if (string.IsNullOrEmpty(scenePath))
            {
                ReportAt(file, $"scene entry at line {entry.Line} has no path");
                continue;
            }
            if (!scenePath.EndsWith(".unity", StringComparison.Ordinal)) ReportAt(file, $"scene '{scenePath}' is not a .unity file");
            var abs = Abs(scenePath);
            if (!File.Exists(abs))
            {
                ReportAt(file, $"scene '{scenePath}' does not exist");
                continue;
            }
            var metaGuid = _metaByAsset.TryGetValue(abs, out var meta) ? meta.Guid : null;
            if (metaGuid == null) ReportAt(file, $"scene '{scenePath}' has no .meta guid to match");
            else if (guid != metaGuid) ReportAt(file, $"scene '{scenePath}' is listed with guid {guid} but its .meta has {metaGuid}");
        }
    }
}
