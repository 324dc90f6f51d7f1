namespace SphFluid.UnityFiles.Yaml;

/// <summary>
/// One <c>--- !u!&lt;ClassId&gt; &amp;&lt;FileId&gt;</c> document: an object of type <see cref="TypeName"/>
/// whose serialized fields are <see cref="Root"/> (the mapping under the type-name key).
/// </summary>
public sealed record UnityDocument(int ClassId, long FileId, string TypeName, UnityYamlNode Root, bool IsStripped, int Line)
{
    /// <summary>The owning GameObject of a component (<c>m_GameObject</c>), or null.</summary>
    public UnityReference? GameObject => Root.GetReference("m_GameObject");

    /// <summary>For a MonoBehaviour: the script reference (<c>m_Script</c>), or null.</summary>
    public UnityReference? Script => Root.GetReference("m_Script");

    /// <summary>For a MonoBehaviour: the guid of its script's .cs file, or null.</summary>
    public string? ScriptGuid => Script?.Guid;

    public override string ToString() => $"--- !u!{ClassId} &{FileId} {TypeName} (line {Line})";
}
