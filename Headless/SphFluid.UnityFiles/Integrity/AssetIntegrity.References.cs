using System;
using System.IO;
using System.Linq;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Integrity;

public sealed partial class AssetIntegrity
{
    void CheckSerializedFiles()
    {
        foreach (var file in _assetFiles)
        {
            if (!StartsWithYamlHeader(file)) continue;
            UnityYamlFile yaml;
            try { yaml = UnityYamlFile.Load(file); }
            catch (Exception e) when (e is FormatException or IOException)
            {
                ReportAt(file, $"Unity would refuse this YAML: {e.Message}");
                continue;
            }
            CheckSerializedFile(file, yaml);
        }
        foreach (var file in _assetFiles.Where(f => Extension(f) == ".inputactions")) CheckInputActions(file);
        CheckShadersFoundByName();
    }

    void CheckSerializedFile(string file, UnityYamlFile yaml)
    {
        if (!yaml.HasUnityHeader) ReportAt(file, $"must start with '{UnityYamlFile.YamlHeader}' and '{UnityYamlFile.TagHeader}'", 1);
        foreach (var id in yaml.DuplicateFileIds.Distinct())
        {
            var lines = yaml.Documents.Where(d => d.FileId == id).Select(d => d.Line).ToList();
            ReportAt(file, $"anchor &{id} is used by more than one document (lines {string.Join(", ", lines)}); references to it reach only the first", lines[1]);
        }
        foreach (var d in yaml.Documents)
            if (UnityKnownIds.TypeNames.TryGetValue(d.ClassId, out var type) && type != d.TypeName)
                ReportAt(file, $"document &{d.FileId} is class {d.ClassId} ({type}) but its root key is '{d.TypeName}'", d.Line);
        if (_metaByAsset.TryGetValue(file, out var meta) && meta.MainObjectFileId is long main && yaml.Find(main) == null)
            ReportAt(file, $"its .meta says mainObjectFileID {main} but no document is '&{main}'");
        CheckReferences(file, yaml);
        CheckScripts(file, yaml);
        var ext = Extension(file);
        if (ext == ".unity" || ext == ".prefab")
        {
            CheckSceneStructure(file, yaml, ext == ".unity");
            CheckTagsAndLayers(file, yaml);
        }
    }

    static bool StartsWithYamlHeader(string file)
    {
        try
        {
            if (UnityTextFile.LengthOf(file) == 0) return false; // empty, or a pipe that opening would block on
            using var reader = new StreamReader(file);
            var first = reader.ReadLine();
            return first != null && first.StartsWith("%YAML", StringComparison.Ordinal);
        }
        catch (IOException) { return false; }
    }

    /// <summary>Every <c>{fileID, guid, type}</c> in the file resolves, with the main-object id and type its target's extension takes.</summary>
    void CheckReferences(string file, UnityYamlFile yaml)
    {
        foreach (var doc in yaml.Documents)
        {
            // References() passes over these, so a typo would otherwise read as an unassigned field.
            foreach (var node in doc.Root.DescendantsAndSelf())
                if (node.IsReference && !UnityReference.TryFrom(node, out _))
                    ReportAt(file, $"&{doc.FileId} {doc.TypeName} has a reference whose fileID '{node["fileID"]!.Value}' is not a 64-bit integer, as Unity's fileIDs are", node.Line);
            foreach (var (path, r) in doc.Root.References())
            {
                var where = $"&{doc.FileId} {doc.TypeName}.{path}";
                int line = doc.Root.At(path)?.Line ?? doc.Line;
                if (r.IsNull) continue;
                if (r.IsLocal)
                {
                    if (yaml.Find(r.FileId) == null) ReportAt(file, $"{where} points at &{r.FileId}, which is not in this file", line);
                    continue;
                }
                if (!UnityMeta.IsValidGuid(r.Guid))
                {
                    ReportAt(file, $"{where} has malformed guid '{r.Guid}'", line);
                    continue;
                }
                if (r.IsBuiltin) continue;
                if (UnityKnownIds.PackageObjectGuids.TryGetValue(r.Guid, out var packaged))
                {
                    if (_manifest != null && !_manifest.Has(packaged.Package) && !InSample(file))
                        ReportAt(file, $"{where} uses {packaged.Name}, which needs {packaged.Package} in Packages/manifest.json", line);
                    continue;
                }
                if (Extension(file) == ".unity") _sceneReferencedGuids.Add(r.Guid);
                if (Extension(file) == ".mat" && path == "m_Shader") _materialShaders[file] = r.Guid;
                if (!_assetByGuid.TryGetValue(r.Guid, out var target))
                {
                    ReportAt(file, $"{where} references guid {r.Guid}, which no .meta in the project has", line);
                    continue;
                }
                CheckMainObject(file, where, line, r, target);
            }
        }
    }

    void CheckMainObject(string file, string where, int line, UnityReference r, string target)
    {
        var ext = Extension(target);
        var rule = UnityKnownIds.MainObjects.FirstOrDefault(kv => kv.Key.Equals(ext, StringComparison.OrdinalIgnoreCase));
        if (rule.Key == null) return;
        var (fileId, type) = rule.Value;
        var name = Rel(target);
        if (r.Type != type) ReportAt(file, $"{where} references '{name}' with type {r.Type}; a {ext} takes type {type}", line);
        if (fileId is long expected)
        {
            if (r.FileId != expected) ReportAt(file, $"{where} references '{name}' with fileID {r.FileId}; a {ext} main object is {expected}", line);
        }
        else if (r.FileId == 0) ReportAt(file, $"{where} references '{name}' with fileID 0", line);
        else if (ext.Equals(".asset", StringComparison.OrdinalIgnoreCase) && StartsWithYamlHeader(target))
        {
            try
            {
                if (UnityYamlFile.Load(target).Find(r.FileId) == null)
                    ReportAt(file, $"{where} references &{r.FileId} in '{name}', which has no such object", line);
            }
            catch (FormatException) { } // the target's own parse error is reported on the target
        }
    }
}
