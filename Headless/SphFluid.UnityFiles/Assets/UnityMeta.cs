using System.Diagnostics.CodeAnalysis;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Assets;

/// <summary>A <c>.meta</c> file: the asset's GUID and its importer block.</summary>
public sealed partial class UnityMeta
{
    [GeneratedRegex("^[0-9a-f]{32}$")]
    private static partial Regex GuidFormat();

    UnityMeta(string metaPath, UnityYamlNode root)
    {
        MetaPath = metaPath;
        Root = root;
        Guid = root.GetString("guid");
        FileFormatVersion = root.GetString("fileFormatVersion");
        IsFolder = root.GetString("folderAsset") == "yes";
        var importer = root.Entries.FirstOrDefault(e => e.Key.EndsWith("Importer", System.StringComparison.Ordinal));
        ImporterType = importer.Key;
        Importer = importer.Value;
    }

    /// <summary>Path of the .meta file itself.</summary>
    public string MetaPath { get; }
    /// <summary>Path of the asset the .meta describes (the .meta path without its extension).</summary>
    public string AssetPath => MetaPath.EndsWith(".meta", System.StringComparison.Ordinal) ? MetaPath[..^5] : MetaPath;
    public string? Guid { get; }
    public string? FileFormatVersion { get; }
    public bool IsFolder { get; }
    /// <summary>The importer block's key, e.g. <c>MonoImporter</c>, <c>ComputeShaderImporter</c>, <c>NativeFormatImporter</c>.</summary>
    public string? ImporterType { get; }
    public UnityYamlNode? Importer { get; }
    public UnityYamlNode Root { get; }

    /// <summary>For NativeFormatImporter assets: the main object's fileID (<c>mainObjectFileID</c>), else null.</summary>
    public long? MainObjectFileId => Importer != null && Importer.TryGetLong("mainObjectFileID", out var id) ? id : null;

    /// <summary>For ScriptedImporter assets (e.g. .inputactions): the importer script reference.</summary>
    public UnityReference? ImporterScript => Importer?.GetReference("script");

    public static bool IsValidGuid([NotNullWhen(true)] string? guid) => guid != null && GuidFormat().IsMatch(guid);

    public static UnityMeta Load(string metaPath) => Parse(UnityTextFile.ReadMayBeEmpty(metaPath), metaPath);

    public static UnityMeta Parse(string text, string metaPath) => new(metaPath, UnityYamlParser.ParseBlock(text, metaPath));

    /// <summary>Reads just the guid of an asset's .meta (<paramref name="assetPath"/> without ".meta"); null if absent.</summary>
    public static string? GuidOf(string assetPath)
    {
        var meta = assetPath + ".meta";
        return File.Exists(meta) ? Load(meta).Guid : null;
    }
}
