using System;
using System.Collections.Generic;
using System.Linq;
using System.Text.Json;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Assets;

/// <summary><c>Packages/manifest.json</c>: package name to version (or <c>file:</c> path), plus testables.</summary>
public sealed class PackageManifest
{
    public string? Path { get; init; }
    public IReadOnlyDictionary<string, string> Dependencies { get; init; } = new Dictionary<string, string>();
    public IReadOnlyList<string> Testables { get; init; } = Array.Empty<string>();

    public bool Has(string package) => Dependencies.ContainsKey(package);

    public string? VersionOf(string package) => Dependencies.TryGetValue(package, out var v) ? v : null;

    public static PackageManifest Load(string path) => Parse(UnityTextFile.ReadMayBeEmpty(path), path);

    public static PackageManifest Parse(string json, string? path = null)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        if (root.ValueKind != JsonValueKind.Object || !root.TryGetProperty("dependencies", out var deps) || deps.ValueKind != JsonValueKind.Object)
            throw new FormatException($"{path}: manifest.json needs a \"dependencies\" object");
        var map = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (var p in deps.EnumerateObject())
            map[p.Name] = (p.Value.ValueKind == JsonValueKind.String ? p.Value.GetString() : null)
                ?? throw new FormatException($"{path}: version of '{p.Name}' must be a string");
        var testables = root.TryGetProperty("testables", out var t) && t.ValueKind == JsonValueKind.Array
            ? t.EnumerateArray().Select(e => (e.ValueKind == JsonValueKind.String ? e.GetString() : null)
                ?? throw new FormatException($"{path}: \"testables\" must be an array of package names")).ToList()
            : new List<string>();
        return new PackageManifest { Path = path, Dependencies = map, Testables = testables };
    }
}
