using System.Diagnostics.CodeAnalysis;
using System.Globalization;

namespace SphFluid.UnityFiles.Yaml;

/// <summary>
/// A serialized object reference <c>{fileID: N, guid: G, type: T}</c>. Same-file references carry no guid;
/// <c>{fileID: 0}</c> is null.
/// </summary>
public sealed record UnityReference(long FileId, string? Guid, int Type)
{
    /// <summary>Asset of built-in extra resources (primitive meshes, default textures).</summary>
    public const string BuiltinExtraGuid = "0000000000000000e000000000000000";
    /// <summary>Built-in default resources (Default-Material, Standard shader, skybox).</summary>
    public const string BuiltinDefaultGuid = "0000000000000000f000000000000000";

    public bool IsNull => FileId == 0 && string.IsNullOrEmpty(Guid);
    /// <summary>An object in the same file (no guid).</summary>
    public bool IsLocal => FileId != 0 && string.IsNullOrEmpty(Guid);
    public bool IsExternal => !string.IsNullOrEmpty(Guid);
    public bool IsBuiltin => Guid == BuiltinExtraGuid || Guid == BuiltinDefaultGuid;

    public static bool TryFrom(UnityYamlNode? node, [NotNullWhen(true)] out UnityReference? reference)
    {
        reference = null;
        if (node == null || !node.IsMapping) return false;
        var fileId = node["fileID"];
        if (fileId == null || !fileId.IsScalar) return false;
        if (!long.TryParse(fileId.Value, NumberStyles.Integer, CultureInfo.InvariantCulture, out var id)) return false;
        string? guid = node["guid"]?.Value;
        int type = node.TryGetLong("type", out var t) ? (int)t : 0;
        reference = new UnityReference(id, string.IsNullOrEmpty(guid) ? null : guid, type);
        return true;
    }

    public override string ToString() => Guid == null
        ? $"{{fileID: {FileId}}}"
        : $"{{fileID: {FileId}, guid: {Guid}, type: {Type}}}";
}
