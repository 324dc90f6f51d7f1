using System;
using System.Collections.Generic;
using System.Linq;

namespace SphFluid.UnityFiles.Yaml;

/// <summary>A parsed Unity serialized file: its <c>%</c> header lines and its documents in file order.</summary>
public sealed class UnityYamlFile
{
    public const string YamlHeader = "%YAML 1.1";
    public const string TagHeader = "%TAG !u! tag:unity3d.com,2011:";

    readonly Dictionary<long, UnityDocument> _byFileId = new();

    public UnityYamlFile(string? path, IReadOnlyList<string> headers, IReadOnlyList<UnityDocument> documents)
    {
        Path = path;
        Headers = headers;
        Documents = documents;
        foreach (var d in documents)
            if (!_byFileId.ContainsKey(d.FileId)) _byFileId.Add(d.FileId, d);
            else DuplicateFileIds.Add(d.FileId);
    }

    /// <summary>The file, or null for text parsed without one.</summary>
    public string? Path { get; }
    public IReadOnlyList<string> Headers { get; }
    public IReadOnlyList<UnityDocument> Documents { get; }
    /// <summary>Anchors (<c>&amp;N</c>) used by more than one document; Unity requires them unique.</summary>
    public List<long> DuplicateFileIds { get; } = new();

    /// <summary>True when the file starts with exactly the two header lines Unity writes.</summary>
    public bool HasUnityHeader => Headers.Count == 2 && Headers[0] == YamlHeader && Headers[1] == TagHeader;

    /// <summary>Reads and parses a file; only a regular file of at most <see cref="UnityTextFile.MaxBytes"/> is read.</summary>
    public static UnityYamlFile Load(string path) => UnityYamlParser.ParseFile(UnityTextFile.Read(path), path);

    public static UnityYamlFile Parse(string text, string? path = null) => UnityYamlParser.ParseFile(text, path);

    public UnityDocument? Find(long fileId) => _byFileId.TryGetValue(fileId, out var d) ? d : null;

    public UnityDocument? Find(UnityReference? reference) =>
        reference != null && reference.IsLocal ? Find(reference.FileId) : null;

    public IEnumerable<UnityDocument> OfType(string typeName) => Documents.Where(d => d.TypeName == typeName);

    public IEnumerable<UnityDocument> OfClass(int classId) => Documents.Where(d => d.ClassId == classId);

    /// <summary>The single document of a settings file or native asset (e.g. <c>PlayerSettings</c>); throws when absent.</summary>
    public UnityDocument Single(string typeName) =>
        OfType(typeName).FirstOrDefault() ?? throw new InvalidOperationException($"{Path}: no '{typeName}' document");
}
