using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Integrity;
using SphFluid.UnityFiles.Scenes;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Headless.Scenes;

/// <summary>
/// A prefab instance's GameObjects and components are in its .prefab file; the scene holds only the instance's overrides
/// (<c>m_Modifications</c>, removed components and GameObjects) and stripped stand-ins for the objects the scene refers
/// to. Unity builds each instance at load from the two; so does the reader, for a prefab that nests no other: a SpawnBox
/// made a prefab, placed twice and tuned per instance, runs as it plays in Unity. Before, such a box was left out without a
/// word (OilAndWater with its Oil box made a prefab ran as water alone).
/// A prefab that nests others, or a variant, is built from a chain of prefabs whose objects the scene addresses through
/// derived fileIDs; one that holds the fluid's components, and a component added to or placed under such an instance, is
/// refused naming the instance and how to unpack it. Instances that hold none (props, lights) are read past.
/// </summary>
public static class PrefabInstances
{
    public const int PrefabInstanceClassId = 1001;

    static readonly string[] FluidScripts =
    {
        RuntimeScripts.Fluid, RuntimeScripts.SpawnBox, RuntimeScripts.FluidContainer, RuntimeScripts.SphereObstacle,
        RuntimeScripts.ContainerSpinner, RuntimeScripts.SphereDriver,
    };

    /// <summary>The scene with every instance of a prefab that nests none built into it, as Unity builds it at load: the
    /// prefab's objects, less those the instance removes, with its overrides applied, its root under the instance's
    /// parent, and each object under the fileID of its stand-in in the scene. Throws a <see cref="SceneException"/>
    /// listing every override of a fluid component's field that its prefab does not have, else every part of the fluid
    /// that lies in an instance it cannot build. A value read from the prefab is reported at the instance's line, an overridden
    /// one at its override's.</summary>
    public static UnityScene Build(string path, UnityScene scene, UnityProject project, string packageFolder)
    {
        var scripts = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string name in FluidScripts)
            if (FluidPackage.ScriptGuid(project, packageFolder, name) is { } guid) scripts[guid] = name; // the reader refuses a missing one by name

        var problems = new List<string>();
        var unknownOverrides = new List<string>();
        // A scene may hold a prop's instance hundreds of times: each prefab is read once.
        var read = new Dictionary<string, Prefab>(StringComparer.Ordinal);
        Prefab Contents(string prefab)
        {
            if (!read.TryGetValue(prefab, out var contents))
                read[prefab] = contents = Read(project, prefab, scripts);
            return contents;
        }

        var toBuild = new List<(UnityDocument Instance, Prefab Prefab)>();
        foreach (var instance in scene.File.OfClass(PrefabInstanceClassId))
        {
            string? prefabPath = project.AssetPathOf(instance.Root.GetReference("m_SourcePrefab"));
            if (prefabPath == null) continue; // an unknown guid is the integrity check's refusal
            var prefab = Contents(prefabPath);
            if (prefab.Unreadable != null)
                problems.Add($"{path}:{instance.Line}: {Named(instance, prefab)}: its prefab cannot be read ({prefab.Unreadable}), so whether it holds the fluid's components cannot be told");
            else if (prefab.File != null)
                toBuild.Add((instance, prefab));
            else if (prefab.Held.Count > 0)
                problems.Add($"{path}:{instance.Line}: {Named(instance, prefab)} holds {string.Join(", ", prefab.Held)}, and nests other prefabs or is a variant, which the reader does not build");
        }

        // A prefab Unity would refuse or break on (two documents under one fileID, a parent cycle, two roots, a script
        // guid no .meta has) would build some other scene: the prefabs get the scene's own check before any is built.
        var prefabProblems = AssetIntegrity.CheckScenes(project.Root,
            toBuild.Select(b => b.Prefab).Distinct().Select(p => (project.FullPath(p.Path), p.File!)).ToList());
        if (prefabProblems.Count > 0)
            throw new SceneException($"{path}: the integrity check refuses prefabs the scene's instances are built from ({prefabProblems.Count} problem(s)):\n  " +
                string.Join("\n  ", prefabProblems));

        var taken = new HashSet<long>(scene.File.Documents.Select(d => d.FileId));
        var standIns = scene.File.Documents.Where(d => d.IsStripped).ToLookup(d => d.Root.GetReference("m_PrefabInstance")?.FileId ?? 0);
        var builtInto = new HashSet<long>(); // the instances built and their stand-ins, which the built objects replace
        var built = new List<UnityDocument>();
        foreach (var (instance, prefab) in toBuild)
            built.AddRange(Instantiate(path, standIns, instance, prefab, scripts, taken, builtInto, unknownOverrides));

        // Unity keeps an override of a field its component no longer has, and ignores it; on the fluid's own components
        // the reader refuses it, as it refuses a field it does not know in the scene itself.
        if (unknownOverrides.Count > 0)
            throw new SceneException($"{path}: prefab instances override fields the fluid's components do not have ({unknownOverrides.Count}):\n  " +
                string.Join("\n  ", unknownOverrides) + "\n  Unity keeps such unused overrides and ignores them: remove them in the Inspector " +
                "(the instance's Overrides dropdown, Unused overrides) to run the scene here");

        var file = new UnityYamlFile(scene.File.Path, scene.File.Headers,
            scene.File.Documents.Where(d => !builtInto.Contains(d.FileId)).Concat(built).ToList());
        var result = new UnityScene(file);
        // The scene's check saw no cycle, but an instance's m_TransformParent may lie under the instance itself.
        if (result.ParentCycles() is { Count: > 0 } cycles)
            throw new SceneException($"{path}: prefab instances put GameObjects in a parent cycle, which Unity cannot load:\n  " +
                string.Join("\n  ", cycles.Select(c => $"{path}:{c[0].Document.Line}: {AssetIntegrity.ParentCycleMessage(c)}")));

        foreach (var behaviour in result.Behaviours())
        {
            if (behaviour.ScriptGuid is not { } guid || !scripts.TryGetValue(guid, out string? script)) continue;
            var owner = file.Find(behaviour.GameObject);
            if (owner is { IsStripped: true })
            {
                problems.Add($"{path}:{behaviour.Line}: a {script} added to a GameObject of {Instance(result, project, owner, Contents)}, which the reader does not build");
                continue;
            }
            var go = result.GameObjectOf(behaviour);
            if (go?.Transform is { } transform && StrippedAncestor(result, transform) is { } ancestor)
                problems.Add($"{path}:{behaviour.Line}: the {script} of GameObject '{go.Name}', which lies under a GameObject of " +
                    $"{Instance(result, project, ancestor, Contents)} that places it, which the reader does not build");
        }

        if (problems.Count > 0)
            throw new SceneException($"{path}: parts of the fluid lie in prefab instances the headless reader cannot build " +
                $"({problems.Count}):\n  {string.Join("\n  ", problems)}\n  The reader builds instances of prefabs that nest no other " +
                "prefab: unpack each other instance in Unity (in the Hierarchy, right-click it, Prefab > Unpack Completely) to run the scene here");
        return result;
    }

    /// <summary>One instance's objects, built from its prefab as Unity builds them.</summary>
    static List<UnityDocument> Instantiate(string path, ILookup<long, UnityDocument> standIns, UnityDocument instance, Prefab prefab,
        IReadOnlyDictionary<string, string> scripts, HashSet<long> taken, HashSet<long> builtInto, List<string> unknown)
    {
        var modification = instance.Root["m_Modification"];
        builtInto.Add(instance.FileId);

        // The objects the scene refers to keep the fileID of their stand-in; the others get one of their own, derived from
        // the instance's and the object's, so that it stays the same run to run.
        var ids = new Dictionary<long, long>();
        foreach (var standIn in standIns[instance.FileId])
            if (standIn.Root.GetReference("m_CorrespondingSourceObject") is { } source && source.Guid == prefab.Guid)
            {
                ids[source.FileId] = standIn.FileId;
                builtInto.Add(standIn.FileId);
            }
        var removed = Removed(modification, prefab);
        var kept = prefab.File!.Documents.Where(d => !removed.Contains(d.FileId)).ToList();
        foreach (var d in kept)
            if (!ids.ContainsKey(d.FileId))
                ids[d.FileId] = FreeId((instance.FileId ^ d.FileId) & long.MaxValue, taken);

        // Unity writes one override a field; should a hand-merged file hold two, the later wins, as it does in Unity.
        var overrides = new Dictionary<(long Target, string Path), UnityYamlNode>();
        foreach (var entry in modification?["m_Modifications"]?.Items ?? Array.Empty<UnityYamlNode>())
            if (entry.GetReference("target") is { } target && target.Guid == prefab.Guid)
                overrides[(target.FileId, entry.GetString("propertyPath", "") ?? "")] = entry;
        var applied = new HashSet<(long, string)>();
        var parent = modification?["m_TransformParent"];

        var objects = new List<UnityDocument>();
        foreach (var d in kept)
        {
            bool isRoot = d.FileId == prefab.RootTransform;
            var root = d.Root.CopyAt(instance.Line, (property, node) =>
            {
                if (overrides.TryGetValue((d.FileId, property), out var entry) && Override(node, entry) is { } value)
                {
                    applied.Add((d.FileId, property));
                    return value;
                }
                if (isRoot && property == "m_Father" && parent != null) return parent.CopyAt(parent.Line, (_, _) => null);
                // A reference within the prefab follows its object to the fileID it has here; one to a removed object is null.
                if (UnityReference.TryFrom(node, out var reference) && reference.IsLocal)
                    return UnityYamlNode.LocalReference(ids.TryGetValue(reference.FileId, out long id) ? id : 0, instance.Line);
                return null;
            });
            objects.Add(new UnityDocument(d.ClassId, ids[d.FileId], d.TypeName, root, IsStripped: false, instance.Line));
        }

        foreach (var ((target, property), entry) in overrides)
            if (!applied.Contains((target, property)) && kept.FirstOrDefault(d => d.FileId == target) is { } component &&
                component.ScriptGuid is { } guid && scripts.TryGetValue(guid, out string? script))
                unknown.Add($"{path}:{entry["propertyPath"]?.Line ?? entry.Line}: {Named(instance, prefab)} overrides {script}.{property}, " +
                    $"which is no field of the {script} in {prefab.Path}");
        return objects;
    }

    /// <summary>The new value of a field an override names: its <c>objectReference</c> for a reference field, its
    /// <c>value</c> for a plain one, at the override's line; null where the override cannot stand for the node (a
    /// mapping or a sequence, which Unity overrides field by field).</summary>
    static UnityYamlNode? Override(UnityYamlNode node, UnityYamlNode entry)
    {
        var replacement = node.IsReference ? entry["objectReference"] : node.IsScalar ? entry["value"] : null;
        if (replacement == null || replacement.IsReference != node.IsReference) return null;
        return replacement.CopyAt(replacement.Line, (_, _) => null);
    }

    /// <summary>The prefab's objects an instance removes: its removed components, and its removed GameObjects with their
    /// components and every GameObject under them.</summary>
    static HashSet<long> Removed(UnityYamlNode? modification, Prefab prefab)
    {
        var removed = new HashSet<long>();
        foreach (var item in modification?["m_RemovedComponents"]?.Items ?? Array.Empty<UnityYamlNode>())
            if (UnityReference.TryFrom(item, out var r) && r.Guid == prefab.Guid) removed.Add(r.FileId);
        var gone = new Queue<long>();
        foreach (var item in modification?["m_RemovedGameObjects"]?.Items ?? Array.Empty<UnityYamlNode>())
            if (UnityReference.TryFrom(item, out var r) && r.Guid == prefab.Guid) gone.Enqueue(r.FileId);
        var scene = gone.Count > 0 ? new UnityScene(prefab.File!) : null;
        while (scene != null && gone.Count > 0)
        {
            var go = scene.GameObject(gone.Dequeue());
            if (go == null || !removed.Add(go.FileId)) continue;
            foreach (var item in go.Document.Root["m_Component"]?.Items ?? Array.Empty<UnityYamlNode>())
                if (item.GetReference("component") is { } c) removed.Add(c.FileId);
            foreach (var child in scene.GameObjects.Where(g => g.Parent?.FileId == go.FileId)) gone.Enqueue(child.FileId);
        }
        return removed;
    }

    static long FreeId(long wanted, HashSet<long> taken)
    {
        long id = wanted == 0 ? 1 : wanted;
        while (!taken.Add(id)) id = id == long.MaxValue ? 1 : id + 1;
        return id;
    }

    /// <summary>What the reader needs of one prefab: its file where it nests no other prefab and so can be built (else
    /// null), the fluid's components in it and in the prefabs nested in it, why it could not be read (or null), and its
    /// root GameObject and Transform.</summary>
    sealed record Prefab(string Path, string? Guid, UnityYamlFile? File, List<string> Held, string? Unreadable, long RootObject, long RootTransform);

    static Prefab Read(UnityProject project, string prefab, IReadOnlyDictionary<string, string> scripts)
    {
        var held = new List<string>();
        string? unreadable = FluidComponentsIn(project, prefab, scripts, held, new HashSet<string>(StringComparer.Ordinal), nested: false, out var file);
        var root = file == null ? null : new UnityScene(file).RootTransforms.FirstOrDefault();
        bool plain = file != null && unreadable == null && !file.Documents.Any(d => d.IsStripped || d.ClassId == PrefabInstanceClassId);
        return new Prefab(prefab, project.GuidOf(prefab), plain ? file : null, held, unreadable, root?.GameObject?.FileId ?? 0, root?.FileId ?? 0);
    }

    /// <summary>Adds to <paramref name="held"/> each fluid component of the prefab at <paramref name="prefab"/> and of the
    /// prefabs nested in it (named with their file); returns why a file could not be read, or null. <paramref name="file"/>
    /// is the prefab's own file where it was read.</summary>
    static string? FluidComponentsIn(UnityProject project, string prefab, IReadOnlyDictionary<string, string> scripts,
        List<string> held, HashSet<string> visited, bool nested, out UnityYamlFile? file)
    {
        file = null;
        // A model (.fbx) stands in as a prefab too, and holds no scripts.
        if (!prefab.EndsWith(".prefab", StringComparison.OrdinalIgnoreCase) || !visited.Add(prefab)) return null;
        try { file = UnityYamlFile.Load(project.FullPath(prefab)); }
        catch (Exception e) when (e is FormatException or IOException or UnauthorizedAccessException) { return e.Message; }

        foreach (var behaviour in file.OfClass(UnityScene.MonoBehaviourClassId))
            if (behaviour.ScriptGuid is { } guid && scripts.TryGetValue(guid, out string? script))
                held.Add($"a {script} on its GameObject '{file.Find(behaviour.GameObject)?.Root.GetString("m_Name", "") ?? ""}'" +
                    (nested ? $" (in {prefab}, nested in it)" : ""));
        foreach (var instance in file.OfClass(PrefabInstanceClassId))
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
    static string Instance(UnityScene scene, UnityProject project, UnityDocument stripped, Func<string, Prefab> contents)
    {
        var instance = scene.File.Find(stripped.Root.GetReference("m_PrefabInstance"));
        if (instance == null) return "a prefab instance";
        string? prefab = project.AssetPathOf(instance.Root.GetReference("m_SourcePrefab"));
        return prefab == null ? $"PrefabInstance &{instance.FileId} of an unknown prefab" : Named(instance, contents(prefab));
    }

    /// <summary>"PrefabInstance 'Oil' of Assets/Prefabs/Oil.prefab": the name the instance gives its root GameObject (an
    /// m_Name override of another of its GameObjects names that one, not the instance), else its prefab's.</summary>
    static string Named(UnityDocument instance, Prefab prefab)
    {
        string? name = prefab.RootObject != 0 ? instance.Root["m_Modification"]?["m_Modifications"]?.Items
            .LastOrDefault(m => m.GetString("propertyPath", "") == "m_Name" && m.GetReference("target") is { } target &&
                target.FileId == prefab.RootObject && target.Guid == prefab.Guid)?.GetString("value", "") : null;
        return $"PrefabInstance '{name ?? Path.GetFileNameWithoutExtension(prefab.Path)}' of {prefab.Path}";
    }
}
