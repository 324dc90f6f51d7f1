using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using SphFluid.UnityFiles.Integrity;
using SphFluid.UnityFiles.Scenes;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Headless.Scenes;

/// <summary>
/// The documents of a scene file that the fluid is read from, and the integrity check's problems split by them. Unity
/// plays a scene whose camera script has a field it no longer declares, or whose prop lost its script, and warns; the
/// reader refused every such scene, so a user's own scene ran in Unity and not here. A problem on a document the fluid
/// is read from still refuses the scene; one on any other document is a warning.
/// </summary>
/// <remarks>
/// Read from: the fluid's components (<see cref="RuntimeScripts.Components"/>), and a MonoBehaviour whose script is
/// missing but which carries a field of theirs (a SpawnBox whose script reference broke looks so, and Unity would drop
/// it without a word); every document these reference, save the Transforms' <c>m_Children</c> (a child does not move
/// its parent) and a GameObject's components other than its Transform; every prefab instance and stripped stand-in,
/// since which instance holds or places the fluid is told only after they are checked. A problem on the file as a
/// whole (its header, an anchor two documents share), or one that names a document read from, refuses too.
/// </remarks>
public static partial class FluidDocuments
{
    /// <summary>The most unread problems a warning lists; the rest are counted.</summary>
    public const int MaxListed = 10;

    [GeneratedRegex(@"&(-?\d+)|fileID: (-?\d+)")]
    private static partial Regex NamedDocument();

    /// <summary><paramref name="problems"/> (the integrity check's, of <paramref name="scene"/>, each at a path relative to
    /// <paramref name="projectRoot"/>) split into those on what the fluid is read from and the rest.
    /// <paramref name="fluidScripts"/> are the guids of the fluid's components.</summary>
    public static (IReadOnlyList<IntegrityProblem> Read, IReadOnlyList<IntegrityProblem> Unread) Split(
        UnityScene scene, string projectRoot, IReadOnlyList<IntegrityProblem> problems, IReadOnlyCollection<string> fluidScripts)
    {
        var file = scene.File;
        string? scenePath = file.Path == null ? null : Path.GetFullPath(file.Path);
        var readFrom = ReadFrom(file, problems, fluidScripts);
        var shared = new HashSet<long>(file.DuplicateFileIds);
        var read = new List<IntegrityProblem>();
        var unread = new List<IntegrityProblem>();
        foreach (var problem in problems)
        {
            var document = DocumentAt(file, problem.Line);
            bool onTheFluid = scenePath == null || Path.GetFullPath(problem.Path, projectRoot) != scenePath || document == null
                || shared.Contains(document.FileId) || readFrom.Contains(document.FileId)
                || NamedDocument().Matches(problem.Message).Any(m => long.TryParse(m.Groups[1].Success ? m.Groups[1].Value : m.Groups[2].Value,
                    NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out long id) && readFrom.Contains(id));
            (onTheFluid ? read : unread).Add(problem);
        }
        return (read, unread);
    }

    /// <summary>The warning for <paramref name="unread"/> problems of the scene at <paramref name="scenePath"/>, or null
    /// for none: each at its line, at most <see cref="MaxListed"/>.</summary>
    public static string? Warning(string scenePath, IReadOnlyList<IntegrityProblem> unread)
    {
        if (unread.Count == 0) return null;
        var lines = unread.Take(MaxListed).Select(p => Located(scenePath, p)).ToList();
        if (unread.Count > MaxListed) lines.Add($"... and {unread.Count - MaxListed} more");
        return $"{scenePath}: the integrity check finds {unread.Count} problem(s) on objects the fluid is not read from; Unity plays " +
            "the scene with them (dropping what it cannot read), and so does this run:\n  " + string.Join("\n  ", lines);
    }

    /// <summary>A problem of the scene at <paramref name="scenePath"/> as <c>scene:line: message</c>, as given on the command
    /// line rather than relative to the project.</summary>
    public static string Located(string scenePath, IntegrityProblem problem) =>
        $"{scenePath}{(problem.Line > 0 ? ":" + problem.Line.ToString(CultureInfo.InvariantCulture) : "")}: {problem.Message}";

    /// <summary>The fileIDs of the documents the fluid is read from (see the remarks above).</summary>
    static HashSet<long> ReadFrom(UnityYamlFile file, IReadOnlyList<IntegrityProblem> problems, IReadOnlyCollection<string> fluidScripts)
    {
        var problemLines = new HashSet<int>(problems.Select(p => p.Line));
        var fields = new HashSet<string>(RuntimeScripts.Fields.Values.SelectMany(f => f), StringComparer.Ordinal);
        var pending = new Stack<UnityDocument>();
        foreach (var d in file.Documents)
        {
            bool fluid = d.ClassId == UnityScene.MonoBehaviourClassId && !d.IsStripped
                && (d.ScriptGuid is { } guid && fluidScripts.Contains(guid)
                    || ScriptMissing(d, problemLines) && d.Root.Keys.Any(fields.Contains));
            if (fluid || d.IsStripped || d.ClassId == UnityScene.PrefabInstanceClassId) pending.Push(d);
        }
        var readFrom = new HashSet<long>();
        while (pending.Count > 0)
        {
            var d = pending.Pop();
            if (!readFrom.Add(d.FileId)) continue;
            foreach (var (path, reference) in d.Root.References())
            {
                if (!reference.IsLocal || path.StartsWith("m_Children", StringComparison.Ordinal)) continue;
                if (file.Find(reference.FileId) is not { } target) continue;
                if (d.ClassId == UnityScene.GameObjectClassId && path.StartsWith("m_Component", StringComparison.Ordinal) && !UnityScene.IsTransform(target)) continue;
                pending.Push(target);
            }
        }
        return readFrom;
    }

    /// <summary>A MonoBehaviour with no script, or one the integrity check refuses at its <c>m_Script</c>.</summary>
    static bool ScriptMissing(UnityDocument d, HashSet<int> problemLines) =>
        d.Script is not { } script || script.IsNull || d.Root["m_Script"] is { } node && problemLines.Contains(node.Line);

    /// <summary>The document whose text holds <paramref name="line"/> (the last to start at or before it; documents
    /// are in file order), or null for a line before the first.</summary>
    static UnityDocument? DocumentAt(UnityYamlFile file, int line)
    {
        var documents = file.Documents;
        int lo = 0, hi = documents.Count;
        while (lo < hi)
        {
            int mid = (lo + hi) >> 1;
            if (documents[mid].Line <= line) lo = mid + 1; else hi = mid;
        }
        return line > 0 && lo > 0 ? documents[lo - 1] : null;
    }
}
