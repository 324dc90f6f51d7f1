using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Scenes;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Headless.Scenes;

/// <summary>
/// The scene reader reads the GameObjects a scene file holds. A prefab instance's GameObjects and components are in its
/// .prefab file, and the scene holds only what the instance overrides, so a fluid component in a prefab, one added to an
/// instance's GameObject, or one under such a GameObject (whose placement the prefab holds) would be left out or misplaced
/// without a word: OilAndWater with its Oil box made a prefab ran as water alone. Such a scene is refused, naming each
/// instance and how to unpack it; instances that hold none of the fluid's components (props, lights) are read past.
/// </summary>
public static class PrefabInstances
{
    public const int PrefabInstanceClassId = 1001;

    static readonly string[] FluidScripts =
    {
        RuntimeScripts.Fluid, RuntimeScripts.SpawnBox, RuntimeScripts.FluidContainer, RuntimeScripts.SphereObstacle,
        RuntimeScripts.ContainerSpinner, RuntimeScripts.SphereDriver,
    };

    /// <summary>Throws a <see cref="SceneException"/> listing every part of the fluid that lies in a prefab instance.</summary>
    public static void RefuseFluidIn(string path, UnityScene scene, UnityProject project, string packageFolder)
    {
        var scripts = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string name in FluidScripts)
            if (FluidPackage.ScriptGuid(project, packageFolder, name) is { } guid) scripts[guid] = name; // the reader refuses a missing one by name

        var problems = new List<string>();
        // A scene may hold a prop's instance hundreds of times: each prefab is read once.
        var read = new Dictionary<string, PrefabContents>(StringComparer.Ordinal);
        PrefabContents Contents(string prefab)
        {
            if (!read.TryGetValue(prefab, out var contents))
                read[prefab] = contents = Read(project, prefab, scripts);
            return contents;
        }

        foreach (var instance in scene.File.OfClass(PrefabInstanceClassId))
        {
            string? prefab = project.AssetPathOf(instance.Root.GetReference("m_SourcePrefab"));
            if (prefab == null) continue; // an unknown guid is the integrity check's refusal
            var contents = Contents(prefab);
            if (contents.Unreadable != null)
                problems.Add($"{path}:{instance.Line}: {Named(instance, prefab, contents)}: its prefab cannot be read ({contents.Unreadable}), so whether it holds the fluid's components cannot be told");
            else if (contents.Held.Count > 0)
                problems.Add($"{path}:{instance.Line}: {Named(instance, prefab, contents)} holds {string.Join(", ", contents.Held)}");
        }

        foreach (var behaviour in scene.Behaviours())
        {
            if (behaviour.ScriptGuid is not { } guid || !scripts.TryGetValue(guid, out string? script)) continue;
            var owner = scene.File.Find(behaviour.GameObject);
            if (owner is { IsStripped: true })
            {
                problems.Add($"{path}:{behaviour.Line}: a {script} added to a GameObject of {Instance(scene, project, owner, Contents)}");
                continue;
            }
            var go = scene.GameObjectOf(behaviour);
            if (go?.Transform is { } transform && StrippedAncestor(scene, transform) is { } ancestor)
                problems.Add($"{path}:{behaviour.Line}: the {script} of GameObject '{go.Name}', which lies under a GameObject of " +
                    $"{Instance(scene, project, ancestor, Contents)} that places it");
        }

        if (problems.Count > 0)
            throw new SceneException($"{path}: parts of the fluid lie in prefab instances, which the headless reader does not read " +
                $"({problems.Count}):\n  {string.Join("\n  ", problems)}\n  The reader reads the GameObjects a scene file holds, and a " +
                "prefab's are in its own file: unpack each instance in Unity (in the Hierarchy, right-click it, Prefab > Unpack Completely) to run the scene here");
    }

    /// <summary>What the reader needs of one prefab: the fluid's components in it and in the prefabs nested in it, why it
    /// could not be read (or null), and its root GameObject, whose name an instance's m_Name override replaces.</summary>
    sealed record PrefabContents(List<string> Held, string? Unreadable, long RootObject);

    static PrefabContents Read(UnityProject project, string prefab, IReadOnlyDictionary<string, string> scripts)
    {
        var held = new List<string>();
        string? unreadable = FluidComponentsIn(project, prefab, scripts, held, new HashSet<string>(StringComparer.Ordinal), nested: false, out long root);
        return new PrefabContents(held, unreadable, root);
    }

    /// <summary>Adds to <paramref name="held"/> each fluid component of the prefab at <paramref name="prefab"/> and of the
    /// prefabs nested in it (named with their file); returns why a file could not be read, or null.
    /// <paramref name="rootObject"/> is the fileID of the prefab's root GameObject, 0 where it has none of its own (a
    /// variant's root is its base's).</summary>
    static string? FluidComponentsIn(UnityProject project, string prefab, IReadOnlyDictionary<string, string> scripts,
        List<string> held, HashSet<string> visited, bool nested, out long rootObject)
    {
        rootObject = 0;
        // A model (.fbx) stands in as a prefab too, and holds no scripts.
        if (!prefab.EndsWith(".prefab", StringComparison.OrdinalIgnoreCase) || !visited.Add(prefab)) return null;
        UnityScene file;
        try { file = UnityScene.Load(project.FullPath(prefab)); }
        catch (Exception e) when (e is FormatException or IOException or UnauthorizedAccessException) { return e.Message; }

        rootObject = file.RootTransforms.FirstOrDefault()?.GameObject?.FileId ?? 0;
        foreach (var behaviour in file.Behaviours())
            if (behaviour.ScriptGuid is { } guid && scripts.TryGetValue(guid, out string? script))
                held.Add($"a {script} on its GameObject '{file.File.Find(behaviour.GameObject)?.Root.GetString("m_Name", "") ?? ""}'" +
                    (nested ? $" (in {prefab}, nested in it)" : ""));
        foreach (var instance in file.File.OfClass(PrefabInstanceClassId))
            if (project.AssetPathOf(instance.Root.GetReference("m_SourcePrefab")) is { } inner &&
                FluidComponentsIn(project, inner, scripts, held, visited, nested: true, out _) is { } unreadable)
                return unreadable;
        return null;
    }

    /// <summary>The first stripped Transform above <paramref name="transform"/>: a GameObject of a prefab instance.</summary>
    static UnityDocument? StrippedAncestor(UnityScene scene, UnityDocument transform)
    {
        var seen = new HashSet<long>();
        for (var t = scene.File.Find(transform.Root.GetReference("m_Father")); t != null && seen.Add(t.FileId);
             t = scene.File.Find(t.Root.GetReference("m_Father")))
            if (t.IsStripped) return t;
        return null;
    }

    /// <summary>The prefab instance a stripped document belongs to, named with its prefab.</summary>
    static string Instance(UnityScene scene, UnityProject project, UnityDocument stripped, Func<string, PrefabContents> contents)
    {
        var instance = scene.File.Find(stripped.Root.GetReference("m_PrefabInstance"));
        if (instance == null) return "a prefab instance";
        string? prefab = project.AssetPathOf(instance.Root.GetReference("m_SourcePrefab"));
        return prefab == null ? Named(instance, "an unknown prefab", null) : Named(instance, prefab, contents(prefab));
    }

    /// <summary>"PrefabInstance 'Oil' of Assets/Prefabs/Oil.prefab": the name the instance gives its root GameObject (an
    /// m_Name override of another of its GameObjects names that one, not the instance), else its prefab's.</summary>
    static string Named(UnityDocument instance, string prefab, PrefabContents? contents)
    {
        string? guid = instance.Root.GetReference("m_SourcePrefab")?.Guid;
        string? name = contents is { RootObject: not 0 } ? instance.Root["m_Modification"]?["m_Modifications"]?.Items
            .LastOrDefault(m => m.GetString("propertyPath", "") == "m_Name" && m.GetReference("target") is { } target &&
                target.FileId == contents.RootObject && target.Guid == guid)?.GetString("value", "") : null;
        return $"PrefabInstance '{name ?? Path.GetFileNameWithoutExtension(prefab)}' of {prefab}";
    }
}
