using SphFluid.UnityFiles.Yaml;

namespace SphFluid.UnityFiles.Assets;

/// <summary><c>ProjectSettings/ProjectVersion.txt</c>: the editor version the project is for.</summary>
public sealed record ProjectVersion(string? EditorVersion, string? EditorVersionWithRevision)
{
    /// <summary>"2022.3" from "2022.3.62f2".</summary>
    public string? Stream
    {
        get
        {
            var parts = EditorVersion?.Split('.');
            return parts is { Length: >= 2 } ? parts[0] + "." + parts[1] : EditorVersion;
        }
    }

    public static ProjectVersion Load(string path)
    {
        var root = UnityYamlParser.ParseBlock(UnityTextFile.ReadMayBeEmpty(path), path);
        return new ProjectVersion(root.GetString("m_EditorVersion"), root.GetString("m_EditorVersionWithRevision"));
    }
}
