using System;
using System.Collections.Generic;
using System.Linq;
using System.Text.Json;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Assets;

/// <summary>An <c>.asmdef</c> (JSON, parsed strictly: no comments, no trailing commas, as Unity's JsonUtility expects).</summary>
public sealed class AssemblyDefinition
{
    public string Path { get; init; } = "";
    public string? Name { get; init; }
    public string? RootNamespace { get; init; }
    /// <summary>Assembly names or <c>GUID:&lt;asmdef meta guid&gt;</c> entries.</summary>
    public IReadOnlyList<string> References { get; init; } = Array.Empty<string>();
    public IReadOnlyList<string> IncludePlatforms { get; init; } = Array.Empty<string>();
    public IReadOnlyList<string> ExcludePlatforms { get; init; } = Array.Empty<string>();
    public bool AllowUnsafeCode { get; init; }
    public bool OverrideReferences { get; init; }
    public IReadOnlyList<string> PrecompiledReferences { get; init; } = Array.Empty<string>();
    public bool AutoReferenced { get; init; } = true;
    public IReadOnlyList<string> DefineConstraints { get; init; } = Array.Empty<string>();
    public bool NoEngineReferences { get; init; }
    /// <summary>Symbols defined when a package (or "Unity") is present in a version range: how an assembly uses an optional package.</summary>
    public IReadOnlyList<VersionDefine> VersionDefines { get; init; } = Array.Empty<VersionDefine>();

    /// <summary>Compiled for the editor only (<c>includePlatforms: ["Editor"]</c>).</summary>
    public bool IsEditorOnly => IncludePlatforms.Count == 1 && IncludePlatforms[0] == "Editor";

    /// <summary>A test assembly: only compiled when the test framework defines UNITY_INCLUDE_TESTS.</summary>
    public bool IsTestAssembly => DefineConstraints.Contains("UNITY_INCLUDE_TESTS");

    public static AssemblyDefinition Load(string path) => Parse(UnityTextFile.ReadMayBeEmpty(path), path);

    public static AssemblyDefinition Parse(string json, string path)
    {
        using var doc = JsonDocument.Parse(json, new JsonDocumentOptions { AllowTrailingCommas = false, CommentHandling = JsonCommentHandling.Disallow });
        var root = doc.RootElement;
        if (root.ValueKind != JsonValueKind.Object) throw new FormatException($"{path}: an asmdef must be a JSON object");
        return new AssemblyDefinition
        {
            Path = path,
            Name = String(root, "name"),
            RootNamespace = String(root, "rootNamespace"),
            References = Strings(root, "references", path),
            IncludePlatforms = Strings(root, "includePlatforms", path),
            ExcludePlatforms = Strings(root, "excludePlatforms", path),
            AllowUnsafeCode = Bool(root, "allowUnsafeCode", false),
            OverrideReferences = Bool(root, "overrideReferences", false),
            PrecompiledReferences = Strings(root, "precompiledReferences", path),
            AutoReferenced = Bool(root, "autoReferenced", true),
            DefineConstraints = Strings(root, "defineConstraints", path),
            NoEngineReferences = Bool(root, "noEngineReferences", false),
            VersionDefines = VersionDefineList(root, path),
        };
    }

    static string? String(JsonElement root, string name) =>
        root.TryGetProperty(name, out var v) && v.ValueKind == JsonValueKind.String ? v.GetString() : null;

    static bool Bool(JsonElement root, string name, bool fallback) =>
        root.TryGetProperty(name, out var v) && (v.ValueKind == JsonValueKind.True || v.ValueKind == JsonValueKind.False) ? v.GetBoolean() : fallback;

    static IReadOnlyList<string> Strings(JsonElement root, string name, string? path)
    {
        if (!root.TryGetProperty(name, out var v)) return Array.Empty<string>();
        if (v.ValueKind != JsonValueKind.Array) throw new FormatException($"{path}: '{name}' must be an array of strings");
        // GetString is null only for a JSON null, which the kind test refuses.
        return v.EnumerateArray().Select(e => (e.ValueKind == JsonValueKind.String ? e.GetString() : null)
            ?? throw new FormatException($"{path}: '{name}' must be an array of strings")).ToList();
    }

    static IReadOnlyList<VersionDefine> VersionDefineList(JsonElement root, string path)
    {
        if (!root.TryGetProperty("versionDefines", out var v)) return Array.Empty<VersionDefine>();
        if (v.ValueKind != JsonValueKind.Array) throw new FormatException($"{path}: 'versionDefines' must be an array of {{name, expression, define}} objects");
        return v.EnumerateArray().Select(e => e.ValueKind == JsonValueKind.Object
                ? new VersionDefine(String(e, "name"), String(e, "expression"), String(e, "define"))
                : throw new FormatException($"{path}: 'versionDefines' must be an array of {{name, expression, define}} objects"))
            .ToList();
    }

    public override string ToString() => $"asmdef '{Name}' ({Path})";
}

/// <summary>One <c>versionDefines</c> entry: <see cref="Define"/> is set when package <see cref="Name"/> (or "Unity") is
/// present at a version inside <see cref="Expression"/> (Unity's range syntax; empty = any version).</summary>
public sealed record VersionDefine(string? Name, string? Expression, string? Define);
