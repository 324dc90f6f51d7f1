using System;
using System.IO;
using System.Linq;
using SphFluid.UnityFiles.Assets;

namespace SphFluid.UnityFiles.Integrity;

public sealed partial class AssetIntegrity
{
    void ScanAssetRoots()
    {
        foreach (var root in ScannedRoots()) ScanFolder(root);
    }

    void ScanFolder(string dir)
    {
        foreach (var file in Directory.GetFiles(dir).OrderBy(f => f, StringComparer.Ordinal))
        {
            var name = Path.GetFileName(file);
            if (name.EndsWith(".meta", StringComparison.Ordinal)) _metaFiles.Add(file);
            else if (!IsHiddenFromUnity(name))
            {
                _assetFiles.Add(file);
                if (Extension(name) is ".csproj" or ".sln")
                    ReportAt(file, ".NET project files must not live under Assets/ (Unity would import them; keep them in Headless/ or Tests/)");
            }
        }
        foreach (var sub in Directory.GetDirectories(dir).OrderBy(d => d, StringComparer.Ordinal))
        {
            var name = Path.GetFileName(sub);
            if (IsHiddenFromUnity(name)) continue;
            if (name.Equals("bin", StringComparison.OrdinalIgnoreCase) || name.Equals("obj", StringComparison.OrdinalIgnoreCase))
            {
                ReportAt(sub, $"build output folder '{name}/' under Assets/: Unity would import its DLLs and files; build outside Assets/");
                continue;
            }
            _assetFolders.Add(sub);
            ScanFolder(sub);
        }
    }

    /// <summary>Resolves guids of the packages Package Manager put in Library/PackageCache, which a scene of a project that
    /// added the fluid by git URL refers to. Only for a scene's check: the whole project's check reads the files this
    /// repository holds (no Library/), and Unity's own packages are not its to judge.</summary>
    void IndexCachedPackages()
    {
        foreach (var package in UnityProject.CachedPackageFolders(_root))
            foreach (var metaPath in Directory.EnumerateFiles(package, "*.meta", SearchOption.AllDirectories))
            {
                UnityMeta meta;
                try { meta = _loadMeta(metaPath); }
                catch (Exception e) when (e is FormatException or IOException or UnauthorizedAccessException) { continue; }
                if (UnityMeta.IsValidGuid(meta.Guid)) _assetByGuid.TryAdd(meta.Guid, meta.AssetPath);
            }
    }

    void CheckMetas()
    {
        foreach (var asset in _assetFolders.Concat(_assetFiles))
        {
            var metaPath = asset + ".meta";
            if (!File.Exists(metaPath))
            {
                ReportAt(asset, "has no .meta (Unity would give it a fresh GUID and every reference to it would break; run Headless/tools/write-metas.py)");
                continue;
            }
            UnityMeta meta;
            try { meta = _loadMeta(metaPath); }
            catch (Exception e) when (e is FormatException or IOException)
            {
                ReportAt(metaPath, $"unreadable .meta: {e.Message}");
                continue;
            }
            _metaByAsset[asset] = meta;
            CheckMeta(meta, Directory.Exists(asset));
        }
        foreach (var metaPath in _metaFiles)
        {
            var asset = metaPath[..^5];
            var name = Path.GetFileName(asset);
            if (!File.Exists(asset) && !Directory.Exists(asset))
                ReportAt(metaPath, $"orphan .meta: '{name}' does not exist (Unity deletes it and warns)");
            else if (IsHiddenFromUnity(name))
                ReportAt(metaPath, $"orphan .meta: '{name}' is hidden from Unity (dot-file, '~', cvs or .tmp), so its .meta is never used");
        }
    }

    void CheckMeta(UnityMeta meta, bool isFolder)
    {
        var path = Rel(meta.MetaPath);
        if (meta.FileFormatVersion != "2") Report(path, $"fileFormatVersion must be 2 (was '{meta.FileFormatVersion}')");
        if (!UnityMeta.IsValidGuid(meta.Guid))
            Report(path, $"guid '{meta.Guid}' is not 32 lowercase hex digits");
        else if (meta.Guid.All(c => c == '0') || meta.Guid.Distinct().Count() <= 2)
            Report(path, $"guid '{meta.Guid}' is a pattern, not a random GUID");
        else if (UnityKnownIds.ForeignGuids.Contains(meta.Guid) || UnityKnownIds.PackageObjectGuids.ContainsKey(meta.Guid))
            Report(path, $"guid '{meta.Guid}' belongs to a Unity package, template or the kit's examples; generate a fresh one");
        else if (_assetByGuid.TryGetValue(meta.Guid, out var owner))
            Report(path, $"duplicate guid {meta.Guid}: also used by '{Rel(owner)}.meta' (Unity reassigns one and breaks its references)");
        else
            _assetByGuid.Add(meta.Guid, meta.AssetPath);

        if (meta.ImporterType == null)
        {
            Report(path, "has no importer block (e.g. DefaultImporter:)");
            return;
        }
        if (isFolder)
        {
            if (!meta.IsFolder) Report(path, "a folder's .meta needs 'folderAsset: yes'");
            if (meta.ImporterType != "DefaultImporter") Report(path, $"a folder's importer is DefaultImporter (was {meta.ImporterType})");
            return;
        }
        if (meta.IsFolder) Report(path, "'folderAsset: yes' on a file's .meta");
        var ext = Extension(meta.AssetPath);
        var expected = UnityKnownIds.Importers.FirstOrDefault(kv => kv.Key.Equals(ext, StringComparison.OrdinalIgnoreCase)).Value;
        if (expected != null && meta.ImporterType != expected)
            Report(path, $"a {ext} file is imported by {expected} (the .meta says {meta.ImporterType})");
        if (meta.ImporterType == "NativeFormatImporter" && meta.MainObjectFileId is null)
            Report(path, "NativeFormatImporter needs mainObjectFileID");
        if (meta.ImporterType == "ScriptedImporter")
        {
            var script = meta.ImporterScript;
            if (script == null || script.Guid == null) Report(path, "ScriptedImporter needs 'script: {fileID: 11500000, guid: ..., type: 3}'");
            else if (!UnityKnownIds.PackageObjectGuids.ContainsKey(script.Guid) && !_assetByGuid.ContainsKey(script.Guid) && !IsProjectGuidLater(script.Guid))
                Report(path, $"ScriptedImporter script guid {script.Guid} is neither a known package importer nor a project script");
        }
    }

    bool IsProjectGuidLater(string guid) => _metaFiles.Any(m => File.ReadLines(m).Take(3).Any(l => l == "guid: " + guid));
}
