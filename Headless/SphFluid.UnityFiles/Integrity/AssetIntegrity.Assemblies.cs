using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using SphFluid.UnityFiles.Assets;

namespace SphFluid.UnityFiles.Integrity;

public sealed partial class AssetIntegrity
{
    readonly List<AssemblyDefinition> _asmdefs = new();

    void CheckAssemblies()
    {
        foreach (var file in _assetFiles.Where(f => Extension(f).Equals(".asmdef", StringComparison.OrdinalIgnoreCase)))
        {
            try
            {
                var asmdef = AssemblyDefinition.Load(file);
                if (string.IsNullOrWhiteSpace(asmdef.Name)) ReportAt(file, "asmdef has no \"name\"");
                else _asmdefs.Add(asmdef);
            }
            catch (Exception e) when (e is JsonException or FormatException)
            {
                ReportAt(file, $"asmdef JSON does not parse: {e.Message}");
            }
        }
        // Only named asmdefs are kept (above), so Name ?? "" never groups an unnamed one.
        foreach (var group in _asmdefs.GroupBy(a => a.Name ?? "", StringComparer.Ordinal).Where(g => g.Count() > 1))
            foreach (var a in group.Skip(1))
                ReportAt(a.Path, $"assembly name '{a.Name}' is also used by '{Rel(group.First().Path)}'");

        var byName = _asmdefs.GroupBy(a => a.Name ?? "", StringComparer.Ordinal).ToDictionary(g => g.Key, g => g.First(), StringComparer.Ordinal);
        var byGuid = new Dictionary<string, AssemblyDefinition>(StringComparer.Ordinal);
        foreach (var a in _asmdefs)
            if (_metaByAsset.TryGetValue(a.Path, out var meta) && meta.Guid != null) byGuid[meta.Guid] = a;

        foreach (var a in _asmdefs)
        {
            CheckAssembly(a, byName, byGuid);
            CheckVersionDefines(a);
        }
    }

    void CheckAssembly(AssemblyDefinition a, Dictionary<string, AssemblyDefinition> byName, Dictionary<string, AssemblyDefinition> byGuid)
    {
        var referenced = new List<string>();
        foreach (var reference in a.References)
        {
            string? name;
            AssemblyDefinition? target = null;
            if (reference.StartsWith("GUID:", StringComparison.Ordinal))
            {
                var guid = reference[5..];
                if (byGuid.TryGetValue(guid, out target)) name = target.Name ?? guid; // only named asmdefs are kept
                else if (!UnityKnownIds.PackageAssemblyGuids.TryGetValue(guid, out name))
                {
                    ReportAt(a.Path, $"reference '{reference}' matches no asmdef .meta in the project and no known package assembly");
                    continue;
                }
            }
            else
            {
                name = reference;
                byName.TryGetValue(name, out target);
            }
            referenced.Add(name);
            if (target != null)
            {
                if (target == a) ReportAt(a.Path, "references itself");
                if (target.IsEditorOnly && !a.IsEditorOnly)
                    ReportAt(a.Path, $"runs outside the editor but references Editor-only '{target.Name}' (player builds would fail)");
                if (a.NoEngineReferences && !target.NoEngineReferences)
                    ReportAt(a.Path, $"has noEngineReferences but references '{target.Name}', which uses the engine");
                continue;
            }
            if (!UnityKnownIds.PackageAssemblies.TryGetValue(name, out var package))
                ReportAt(a.Path, $"reference '{reference}' resolves to no asmdef under Assets/ or an embedded package, nor a known package assembly");
            else if (IsOptional(a, package))
                continue; // Unity drops a reference to an absent assembly; the code behind the versionDefines symbol goes with it
            else if (_manifest != null && !_manifest.Has(package))
                ReportAt(a.Path, $"reference '{name}' needs package {package} in Packages/manifest.json");
            else if (name == "Unity.InputSystem.TestFramework" && _manifest != null && !_manifest.Testables.Contains("com.unity.inputsystem"))
                ReportAt(a.Path, "Unity.InputSystem.TestFramework needs \"testables\": [\"com.unity.inputsystem\"] in Packages/manifest.json");
        }
        foreach (var dll in a.PrecompiledReferences)
        {
            if (UnityKnownIds.PackageDlls.TryGetValue(dll, out var package))
            {
                if (_manifest != null && !_manifest.Has(package)) ReportAt(a.Path, $"precompiled reference '{dll}' needs package {package}");
            }
            else if (!_assetFiles.Any(f => Path.GetFileName(f).Equals(dll, StringComparison.OrdinalIgnoreCase)))
                ReportAt(a.Path, $"precompiled reference '{dll}' is no DLL in the project or a known package");
        }
        if (a.PrecompiledReferences.Count > 0 && !a.OverrideReferences)
            ReportAt(a.Path, "precompiledReferences are only used with overrideReferences: true");
        if (a.IsTestAssembly)
        {
            if (!a.OverrideReferences || !a.PrecompiledReferences.Contains("nunit.framework.dll"))
                ReportAt(a.Path, "a test assembly needs overrideReferences: true and precompiledReferences [\"nunit.framework.dll\"]");
            foreach (var runner in new[] { "UnityEngine.TestRunner", "UnityEditor.TestRunner" }.Where(r => !referenced.Contains(r)))
                ReportAt(a.Path, $"a test assembly references {runner}");
            if (a.AutoReferenced) ReportAt(a.Path, "a test assembly should have autoReferenced: false (nothing may depend on tests)");
        }
    }

    /// <summary>
    /// Whether <paramref name="a"/> uses <paramref name="package"/> only when present: the package (or one it brings,
    /// such as URP's SRP Core) is named by one of the asmdef's versionDefines.
    /// </summary>
    static bool IsOptional(AssemblyDefinition a, string package) =>
        a.VersionDefines.Any(v => v.Name == package ||
            (v.Name != null && UnityKnownIds.PackageDependencies.TryGetValue(v.Name, out var brought) && brought.Contains(package)));

    void CheckVersionDefines(AssemblyDefinition a)
    {
        foreach (var v in a.VersionDefines)
        {
            var where = $"versionDefines entry for '{v.Name}'";
            if (string.IsNullOrWhiteSpace(v.Name)) ReportAt(a.Path, "a versionDefines entry has no \"name\" (a package name or \"Unity\")");
            if (v.Define == null || !System.Text.RegularExpressions.Regex.IsMatch(v.Define, "^[A-Za-z_][A-Za-z0-9_]*$"))
                ReportAt(a.Path, $"{where} defines '{v.Define}', which is no C# symbol");
            if (v.Expression != null && v.Expression.Length > 0 && !System.Text.RegularExpressions.Regex.IsMatch(v.Expression, @"^\s*([\[(]\s*[0-9][0-9A-Za-z.\-]*\s*(,\s*[0-9][0-9A-Za-z.\-]*\s*)?[\])]|[0-9][0-9A-Za-z.\-]*|[\[(]\s*,\s*[0-9][0-9A-Za-z.\-]*\s*[\])]|[\[(]\s*[0-9][0-9A-Za-z.\-]*\s*,\s*[\])])\s*$"))
                ReportAt(a.Path, $"{where} has expression '{v.Expression}', which is no version or version range (e.g. 14.0.0 or [14.0,15.0))");
        }
    }

    /// <summary>The asmdef that compiles <paramref name="csFile"/>: the nearest one in its folder or above, within the asset root.</summary>
    AssemblyDefinition? AssemblyOf(string csFile)
    {
        for (var dir = Path.GetDirectoryName(csFile); dir != null && dir.Length >= _root.Length; dir = Path.GetDirectoryName(dir))
        {
            var a = _asmdefs.FirstOrDefault(x => Path.GetDirectoryName(x.Path) == dir);
            if (a != null) return a;
            if (Directory.Exists(dir) && Directory.GetFiles(dir, "*.asmdef").Length > 0) return null; // unparseable asmdef: already reported
        }
        return null;
    }
}
