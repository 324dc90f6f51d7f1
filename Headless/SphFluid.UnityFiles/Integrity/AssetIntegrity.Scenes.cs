using System.Collections.Generic;
using System.Linq;
using SphFluid.UnityFiles.Scenes;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Integrity;

public sealed partial class AssetIntegrity
{
    /// <summary>"GameObject 'A' &amp;1 is its own parent" or "GameObjects 'A' &amp;1 -> 'B' &amp;3 -> 'A' form a parent cycle".</summary>
    public static string ParentCycleMessage(IReadOnlyList<UnityGameObject> cycle)
    {
        static string Name(UnityGameObject g) => $"'{g.Name}' &{g.FileId}";
        return cycle.Count == 1
            ? $"GameObject {Name(cycle[0])} is its own parent (its Transform's m_Father points back at it)"
            : $"GameObjects {string.Join(" -> ", cycle.Append(cycle[0]).Select(Name))} form a parent cycle through Transform.m_Father";
    }

    /// <summary>
    /// Unity writes a bool as 0 or 1. Which GameObjects and components count (the scene reader's spawn boxes among them)
    /// follows m_IsActive and m_Enabled, so any other value is refused rather than read as one or the other.
    /// </summary>
    void CheckFlag(string file, UnityYamlNode root, string key, string owner)
    {
        if (root[key] is not { } flag || flag.AsFlag != null) return;
        ReportAt(file, $"{owner} {key} must be 0 or 1 (was '{flag}')", flag.Line);
    }

    /// <summary>
    /// GameObject ↔ component back references, Transform parent ↔ children agreement, and (scenes) SceneRoots equal to the
    /// parentless Transforms (unity-kit §4.1, §4.5).
    /// </summary>
    void CheckSceneStructure(string file, UnityYamlFile yaml, bool isScene)
    {
        if (isScene)
            foreach (var (classId, type) in UnityKnownIds.SceneSettings)
                if (!yaml.OfClass(classId).Any()) ReportAt(file, $"has no {type} document (!u!{classId})");

        foreach (var go in yaml.OfClass(UnityScene.GameObjectClassId).Where(d => !d.IsStripped))
        {
            var name = $"GameObject '{go.Root.GetString("m_Name", "")}' &{go.FileId}";
            CheckFlag(file, go.Root, "m_IsActive", name);
            var components = go.Root["m_Component"]?.Items.Select(i => i.GetReference("component")).ToList();
            if (components == null || components.Count == 0)
            {
                ReportAt(file, $"{name} has no m_Component list (it needs at least its Transform)", go.Line);
                continue;
            }
            int transforms = 0;
            for (int i = 0; i < components.Count; i++)
            {
                var c = yaml.Find(components[i]);
                if (c == null)
                {
                    ReportAt(file, $"{name} m_Component[{i}] {components[i]} is not a document in this file", go.Root.At($"m_Component[{i}]")?.Line ?? go.Line);
                    continue;
                }
                if (UnityScene.IsTransform(c)) transforms++;
                if (i == 0 && !UnityScene.IsTransform(c)) ReportAt(file, $"{name} must list its Transform first (found {c.TypeName})", go.Root.At($"m_Component[{i}]")?.Line ?? go.Line);
                if (c.GameObject?.FileId != go.FileId)
                    ReportAt(file, $"{name} lists {c.TypeName} &{c.FileId}, whose m_GameObject is {c.GameObject?.ToString() ?? "missing"}", c.Root["m_GameObject"]?.Line ?? c.Line);
            }
            if (transforms != 1) ReportAt(file, $"{name} has {transforms} Transforms (exactly one required)", go.Line);
        }

        foreach (var c in yaml.Documents.Where(d => !d.IsStripped && d.ClassId != UnityScene.GameObjectClassId && d.Root.Has("m_GameObject")))
        {
            CheckFlag(file, c.Root, "m_Enabled", $"{c.TypeName} &{c.FileId}");
            var owner = yaml.Find(c.GameObject);
            if (owner == null)
            {
                if (c.GameObject is { IsNull: false, IsLocal: true }) continue; // dangling local reference: reported by CheckReferences
                ReportAt(file, $"{c.TypeName} &{c.FileId} has no owning GameObject", c.Line);
                continue;
            }
            if (owner.IsStripped) continue; // component added to a prefab instance
            if (owner.ClassId != UnityScene.GameObjectClassId)
            {
                ReportAt(file, $"{c.TypeName} &{c.FileId} m_GameObject points at a {owner.TypeName}", c.Root["m_GameObject"]?.Line ?? c.Line);
                continue;
            }
            var listed = owner.Root["m_Component"]?.Items.Any(i => i.GetReference("component")?.FileId == c.FileId) ?? false;
            if (!listed) ReportAt(file, $"{c.TypeName} &{c.FileId} belongs to GameObject &{owner.FileId}, which does not list it in m_Component", c.Root["m_GameObject"]?.Line ?? c.Line);
        }

        var transformDocs = yaml.Documents.Where(d => UnityScene.IsTransform(d) && !d.IsStripped).ToList();
        foreach (var t in transformDocs)
        {
            var fatherRef = t.Root.GetReference("m_Father");
            if (fatherRef is { IsNull: false })
            {
                var father = yaml.Find(fatherRef);
                if (father != null && !father.IsStripped)
                {
                    if (!UnityScene.IsTransform(father)) ReportAt(file, $"Transform &{t.FileId} m_Father points at a {father.TypeName}", t.Root["m_Father"]?.Line ?? t.Line);
                    else if (!(father.Root["m_Children"]?.Items.Any(i => i.GetReference("")?.FileId == t.FileId) ?? false))
                        ReportAt(file, $"Transform &{t.FileId} names &{father.FileId} as m_Father, which does not list it in m_Children", t.Root["m_Father"]?.Line ?? t.Line);
                }
            }
            foreach (var childRef in t.Root["m_Children"]?.Items.Select(i => i.GetReference("")) ?? Enumerable.Empty<UnityReference>())
            {
                var child = yaml.Find(childRef);
                if (child == null || child.IsStripped) continue;
                if (!UnityScene.IsTransform(child)) ReportAt(file, $"Transform &{t.FileId} lists a {child.TypeName} as a child", t.Root["m_Children"]?.Line ?? t.Line);
                else if (child.Root.GetReference("m_Father")?.FileId != t.FileId)
                    ReportAt(file, $"Transform &{t.FileId} lists child &{child.FileId}, whose m_Father is {child.Root.GetReference("m_Father")?.ToString() ?? "missing"}", t.Root["m_Children"]?.Line ?? t.Line);
            }
        }

        // An instance's root hangs under its m_TransformParent as a Transform hangs under its m_Father; the reader took one
        // pointing at a GameObject for no parent and built the instance at the scene's root.
        foreach (var instance in yaml.OfClass(UnityScene.PrefabInstanceClassId))
        {
            var parent = instance.Root.At("m_Modification.m_TransformParent");
            if (yaml.Find(instance.Root.GetReference("m_Modification.m_TransformParent")) is { } found && !UnityScene.IsTransform(found))
                ReportAt(file, $"PrefabInstance &{instance.FileId} m_Modification.m_TransformParent points at a {found.TypeName}, not a Transform", parent?.Line ?? instance.Line);
        }

        foreach (var cycle in new UnityScene(yaml).ParentCycles())
            ReportAt(file, ParentCycleMessage(cycle), cycle[0].Transform?.Root["m_Father"]?.Line ?? cycle[0].Document.Line);

        var parentless = transformDocs.Where(t => t.Root.GetReference("m_Father") is not { IsNull: false }).Select(t => t.FileId).ToList();
        var rootsDoc = yaml.OfClass(UnityScene.SceneRootsClassId).ToList();
        if (!isScene)
        {
            if (parentless.Count != 1 && !yaml.OfClass(UnityScene.PrefabInstanceClassId).Any())
                ReportAt(file, $"a prefab needs exactly one root Transform (found {parentless.Count})");
            return;
        }
        if (rootsDoc.Count != 1)
        {
            ReportAt(file, $"a 2022.3 scene has exactly one SceneRoots document (&9223372036854775807), found {rootsDoc.Count}");
            return;
        }
        var listedRoots = rootsDoc[0].Root["m_Roots"]?.Items.Select(i => i.GetReference("")?.FileId ?? 0).ToList() ?? new List<long>();
        foreach (var id in listedRoots.GroupBy(x => x).Where(g => g.Count() > 1).Select(g => g.Key))
            ReportAt(file, $"SceneRoots lists &{id} twice", rootsDoc[0].Line);
        foreach (var id in parentless.Where(id => !listedRoots.Contains(id)))
            ReportAt(file, $"root Transform &{id} is missing from SceneRoots", rootsDoc[0].Line);
        foreach (var id in listedRoots.Distinct())
        {
            var d = yaml.Find(id);
            if (d == null) continue; // dangling: reported by CheckReferences
            if (!UnityScene.IsTransform(d)) ReportAt(file, $"SceneRoots lists &{id}, a {d.TypeName}, not a Transform", rootsDoc[0].Line);
            else if (!d.IsStripped && !parentless.Contains(id)) ReportAt(file, $"SceneRoots lists Transform &{id}, which has a parent", rootsDoc[0].Line);
        }
    }
}
