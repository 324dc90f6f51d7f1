using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Scenes;

/// <summary>
/// A scene (or prefab) as GameObjects, components and a Transform hierarchy, read from its YAML documents.
/// Use <see cref="Behaviours(string)"/> with a script's .meta guid to find the components a runner cares about,
/// then read their serialized fields from <see cref="UnityDocument.Root"/>.
/// </summary>
public sealed class UnityScene
{
    public const int GameObjectClassId = 1;
    public const int TransformClassId = 4;
    public const int RectTransformClassId = 224;
    public const int MonoBehaviourClassId = 114;
    public const int SceneRootsClassId = 1660057539;
    public const int PrefabInstanceClassId = 1001;

    readonly Dictionary<long, UnityGameObject> _gameObjects = new();
    readonly Dictionary<long, WorldTransform> _worldCache = new();

    public UnityScene(UnityYamlFile file)
    {
        File = file ?? throw new ArgumentNullException(nameof(file));
        foreach (var d in file.Documents)
            if (d.ClassId == GameObjectClassId && !d.IsStripped && !_gameObjects.ContainsKey(d.FileId))
                _gameObjects.Add(d.FileId, new UnityGameObject(this, d));
    }

    public UnityYamlFile File { get; }
    public string? Path => File.Path;
    public string Name => System.IO.Path.GetFileNameWithoutExtension(File.Path ?? "");

    public static UnityScene Load(string path) => new(UnityYamlFile.Load(path));

    public static UnityScene Parse(string text, string? path = null) => new(UnityYamlFile.Parse(text, path));

    public IEnumerable<UnityGameObject> GameObjects => _gameObjects.Values;

    public UnityGameObject? GameObject(long fileId) => _gameObjects.TryGetValue(fileId, out var g) ? g : null;

    /// <summary>The first GameObject named <paramref name="name"/>, or null.</summary>
    public UnityGameObject? FindGameObject(string name) => _gameObjects.Values.FirstOrDefault(g => g.Name == name);

    /// <summary>The GameObject owning a component document (via its <c>m_GameObject</c>).</summary>
    public UnityGameObject? GameObjectOf(UnityDocument? component) =>
        component == null ? null
        : component.ClassId == GameObjectClassId ? GameObject(component.FileId)
        : GameObject(component.GameObject?.FileId ?? 0);

    /// <summary>Every MonoBehaviour document, or those whose <c>m_Script</c> guid is <paramref name="scriptGuid"/>.</summary>
    public IEnumerable<UnityDocument> Behaviours(string? scriptGuid = null) =>
        File.Documents.Where(d => d.ClassId == MonoBehaviourClassId && !d.IsStripped && (scriptGuid == null || d.ScriptGuid == scriptGuid));

    public IEnumerable<UnityDocument> Transforms => File.Documents.Where(d => IsTransform(d) && !d.IsStripped);

    /// <summary>Transforms with no parent (what <c>SceneRoots</c> must list).</summary>
    public IEnumerable<UnityDocument> RootTransforms =>
        Transforms.Where(t => t.Root.GetReference("m_Father") is not { IsNull: false });

    /// <summary>The fileIDs listed by the <c>SceneRoots</c> document (2022.2+), or null when the file has none.</summary>
    public IReadOnlyList<long>? SceneRoots
    {
        get
        {
            var roots = File.OfClass(SceneRootsClassId).FirstOrDefault();
            return roots?.Root["m_Roots"]?.Items.Select(i => i.GetReference("")?.FileId ?? 0).ToList()
                   ?? (roots == null ? null : new List<long>());
        }
    }

    /// <summary>
    /// Every loop in the parent chains of the GameObjects (through their Transforms' <c>m_Father</c>): an object that is
    /// its own parent, or two or more that are each other's ancestors. Each cycle lists its objects from child to
    /// parent. Unity cannot load such a scene; every walk up the hierarchy would go round forever.
    /// </summary>
    public IReadOnlyList<IReadOnlyList<UnityGameObject>> ParentCycles()
    {
        // Each object has at most one parent, so following parents from every object once finds every loop in
        // linear time: a walk that meets an object of its own walk has closed a loop.
        var walkOf = new Dictionary<long, int>();
        var cycles = new List<IReadOnlyList<UnityGameObject>>();
        int walk = 0;
        foreach (var start in _gameObjects.Values)
        {
            walk++;
            var path = new List<UnityGameObject>();
            var g = start;
            while (g != null && !walkOf.ContainsKey(g.FileId))
            {
                walkOf[g.FileId] = walk;
                path.Add(g);
                g = g.Parent;
            }
            if (g == null || walkOf[g.FileId] != walk) continue;
            int first = path.FindIndex(p => p.FileId == g.FileId);
            if (first >= 0) cycles.Add(path.GetRange(first, path.Count - first));
        }
        return cycles;
    }

    public static bool IsTransform(UnityDocument d) => d.ClassId == TransformClassId || d.ClassId == RectTransformClassId;

    /// <summary>World pose of a Transform document, composing <c>m_Father</c> up to the root.</summary>
    public WorldTransform WorldTransformOf(UnityDocument transform)
    {
        // Up the chain to a cached or parentless Transform, then composed back down: a loop, not recursion, so a
        // deep hierarchy cannot exhaust the stack, and a parent cycle is named instead of followed.
        var chain = new List<UnityDocument>();
        var seen = new HashSet<long>();
        var parent = WorldTransform.Identity;
        for (var t = transform; t != null; t = Father(t))
        {
            if (_worldCache.TryGetValue(t.FileId, out var cached))
            {
                parent = cached;
                break;
            }
            if (!seen.Add(t.FileId))
                throw new InvalidDataException($"{Path}: Transform &{t.FileId} is its own ancestor (a parent cycle through m_Father)");
            chain.Add(t);
        }
        for (int i = chain.Count - 1; i >= 0; i--)
        {
            var r = chain[i].Root;
            var rotation = r["m_LocalRotation"] != null ? r.GetQuaternion("m_LocalRotation") : Quaternion.Identity;
            parent = parent.Compose(r.GetVector3("m_LocalPosition", Vector3.Zero), rotation, r.GetVector3("m_LocalScale", Vector3.One));
            _worldCache[chain[i].FileId] = parent;
        }
        return parent;
    }

    UnityDocument? Father(UnityDocument transform)
    {
        var father = File.Find(transform.Root.GetReference("m_Father"));
        return father != null && IsTransform(father) ? father : null;
    }

    public WorldTransform WorldTransformOf(long transformFileId) =>
        WorldTransformOf(File.Find(transformFileId) ?? throw new ArgumentException($"{Path}: no document &{transformFileId}"));
}
