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
/// to. Unity builds each instance at load from the two, and so does the reader: a SpawnBox made a prefab, placed twice and
/// tuned per instance, runs as it plays in Unity. A prefab that nests others, or a variant (an instance of its base with
/// overrides), is built the same way, innermost first. Before, such a box was left out without a word (OilAndWater with
/// its Oil box made a prefab ran as water alone).
/// A prefab that cannot be built (one that nests a model, whose objects come from its importer, not from YAML) is read
/// past when it holds none of the fluid's components; one that holds them, or has them added or placed under an
/// instance, is refused naming the instance and how to unpack it.
/// </summary>
public static partial class PrefabInstances
{
    /// <summary>The scene with every prefab instance that holds, carries or places the fluid built into it (a prop's is
    /// left as it stands), as Unity builds it at load: the prefab's objects, less those the instance removes, with its
    /// overrides applied, its root under the instance's parent, and each object under the fileID of its stand-in. Throws a <see cref="SceneException"/> for a prefab the
    /// integrity check refuses, for an override of a fluid component's field that its prefab does not have, and for each
    /// part of the fluid that lies in an instance it cannot build. A value read from a prefab keeps its line there
    /// (<see cref="UnityYamlNode.SourceFile"/> names the prefab), an overridden one is at its override's line.</summary>
    public static UnityScene Build(string path, UnityScene scene, UnityProject project, string packageFolder)
    {
        var scripts = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string name in RuntimeScripts.Components)
            if (FluidPackage.ScriptGuid(project, packageFolder, name) is { } guid) scripts[guid] = name; // the reader refuses a missing one by name
        var prefabs = new PrefabReader(path, project, scripts);

        var problems = new List<string>();
        var toBuild = new List<(UnityDocument Instance, Prefab Prefab)>();
        var placing = InstancesPlacingTheFluid(scene, scripts, prefabs, project);
        foreach (var instance in scene.File.OfClass(UnityScene.PrefabInstanceClassId))
        {
            string? prefabPath = project.AssetPathOf(instance.Root.GetReference("m_SourcePrefab"));
            if (prefabPath == null) continue; // an unknown guid is the integrity check's refusal
            var prefab = prefabs.Get(prefabPath);
            // A prop's instance places none of the fluid (an instance whose prefab holds some is among the placing): it is
            // neither built nor held to the integrity check.
            if (!placing.Contains(instance.FileId) && prefab.Unreadable == null) continue;
            if (prefab.Unreadable != null)
                problems.Add($"{path}:{instance.Line}: {Named(instance, prefab)}: its prefab cannot be read ({prefab.Unreadable}), so whether it holds the fluid's components cannot be told");
            else if (prefabs.Build(prefab) != null)
                toBuild.Add((instance, prefab));
            else if (prefab.Held.Count > 0)
                problems.Add($"{path}:{instance.Line}: {Named(instance, prefab)} holds {string.Join(", ", prefab.Held)}; the reader cannot build it: {prefab.NotBuilt}");
        }

        // A prefab Unity would refuse or break on (two documents under one fileID, a parent cycle, two roots, a script
        // guid no .meta has) would build some other scene: the prefabs get the scene's own check before any is built.
        var used = toBuild.Select(b => b.Prefab).Distinct().ToList();
        var prefabProblems = used.Count == 0 ? Array.Empty<IntegrityProblem>()
            : AssetIntegrity.CheckScenes(project, used.SelectMany(p => p.Contents!.Sources).Distinct().ToList());
        if (prefabProblems.Count > 0)
            throw new SceneException($"{path}: the integrity check refuses prefabs the scene's instances are built from ({prefabProblems.Count} problem(s)):\n  " +
                string.Join("\n  ", prefabProblems));

        var taken = new HashSet<long>(scene.File.Documents.Select(d => d.FileId));
        var standIns = StandIns(scene.File);
        var unused = used.SelectMany(p => p.Contents!.UnusedOverrides).ToList();
        var built = new List<UnityDocument>();
        foreach (var (instance, prefab) in toBuild)
            built.AddRange(Instantiate(path, standIns, instance, prefab, prefabs, taken, unused));
        // Unity keeps an override of a field its component no longer has, and ignores it; on the fluid's own components
        // the reader refuses it, as it refuses a field it does not know in the scene itself.
        if (unused.Count > 0)
            throw new SceneException($"{path}: prefab instances that hold or place the fluid carry overrides the reader refuses ({unused.Count}):\n  " +
                string.Join("\n  ", unused) + "\n  Unity keeps an override of a field or object its prefab lacks and ignores it: remove " +
                "such unused overrides in the Inspector (the instance's Overrides dropdown, Unused overrides), and the others from the " +
                "instance's m_Modifications in the scene file, to run the scene here");

        // The stand-ins of the instances built give way to the objects they stood for; one that stands for no object
        // stays, stripped, and what lies on or under it is refused below.
        var replaced = new HashSet<long>(built.Select(d => d.FileId));
        var file = new UnityYamlFile(scene.File.Path, scene.File.Headers,
            scene.File.Documents.Where(d => !replaced.Contains(d.FileId)).Concat(built).ToList());
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
                problems.Add($"{path}:{behaviour.Line}: a {script} added to a GameObject of {Instance(result, project, owner, prefabs)}, which the reader cannot build");
                continue;
            }
            var go = result.GameObjectOf(behaviour);
            if (go?.Transform is { } transform && StrippedAncestor(result, transform) is { } ancestor)
                problems.Add($"{path}:{behaviour.Line}: the {script} of GameObject '{go.Name}', which lies under a GameObject of " +
                    $"{Instance(result, project, ancestor, prefabs)} that places it, which the reader cannot build");
        }

        if (problems.Count > 0)
            throw new SceneException($"{path}: parts of the fluid lie in prefab instances the headless reader cannot build " +
                $"({problems.Count}):\n  {string.Join("\n  ", problems)}\n  Unpack each such instance in Unity (in the Hierarchy, " +
                "right-click it, Prefab > Unpack Completely) to run the scene here");
        return result;
    }

    /// <summary>The instances that hold a fluid component, have one added to a GameObject of theirs, or place one:
    /// those on the way up from it, and from each such instance's parent in turn, to the scene's root.</summary>
    static HashSet<long> InstancesPlacingTheFluid(UnityScene scene, IReadOnlyDictionary<string, string> scripts, PrefabReader prefabs,
        UnityProject project)
    {
        var file = scene.File;
        var placing = new HashSet<long>();
        var pending = new Stack<UnityDocument>(); // Transforms, or stand-ins for them, whose chain of parents is to be walked
        foreach (var instance in file.OfClass(UnityScene.PrefabInstanceClassId))
            if (project.AssetPathOf(instance.Root.GetReference("m_SourcePrefab")) is { } prefab && prefabs.Get(prefab).Held.Count > 0)
                pending.Push(instance);
        foreach (var behaviour in scene.Behaviours())
            if (behaviour.ScriptGuid is { } guid && scripts.ContainsKey(guid) && file.Find(behaviour.GameObject) is { } owner)
                pending.Push(owner.IsStripped ? owner : scene.GameObjectOf(behaviour)?.Transform ?? owner);

        var walked = new HashSet<long>();
        while (pending.Count > 0)
        {
            var d = pending.Pop();
            if (!walked.Add(d.FileId)) continue;
            if (d.ClassId == UnityScene.PrefabInstanceClassId)
            {
                placing.Add(d.FileId);
                if (file.Find(d.Root["m_Modification"]?.GetReference("m_TransformParent")) is { } parent) pending.Push(parent);
            }
            else if (d.IsStripped)
            {
                if (file.Find(d.Root.GetReference("m_PrefabInstance")) is { } instance) pending.Push(instance);
            }
            else if (file.Find(d.Root.GetReference("m_Father")) is { } father)
                pending.Push(father);
        }
        return placing;
    }

    /// <summary>A file's stripped stand-ins, by the fileID of the instance each stands in for.</summary>
    static ILookup<long, UnityDocument> StandIns(UnityYamlFile file) =>
        file.Documents.Where(d => d.IsStripped).ToLookup(d => d.Root.GetReference("m_PrefabInstance")?.FileId ?? 0);

    /// <summary>One instance's objects, built from its prefab as Unity builds them. <paramref name="path"/> is the file
    /// holding the instance (a scene, or a prefab that nests it), whose fileIDs <paramref name="taken"/> lists.</summary>
    static List<UnityDocument> Instantiate(string path, ILookup<long, UnityDocument> standIns, UnityDocument instance, Prefab prefab,
        PrefabReader prefabs, HashSet<long> taken, List<string> unused)
    {
        var modification = instance.Root["m_Modification"];
        var contents = prefab.Contents!;
        var objects = contents.File.Documents;

        // The objects the file refers to keep the fileID of their stand-in; the others get the instance's fileID xor their
        // own, which is how Unity derives the fileIDs that the overrides of an instance of a nesting prefab name.
        var ids = new Dictionary<long, long>();
        foreach (var standIn in standIns[instance.FileId])
            if (standIn.Root.GetReference("m_CorrespondingSourceObject") is { } source && source.Guid == prefab.Guid)
                ids[source.FileId] = standIn.FileId;
        var removed = Removed(modification, prefab);
        var kept = objects.Where(d => !removed.Contains(d.FileId)).ToList();
        prefabs.CountBuilt(kept.Count, prefab.Path, path);
        foreach (var d in kept)
            if (!ids.ContainsKey(d.FileId))
                ids[d.FileId] = FreeId((instance.FileId ^ d.FileId) & long.MaxValue, taken);

        // Named once: it reads the overrides, and a refusal of 60 000 of them named the instance afresh for each (minutes).
        string? name = null;
        string Name() => name ??= Named(instance, prefab);
        string At(UnityYamlNode entry) => $"{path}:{entry["propertyPath"]?.Line ?? entry.Line}: {Name()} overrides";

        // Unity removes neither a GameObject's Transform nor the instance's root (deleting the instance removes that); a
        // hand-written removal of either left the box at the world's origin, or left it out, without a word.
        foreach (var item in modification?["m_RemovedComponents"]?.Items ?? Array.Empty<UnityYamlNode>())
            if (UnityReference.TryFrom(item, out var r) && r.Guid == prefab.Guid && contents.File.Find(r.FileId) is { } c && UnityScene.IsTransform(c))
                unused.Add($"{path}:{item.Line}: {Name()} removes the {c.TypeName} &{r.FileId} of {prefab.Path}, " +
                    "which Unity cannot remove: a GameObject keeps its Transform");
        foreach (var item in modification?["m_RemovedGameObjects"]?.Items ?? Array.Empty<UnityYamlNode>())
            if (UnityReference.TryFrom(item, out var r) && r.Guid == prefab.Guid && r.FileId == contents.RootObject)
                unused.Add($"{path}:{item.Line}: {Name()} removes the root GameObject of {prefab.Path}, which Unity " +
                    "does not: deleting the instance is how its root leaves the scene");

        // Unity writes one override a field; should a hand-merged file hold two, the later wins, as it does in Unity.
        var overrides = new Dictionary<(long Target, string Path), UnityYamlNode>();
        foreach (var entry in modification?["m_Modifications"]?.Items ?? Array.Empty<UnityYamlNode>())
        {
            if (entry.GetReference("target") is not { } target) continue;
            string property = entry.GetString("propertyPath", "") ?? "";
            // Which object a component is on, which script it runs and where a Transform hangs are the prefab's; Unity
            // restructures no instance, and an override of them (a hand edit) made a SpawnBox vanish without a word.
            if (target.Guid == prefab.Guid && Structural.Contains(property.Split('.', '[')[0]))
                unused.Add($"{At(entry)} {Described(prefab, target.FileId, prefabs)}.{property}, which ties the prefab's " +
                    "objects together: Unity writes no such override (it restructures no instance), and what it would build from a hand-written one is not known here");
            else if (target.Guid == prefab.Guid)
                overrides[(target.FileId, property)] = entry;
            // An override names an object of the instance's own prefab; one of another asset's (a hand edit, or a merge
            // gone wrong) changes nothing in Unity, and in a prefab holding the fluid may have been meant for a fluid field.
            else if (prefab.Held.Count > 0 && !target.IsNull)
                unused.Add($"{At(entry)} {property} of " +
                    $"&{target.FileId} {(target.IsLocal ? "of this file" : $"of another asset (guid {target.Guid})")}; an instance's " +
                    $"overrides name objects of its own prefab, {prefab.Path}");
        }
        var applied = new HashSet<(long, string)>();
        var misfits = new Dictionary<(long, string), UnityYamlNode>(); // fields an override names that its value cannot stand for
        var parent = modification?["m_TransformParent"];

        var built = new List<UnityDocument>();
        foreach (var d in kept)
        {
            bool isRoot = d.FileId == contents.RootTransform;
            var root = d.Root.CopyFrom(prefab.Path, (property, node) =>
            {
                if (overrides.TryGetValue((d.FileId, property), out var entry))
                {
                    if (Override(node, entry) is { } value)
                    {
                        applied.Add((d.FileId, property));
                        return value;
                    }
                    misfits[(d.FileId, property)] = node;
                }
                if (isRoot && property == "m_Father" && parent != null) return parent.CopyFrom(null, (_, _) => null);
                // A reference within the prefab follows its object to the fileID it has here; one to a removed object is null.
                if (UnityReference.TryFrom(node, out var reference) && reference.IsLocal)
                    return UnityYamlNode.LocalReference(ids.TryGetValue(reference.FileId, out long id) ? id : 0, instance.Line);
                return null;
            });
            built.Add(new UnityDocument(d.ClassId, ids[d.FileId], d.TypeName, root, IsStripped: false, instance.Line));
        }

        // An override the prefab has no field for changes nothing in Unity. The reader refuses one of a fluid component's,
        // and, in a prefab holding the fluid's components, one whose object it cannot find: that may be a fluid field too.
        foreach (var ((target, property), entry) in overrides)
        {
            if (applied.Contains((target, property)) || removed.Contains(target)) continue;
            string at = At(entry);
            if (contents.File.Find(target) is not { } component)
            {
                if (prefab.Held.Count > 0) unused.Add($"{at} {property} of &{target}, which {prefab.Path} does not hold");
            }
            else if (component.ScriptGuid is { } guid && prefabs.Scripts.TryGetValue(guid, out string? script))
                unused.Add(misfits.TryGetValue((target, property), out var field)
                    ? $"{at} {script}.{property}, {Misfit(field, property)}"
                    : $"{at} {script}.{property}, which is no field of the {script} in {prefab.Path}");
        }
        return built;
    }

    /// <summary>The fields that tie a prefab's objects together (a component to its GameObject and script, a Transform to
    /// its parent and children, an object to its source), which an instance in Unity does not override.</summary>
    static readonly HashSet<string> Structural = new(StringComparer.Ordinal)
    {
        "m_GameObject", "m_Script", "m_Component", "m_Father", "m_Children", "m_CorrespondingSourceObject", "m_PrefabInstance", "m_PrefabAsset",
    };

    /// <summary>An object of <paramref name="prefab"/> as a refusal names it: a fluid component by its script, any other
    /// by its type, one the prefab does not hold by its fileID.</summary>
    static string Described(Prefab prefab, long fileId, PrefabReader prefabs) =>
        prefab.Contents!.File.Find(fileId) is not { } d ? $"&{fileId}"
        : d.ScriptGuid is { } guid && prefabs.Scripts.TryGetValue(guid, out string? script) ? script : d.TypeName;

    /// <summary>The new value of a field an override names: its <c>objectReference</c> for a reference field, its
    /// <c>value</c> for a plain one, at the override's line; null where the override cannot stand for the node (a
    /// mapping or a sequence, which Unity overrides field by field).</summary>
    static UnityYamlNode? Override(UnityYamlNode node, UnityYamlNode entry)
    {
        var replacement = node.IsReference ? entry["objectReference"] : node.IsScalar ? entry["value"] : null;
        if (replacement == null || replacement.IsReference != node.IsReference) return null;
        return replacement.CopyFrom(null, (_, _) => null);
    }

    /// <summary>Why an override cannot stand for the field it names: Unity writes one per value, never one for a block.</summary>
    static string Misfit(UnityYamlNode field, string property) =>
        field.IsReference ? "a reference, with no objectReference to put in it"
        : field.IsMapping ? $"a block of fields, with one value (Unity overrides each field of it: {property}.<field>)"
        : field.IsSequence ? $"a list, with one value (Unity overrides its length and items: {property}.Array.size, {property}.Array.data[i])"
        : "a value, with none to put in it";

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
        if (gone.Count == 0) return removed;
        var scene = new UnityScene(prefab.Contents!.File);
        // Looked up, not scanned for each GameObject removed: removing the top of a chain of 4 000 took 40 s.
        var children = scene.GameObjects.ToLookup(g => g.Parent?.FileId ?? 0);
        while (gone.Count > 0)
        {
            var go = scene.GameObject(gone.Dequeue());
            if (go == null || !removed.Add(go.FileId)) continue;
            foreach (var item in go.Document.Root["m_Component"]?.Items ?? Array.Empty<UnityYamlNode>())
                if (item.GetReference("component") is { } c) removed.Add(c.FileId);
            foreach (var child in children[go.FileId]) gone.Enqueue(child.FileId);
        }
        return removed;
    }

    static long FreeId(long wanted, HashSet<long> taken)
    {
        long id = wanted == 0 ? 1 : wanted;
        while (!taken.Add(id)) id = id == long.MaxValue ? 1 : id + 1;
        return id;
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
    static string Instance(UnityScene scene, UnityProject project, UnityDocument stripped, PrefabReader prefabs)
    {
        var instance = scene.File.Find(stripped.Root.GetReference("m_PrefabInstance"));
        if (instance == null) return "a prefab instance";
        string? prefab = project.AssetPathOf(instance.Root.GetReference("m_SourcePrefab"));
        return prefab == null ? $"PrefabInstance &{instance.FileId} of an unknown prefab" : Named(instance, prefabs.Get(prefab));
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
