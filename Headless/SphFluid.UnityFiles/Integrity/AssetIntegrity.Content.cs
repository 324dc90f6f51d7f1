using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Integrity;

public sealed partial class AssetIntegrity
{
    [GeneratedRegex(@"Shader\.Find\(\s*""(?<name>[^""]+)""\s*\)")]
    private static partial Regex ShaderFindCall();

    [GeneratedRegex(@"^\s*Shader\s+""(?<name>[^""]+)""", RegexOptions.Multiline)]
    private static partial Regex ShaderName();

    readonly HashSet<string> _sceneReferencedGuids = new(StringComparer.Ordinal);
    readonly Dictionary<string, string> _materialShaders = new(StringComparer.Ordinal);
    (HashSet<string> Tags, Dictionary<int, string> Layers)? _tagManager;

    /// <summary>
    /// A shader reached only through <c>Shader.Find</c> is stripped from players unless a scene (directly or through a
    /// material) uses it, it sits in Resources/, or GraphicsSettings always includes it (unity-kit §1.6, checklist 8).
    /// </summary>
    void CheckShadersFoundByName()
    {
        var shaders = _assetFiles.Where(f => Extension(f) == ".shader").ToList();
        if (shaders.Count == 0) return;
        var byName = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (var s in shaders)
        {
            var m = ShaderName().Match(ReadText(s));
            if (m.Success) byName.TryAdd(m.Groups["name"].Value, s);
        }
        var included = new HashSet<string>(_sceneReferencedGuids, StringComparer.Ordinal);
        foreach (var (material, shaderGuid) in _materialShaders)
            if (_metaByAsset.TryGetValue(material, out var meta) && meta.Guid != null && _sceneReferencedGuids.Contains(meta.Guid)) included.Add(shaderGuid);
        foreach (var guid in AlwaysIncludedShaderGuids()) included.Add(guid);

        foreach (var cs in _assetFiles.Where(f => Extension(f) == ".cs"))
        {
            foreach (Match call in ShaderFindCall().Matches(ReadText(cs)))
            {
                var name = call.Groups["name"].Value;
                if (!byName.TryGetValue(name, out var shader)) continue; // a built-in shader
                var inResources = Rel(shader).Split('/').Contains("Resources");
                var guid = _metaByAsset.TryGetValue(shader, out var meta) ? meta.Guid : null;
                if (!inResources && (guid == null || !included.Contains(guid)))
                    ReportAt(cs, $"Shader.Find(\"{name}\") finds '{Rel(shader)}', which no scene or scene material uses, is not in Resources/ and not in GraphicsSettings m_AlwaysIncludedShaders: players would get null");
            }
        }
    }

    IEnumerable<string> AlwaysIncludedShaderGuids()
    {
        var file = Abs("ProjectSettings/GraphicsSettings.asset");
        if (!File.Exists(file)) return Array.Empty<string>();
        try
        {
            var list = UnityYamlFile.Load(file).Documents.FirstOrDefault()?.Root["m_AlwaysIncludedShaders"];
            return list?.Items.Select(i => i.GetReference("")?.Guid).OfType<string>().ToList() ?? new List<string>();
        }
        catch (FormatException) { return Array.Empty<string>(); }
    }

    /// <summary>Custom tags and layers used by a scene must be declared in ProjectSettings/TagManager.asset.</summary>
    void CheckTagsAndLayers(string file, UnityYamlFile yaml)
    {
        foreach (var go in yaml.OfClass(1).Where(d => !d.IsStripped))
        {
            var name = $"GameObject '{go.Root.GetString("m_Name", "")}' &{go.FileId}";
            var tag = go.Root.GetString("m_TagString", "Untagged");
            if (!UnityKnownIds.BuiltinTags.Contains(tag) && !TagManager().Tags.Contains(tag))
                ReportAt(file, $"{name} has tag '{tag}', which ProjectSettings/TagManager.asset does not declare", go.Root["m_TagString"]?.Line ?? go.Line);
            var layerNode = go.Root["m_Layer"];
            long layer = 0;
            if (layerNode != null && !go.Root.TryGetLong("m_Layer", out layer))
                ReportAt(file, $"{name} m_Layer must be an integer in 0..31 (was '{layerNode}')", layerNode.Line);
            else if (layer < 0 || layer > 31)
                ReportAt(file, $"{name} has layer {layer}; layers are 0..31", layerNode?.Line ?? go.Line);
            else if (!UnityKnownIds.BuiltinLayers.Contains((int)layer) && !TagManager().Layers.ContainsKey((int)layer))
                ReportAt(file, $"{name} is on layer {layer}, which ProjectSettings/TagManager.asset does not name", layerNode?.Line ?? go.Line);
        }
    }

    (HashSet<string> Tags, Dictionary<int, string> Layers) TagManager()
    {
        if (_tagManager is { } cached) return cached;
        var tags = new HashSet<string>(StringComparer.Ordinal);
        var layers = new Dictionary<int, string>();
        var file = Abs("ProjectSettings/TagManager.asset");
        if (File.Exists(file))
        {
            try
            {
                var root = UnityYamlFile.Load(file).Documents.FirstOrDefault()?.Root;
                foreach (var t in root?["tags"]?.Items ?? Array.Empty<UnityYamlNode>())
                    if (t.IsScalar) tags.Add(t.Value);
                var items = root?["layers"]?.Items ?? Array.Empty<UnityYamlNode>();
                for (int i = 0; i < items.Count; i++)
                {
                    string? layer = items[i].Value;
                    if (!string.IsNullOrEmpty(layer)) layers[i] = layer;
                }
            }
            catch (FormatException) { } // reported by CheckSettingsFile
        }
        _tagManager = (tags, layers);
        return _tagManager.Value;
    }

    /// <summary>An Input System actions asset: JSON with maps whose actions have unique names and ids, and bindings that name them.</summary>
    void CheckInputActions(string file)
    {
        JsonDocument doc;
        try { doc = JsonDocument.Parse(ReadText(file)); }
        catch (JsonException e)
        {
            ReportAt(file, $"does not parse as JSON: {e.Message}");
            return;
        }
        using (doc)
        {
            var root = doc.RootElement;
            if (root.ValueKind != JsonValueKind.Object || !root.TryGetProperty("maps", out var maps) || maps.ValueKind != JsonValueKind.Array)
            {
                ReportAt(file, "an .inputactions asset is a JSON object with a \"maps\" array");
                return;
            }
            var ids = new HashSet<string>(StringComparer.Ordinal);
            foreach (var map in maps.EnumerateArray())
            {
                var mapName = Text(map, "name");
                if (string.IsNullOrEmpty(mapName)) ReportAt(file, "an action map has no name");
                CheckId(file, map, $"map '{mapName}'", ids);
                var actions = new HashSet<string>(StringComparer.Ordinal);
                foreach (var action in Elements(map, "actions"))
                {
                    var actionName = Text(action, "name");
                    if (string.IsNullOrEmpty(actionName)) ReportAt(file, $"map '{mapName}' has an action without a name");
                    else if (!actions.Add(actionName)) ReportAt(file, $"map '{mapName}' has two actions named '{actionName}'");
                    CheckId(file, action, $"action '{mapName}/{actionName}'", ids);
                }
                foreach (var binding in Elements(map, "bindings"))
                {
                    var target = Text(binding, "action") ?? "";
                    var slash = target.IndexOf('/');
                    var local = slash >= 0 && target[..slash] == mapName ? target[(slash + 1)..] : target;
                    if (target.Length > 0 && !actions.Contains(local))
                        ReportAt(file, $"map '{mapName}' has a binding '{Text(binding, "path")}' for unknown action '{target}'");
                    CheckId(file, binding, $"binding '{Text(binding, "path")}' in map '{mapName}'", ids);
                }
            }
        }
    }

    void CheckId(string file, JsonElement element, string what, HashSet<string> ids)
    {
        var id = Text(element, "id");
        if (string.IsNullOrEmpty(id)) return; // Unity assigns missing ids on import
        if (!Guid.TryParse(id, out _)) ReportAt(file, $"{what} has id '{id}', which is not a GUID");
        else if (!ids.Add(id)) ReportAt(file, $"{what} reuses id {id}");
    }

    static string? Text(JsonElement e, string name) =>
        e.ValueKind == JsonValueKind.Object && e.TryGetProperty(name, out var v) && v.ValueKind == JsonValueKind.String ? v.GetString() : null;

    static IEnumerable<JsonElement> Elements(JsonElement e, string name) =>
        e.ValueKind == JsonValueKind.Object && e.TryGetProperty(name, out var v) && v.ValueKind == JsonValueKind.Array
            ? v.EnumerateArray().ToList() : Enumerable.Empty<JsonElement>();
}
