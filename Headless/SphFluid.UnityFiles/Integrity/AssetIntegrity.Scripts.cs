using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Integrity;

public sealed partial class AssetIntegrity
{
    [GeneratedRegex(@"\b(?<mods>(?:(?:public|internal|private|protected|sealed|abstract|static|partial|unsafe|new)\s+)*)class\s+(?<name>[A-Za-z_]\w*)\s*(?<generic><[^>{]*>)?\s*(?::\s*(?<bases>[^{]+?))?\s*(?:where\b[^{]*)?\{")]
    private static partial Regex ClassDeclaration();

    [GeneratedRegex(@"//[^\n]*|/\*.*?\*/", RegexOptions.Singleline)]
    private static partial Regex Comments();

    sealed record ScriptClass(string Name, bool IsAbstract, bool IsStatic, bool IsGeneric, string? Base, string File);

    Dictionary<string, List<ScriptClass>>? _classes;
    /// <summary>Why a script is not a usable MonoBehaviour, or null when it is, by .cs file.</summary>
    readonly Dictionary<string, string?> _scriptVerdicts = new(StringComparer.Ordinal);

    /// <summary>Every MonoBehaviour's <c>m_Script</c> names a .cs whose file name is a concrete MonoBehaviour/ScriptableObject class in it.</summary>
    void CheckScripts(string file, UnityYamlFile yaml)
    {
        bool isScene = Extension(file) is ".unity" or ".prefab";
        foreach (var doc in yaml.Documents.Where(d => d.ClassId == 114 && !d.IsStripped))
        {
            var where = $"MonoBehaviour &{doc.FileId} (line {doc.Line})";
            var script = doc.Script;
            if (script == null || script.IsNull)
            {
                ReportAt(file, $"{where} has no m_Script (Missing Script)", doc.Root["m_Script"]?.Line ?? doc.Line);
                continue;
            }
            if (script.IsBuiltin || script.Guid == null) continue;
            if (UnityKnownIds.PackageObjectGuids.TryGetValue(script.Guid, out var packaged))
            {
                if (packaged.Name == UnityKnownIds.StandaloneInputModule && _activeInputHandler == 1)
                    ReportAt(file, $"{where} is uGUI's StandaloneInputModule, which reads the legacy Input Manager and throws with activeInputHandler 1; use InputSystemUIInputModule", doc.Root["m_Script"]?.Line ?? doc.Line);
                continue;
            }
            if (!_assetByGuid.TryGetValue(script.Guid, out var target)) continue; // unresolved guid: reported by CheckReferences
            var ext = Extension(target);
            if (ext.Equals(".dll", StringComparison.OrdinalIgnoreCase)) continue;
            if (!ext.Equals(".cs", StringComparison.OrdinalIgnoreCase))
            {
                ReportAt(file, $"{where} m_Script points at '{Rel(target)}', which is not a C# script", doc.Root["m_Script"]?.Line ?? doc.Line);
                continue;
            }
            var verdict = ScriptVerdict(target);
            if (verdict != null) ReportAt(file, $"{where} uses '{Rel(target)}': {verdict} (Unity shows Missing Script)", doc.Root["m_Script"]?.Line ?? doc.Line);
            else CheckSerializedFieldNames(file, where, doc, target);
            if (isScene && EditorOnly(target))
                ReportAt(file, $"{where} uses '{Rel(target)}', which compiles into an Editor-only assembly (Missing Script in players)", doc.Root["m_Script"]?.Line ?? doc.Line);
        }
    }

    static readonly HashSet<string> BehaviourKeys = new(StringComparer.Ordinal)
    {
        "m_ObjectHideFlags", "m_CorrespondingSourceObject", "m_PrefabInstance", "m_PrefabAsset", "m_GameObject", "m_Enabled",
        "m_EditorHideFlags", "m_Script", "m_Name", "m_EditorClassIdentifier",
    };

    /// <summary>
    /// A key the script does not declare is silently dropped by Unity and the field keeps its default: in a hand-written
    /// scene that is a typo. Each top-level key must appear as a word in the script or one of its project base classes.
    /// </summary>
    void CheckSerializedFieldNames(string file, string where, UnityDocument doc, string csFile)
    {
        var sources = new List<string> { Comments().Replace(ReadText(csFile), " ") };
        var current = DeclarationWithBase(Path.GetFileNameWithoutExtension(csFile));
        for (int depth = 0; current != null && depth < 20; depth++)
        {
            if (current.Base == null || UnityKnownIds.SerializableScriptBases.Contains(current.Base)) break;
            current = DeclarationWithBase(current.Base) ?? (Classes().TryGetValue(current.Base, out var list) ? list[0] : null);
            if (current != null) sources.Add(Comments().Replace(ReadText(current.File), " "));
        }
        foreach (var key in doc.Root.Keys.Where(k => !BehaviourKeys.Contains(k)))
        {
            if (!sources.Any(src => Regex.IsMatch(src, @"\b" + Regex.Escape(key) + @"\b")))
                ReportAt(file, $"{where} sets '{key}', which '{Rel(csFile)}' does not declare (Unity drops it and the field keeps its default)", doc.Root[key]?.Line ?? doc.Line);
            else if (doc.Root[key] is { IsScalar: true } value && UnwrittenScalar(sources, key, value.Value) is { } expected)
                ReportAt(file, $"{where} {key} must be {expected} (was '{value.Value}'), as Unity writes the field '{Rel(csFile)}' declares", value.Line);
        }
    }

    [GeneratedRegex(@"\b(?<type>bool|int|float)\s+(?<name>[A-Za-z_]\w*)\s*(?:=[^;]*)?;")]
    private static partial Regex ScalarField();

    /// <summary>
    /// What Unity would write for a top-level bool, int or float field in place of <paramref name="text"/>, or null when
    /// it could have written it. The scene reader reads only the fields it simulates, so a hand-edited `visible: abc` on
    /// another component would otherwise pass and leave Unity to read it as it may.
    /// </summary>
    static string? UnwrittenScalar(IEnumerable<string> sources, string key, string? text)
    {
        var type = sources.SelectMany(src => ScalarField().Matches(src)).FirstOrDefault(m => m.Groups["name"].Value == key)?.Groups["type"].Value;
        return type switch
        {
            "bool" => text is "0" or "1" ? null : "0 or 1 (a bool)",
            "int" => int.TryParse(text, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out _) ? null : "a whole number in the range of an int",
            "float" => UnityYamlNode.TryParseNumber(text, out _) ? null : "a number (a float)",
            _ => null,
        };
    }

    /// <summary>The legacy Input class throws at runtime when only the Input System is active (activeInputHandler 1).</summary>
    void CheckLegacyInput()
    {
        if (_activeInputHandler != 1) return;
        foreach (var cs in _assetFiles.Where(f => Extension(f) == ".cs"))
        {
            var text = Comments().Replace(ReadText(cs), " ");
            var m = LegacyInputCall().Match(text);
            if (m.Success)
                ReportAt(cs, $"uses the legacy Input Manager ('{m.Value}'), which throws with activeInputHandler 1; use the Input System");
        }
    }

    [GeneratedRegex(@"(?<![\w.])(?:UnityEngine\.)?Input\.(?:Get(?:Key|KeyDown|KeyUp|Axis|AxisRaw|Button|ButtonDown|ButtonUp|MouseButton|MouseButtonDown|MouseButtonUp|Touch)\b|mousePosition|mouseScrollDelta|anyKey|anyKeyDown|touchCount|inputString)")]
    private static partial Regex LegacyInputCall();

    bool EditorOnly(string csFile)
    {
        var asm = AssemblyOf(csFile);
        if (asm != null) return asm.IsEditorOnly;
        return Rel(csFile).Split('/').Contains("Editor");
    }

    /// <summary>Null when the script is fine, else why Unity cannot bind it.</summary>
    string? ScriptVerdict(string csFile)
    {
        if (_scriptVerdicts.TryGetValue(csFile, out var cached)) return cached;
        var className = Path.GetFileNameWithoutExtension(csFile);
        var own = ReadClasses(csFile).Where(c => c.Name == className).ToList();
        string? verdict = null;
        if (own.Count == 0) verdict = $"declares no class named '{className}' (the class name must equal the file name)";
        else
        {
            // A partial class may name its base in another file.
            var c = own.FirstOrDefault(x => x.Base != null) ?? DeclarationWithBase(className) ?? own[0];
            if (c.IsGeneric) verdict = $"'{className}' is generic";
            else if (c.IsAbstract) verdict = $"'{className}' is abstract";
            else if (c.IsStatic) verdict = $"'{className}' is static";
            else verdict = BaseChainVerdict(c);
        }
        _scriptVerdicts[csFile] = verdict;
        return verdict;
    }

    string? BaseChainVerdict(ScriptClass c)
    {
        var seen = new HashSet<string>();
        var current = c;
        while (true)
        {
            var b = current.Base;
            if (b == null) return $"'{current.Name}' derives from nothing, so it is not a MonoBehaviour or ScriptableObject";
            if (UnityKnownIds.SerializableScriptBases.Contains(b)) return null;
            if (!seen.Add(b)) return $"'{c.Name}' has a base-class cycle";
            var next = DeclarationWithBase(b) ?? (Classes().TryGetValue(b, out var list) ? list.FirstOrDefault() : null);
            if (next == null) return $"'{c.Name}' derives from '{b}', which is no MonoBehaviour/ScriptableObject the project declares";
            current = next;
        }
    }

    ScriptClass? DeclarationWithBase(string name) =>
        Classes().TryGetValue(name, out var list) ? list.FirstOrDefault(c => c.Base != null) : null;

    Dictionary<string, List<ScriptClass>> Classes()
    {
        if (_classes != null) return _classes;
        _classes = new Dictionary<string, List<ScriptClass>>(StringComparer.Ordinal);
        foreach (var cs in _assetFiles.Where(f => Extension(f).Equals(".cs", StringComparison.OrdinalIgnoreCase)))
            foreach (var c in ReadClasses(cs))
            {
                if (!_classes.TryGetValue(c.Name, out var list)) _classes[c.Name] = list = new List<ScriptClass>();
                list.Add(c);
            }
        return _classes;
    }

    IEnumerable<ScriptClass> ReadClasses(string csFile)
    {
        string text;
        try { text = Comments().Replace(ReadText(csFile), " "); }
        catch (IOException) { yield break; }
        foreach (Match m in ClassDeclaration().Matches(text))
        {
            var mods = m.Groups["mods"].Value;
            string? firstBase = null;
            if (m.Groups["bases"].Success)
            {
                var b = m.Groups["bases"].Value.Split(',')[0].Trim();
                int lt = b.IndexOf('<');
                if (lt >= 0) b = b[..lt];
                firstBase = b[(b.LastIndexOf('.') + 1)..].Trim();
            }
            yield return new ScriptClass(m.Groups["name"].Value, mods.Contains("abstract"), mods.Contains("static"),
                m.Groups["generic"].Success, firstBase, csFile);
        }
    }
}
