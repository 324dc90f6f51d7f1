using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Assets;

/// <summary>
/// <c>Packages/&lt;name&gt;/package.json</c> of a package embedded in the project: the fields the Package Manager
/// needs to resolve it (name, version, unity, dependencies).
/// </summary>
public sealed class EmbeddedPackage
{
    // Package Manager names: lower case, reverse domain, at least three dot-separated parts.
    static readonly Regex NamePattern = new(@"^[a-z0-9][a-z0-9_-]*(\.[a-z0-9][a-z0-9_-]*){2,}$", RegexOptions.CultureInvariant);
    static readonly Regex VersionPattern = new(@"^\d+\.\d+\.\d+(-[0-9A-Za-z.-]+)?$", RegexOptions.CultureInvariant);
    static readonly Regex UnityPattern = new(@"^\d{4}\.\d+$", RegexOptions.CultureInvariant);

    public string? Path { get; init; }
    public string? Name { get; init; }
    public string? Version { get; init; }
    public string? Unity { get; init; }
    public IReadOnlyDictionary<string, string> Dependencies { get; init; } = new Dictionary<string, string>();
    /// <summary>The <c>"samples"</c> entries: what Package Manager offers to import, each a folder under <c>Samples~</c>.</summary>
    public IReadOnlyList<PackageSample> Samples { get; init; } = Array.Empty<PackageSample>();

    /// <summary>The folder Package Manager copies samples from; Unity never imports it in place (its name ends in '~').</summary>
    public const string SamplesFolder = "Samples~";

    public static EmbeddedPackage Load(string path) => Parse(UnityTextFile.ReadMayBeEmpty(path), path);

    public static EmbeddedPackage Parse(string json, string? path = null)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        if (root.ValueKind != JsonValueKind.Object) throw new FormatException("package.json must be an object");
        var deps = new Dictionary<string, string>(StringComparer.Ordinal);
        if (root.TryGetProperty("dependencies", out var d))
        {
            if (d.ValueKind != JsonValueKind.Object) throw new FormatException("\"dependencies\" must be an object");
            foreach (var p in d.EnumerateObject())
                deps[p.Name] = (p.Value.ValueKind == JsonValueKind.String ? p.Value.GetString() : null)
                    ?? throw new FormatException($"version of dependency '{p.Name}' must be a string");
        }
        var samples = new List<PackageSample>();
        if (root.TryGetProperty("samples", out var list))
        {
            if (list.ValueKind != JsonValueKind.Array) throw new FormatException("\"samples\" must be an array of {displayName, description, path} objects");
            foreach (var sample in list.EnumerateArray())
            {
                if (sample.ValueKind != JsonValueKind.Object) throw new FormatException("\"samples\" must be an array of {displayName, description, path} objects");
                samples.Add(new PackageSample(Text(sample, "displayName"), Text(sample, "description"), Text(sample, "path")));
            }
        }
        return new EmbeddedPackage
        {
            Path = path,
            Name = Text(root, "name"),
            Version = Text(root, "version"),
            Unity = Text(root, "unity"),
            Dependencies = deps,
            Samples = samples,
        };
    }

    /// <summary>What the Package Manager would refuse in the file itself, one message per field.</summary>
    public IEnumerable<string> Problems(string folderName)
    {
        if (Name == null || !NamePattern.IsMatch(Name))
            yield return $"\"name\" must be a lower-case reverse-domain name such as com.company.package (was '{Name}')";
        else if (Name != folderName)
            yield return $"\"name\" '{Name}' must equal its folder's name '{folderName}'";
        if (Version == null || !VersionPattern.IsMatch(Version))
            yield return $"\"version\" must be a semantic version such as 1.2.3 (was '{Version}')";
        if (Unity == null || !UnityPattern.IsMatch(Unity))
            yield return $"\"unity\" must be a Unity release such as 2022.3 (was '{Unity}')";
        foreach (var sample in Samples)
        {
            if (string.IsNullOrWhiteSpace(sample.DisplayName))
                yield return $"sample '{sample.Path}' has no \"displayName\" (Package Manager lists samples by it)";
            if (!sample.IsUnderSamplesFolder)
                yield return $"sample '{sample.DisplayName}' has \"path\" '{sample.Path}'; it must be a folder under {SamplesFolder}/ (Unity would import it in place)";
        }
    }

    static string? Text(JsonElement root, string field) =>
        root.TryGetProperty(field, out var v) && v.ValueKind == JsonValueKind.String ? v.GetString() : null;
}

/// <summary>One entry of a package's <c>"samples"</c>: Package Manager copies <see cref="Path"/> (relative to the
/// package) into <c>Assets/Samples/&lt;package&gt;/&lt;version&gt;/&lt;displayName&gt;</c> when asked, .meta files included.</summary>
public sealed record PackageSample(string? DisplayName, string? Description, string? Path)
{
    /// <summary>A folder below <c>Samples~/</c>, written with forward slashes and without '..'.</summary>
    [System.Diagnostics.CodeAnalysis.MemberNotNullWhen(true, nameof(Path))]
    public bool IsUnderSamplesFolder =>
        Path != null && Path.StartsWith(EmbeddedPackage.SamplesFolder + "/", StringComparison.Ordinal) &&
        Path.Length > EmbeddedPackage.SamplesFolder.Length + 1 && !Path.Contains('\\') && !Path.Split('/').Contains("..");
}
