using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Scenes;

/// <summary>A GameObject of a scene with its components resolved through <c>m_Component</c>.</summary>
public sealed class UnityGameObject
{
    readonly UnityScene _scene;

    internal UnityGameObject(UnityScene scene, UnityDocument document)
    {
        _scene = scene;
        Document = document;
    }

    public UnityDocument Document { get; }
    public long FileId => Document.FileId;
    public string Name => Document.Root.GetString("m_Name", "");
    public string Tag => Document.Root.GetString("m_TagString", "Untagged");
    public int Layer => Document.Root.GetInt("m_Layer", 0);

    /// <summary>The documents listed in <c>m_Component</c>, in order (missing ones skipped).</summary>
    public IEnumerable<UnityDocument> Components =>
        Document.Root["m_Component"]?.Items
            .Select(i => _scene.File.Find(i.GetReference("component")))
            .OfType<UnityDocument>() ?? Enumerable.Empty<UnityDocument>();

    /// <summary>The Transform (or RectTransform) component, or null.</summary>
    public UnityDocument? Transform => Components.FirstOrDefault(c => UnityScene.IsTransform(c));

    public UnityDocument? Component(string typeName) => Components.FirstOrDefault(c => c.TypeName == typeName);

    public IEnumerable<UnityDocument> ComponentsOfType(string typeName) => Components.Where(c => c.TypeName == typeName);

    /// <summary>MonoBehaviours on this object whose script has <paramref name="scriptGuid"/>.</summary>
    public IEnumerable<UnityDocument> Behaviours(string scriptGuid) =>
        Components.Where(c => c.TypeName == "MonoBehaviour" && c.ScriptGuid == scriptGuid);

    public UnityGameObject? Parent
    {
        get
        {
            var t = Transform;
            var father = t == null ? null : _scene.File.Find(t.Root.GetReference("m_Father"));
            return father == null ? null : _scene.GameObjectOf(father);
        }
    }

    public IEnumerable<UnityGameObject> Children =>
        Transform?.Root["m_Children"]?.Items
            .Select(i => _scene.File.Find(i.GetReference("")))
            .OfType<UnityDocument>()
            .Select(d => _scene.GameObjectOf(d))
            .OfType<UnityGameObject>() ?? Enumerable.Empty<UnityGameObject>();

    public Vector3 LocalPosition => Transform?.Root.GetVector3("m_LocalPosition", Vector3.Zero) ?? Vector3.Zero;
    public Quaternion LocalRotation => Transform is { } t && t.Root["m_LocalRotation"] != null ? t.Root.GetQuaternion("m_LocalRotation") : Quaternion.Identity;
    public Vector3 LocalScale => Transform?.Root.GetVector3("m_LocalScale", Vector3.One) ?? Vector3.One;

    /// <summary>World pose composed through every parent.</summary>
    public WorldTransform World => Transform is { } t ? _scene.WorldTransformOf(t) : WorldTransform.Identity;

    /// <summary>
    /// This object, its parent, its parent's parent... up to the root. Stops before an object comes round again, so a
    /// parent cycle in a broken scene (see <see cref="UnityScene.ParentCycles"/>) ends the walk instead of looping.
    /// </summary>
    public IEnumerable<UnityGameObject> SelfAndAncestors
    {
        get
        {
            var seen = new HashSet<long>();
            for (UnityGameObject? g = this; g != null && seen.Add(g.FileId); g = g.Parent) yield return g;
        }
    }

    /// <summary>"Parent/Child" path from the scene root, for messages.</summary>
    public string HierarchyPath => string.Join("/", SelfAndAncestors.Select(g => g.Name).Reverse());

    public override string ToString() => $"GameObject '{Name}' &{FileId}";
}
