using System;
using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using System.Linq;
using System.Numerics;

namespace SphFluid.UnityFiles.Yaml;

public enum UnityYamlNodeKind { Scalar, Mapping, Sequence }

/// <summary>
/// One node of a Unity YAML tree: a scalar, a mapping (keys in file order) or a sequence.
/// Block and flow forms parse to the same shape, so <c>{x: 1, y: 2}</c> and an indented block are read alike.
/// </summary>
public sealed class UnityYamlNode
{
    static readonly IReadOnlyList<KeyValuePair<string, UnityYamlNode>> NoEntries = Array.Empty<KeyValuePair<string, UnityYamlNode>>();
    static readonly IReadOnlyList<UnityYamlNode> NoItems = Array.Empty<UnityYamlNode>();

    readonly List<KeyValuePair<string, UnityYamlNode>>? _entries;
    // Keys are looked up by name on every read and checked for duplicates on every add: a list scan would make
    // a mapping of n keys cost n^2 to build.
    readonly Dictionary<string, UnityYamlNode>? _byKey;
    readonly List<UnityYamlNode>? _items;

    UnityYamlNode(UnityYamlNodeKind kind, string? value, bool quoted, int line, string? sourceFile = null)
    {
        Kind = kind;
        Value = value;
        IsQuoted = quoted;
        Line = line;
        SourceFile = sourceFile;
        if (kind == UnityYamlNodeKind.Mapping)
        {
            _entries = new();
            _byKey = new(StringComparer.Ordinal);
        }
        if (kind == UnityYamlNodeKind.Sequence) _items = new();
    }

    public UnityYamlNodeKind Kind { get; }
    /// <summary>Scalar text after unquoting; empty for an empty value (<c>key: </c>); null for mappings and sequences.</summary>
    public string? Value { get; }
    public bool IsQuoted { get; }
    /// <summary>1-based line in the source file where the node starts (0 if unknown); for a mapping or sequence that is a
    /// key's value, the key's line, though a block one's first member stands below it.</summary>
    public int Line { get; }
    /// <summary>The file <see cref="Line"/> is in where that is not the file the node is read as part of: a prefab's value
    /// copied into the scene that places the prefab (<see cref="CopyFrom"/>) names the prefab. Null for a node of the file
    /// itself.</summary>
    public string? SourceFile { get; }

    [MemberNotNullWhen(true, nameof(Value))]
    public bool IsScalar => Kind == UnityYamlNodeKind.Scalar;
    [MemberNotNullWhen(true, nameof(_entries), nameof(_byKey))]
    public bool IsMapping => Kind == UnityYamlNodeKind.Mapping;
    [MemberNotNullWhen(true, nameof(_items))]
    public bool IsSequence => Kind == UnityYamlNodeKind.Sequence;
    /// <summary>True for <c>key: </c> with nothing after it.</summary>
    public bool IsEmpty => IsScalar && Value.Length == 0 && !IsQuoted;

    public IReadOnlyList<KeyValuePair<string, UnityYamlNode>> Entries => _entries ?? NoEntries;
    public IReadOnlyList<UnityYamlNode> Items => _items ?? NoItems;
    public IEnumerable<string> Keys => Entries.Select(e => e.Key);

    public static UnityYamlNode Scalar(string? value, bool quoted = false, int line = 0) => new(UnityYamlNodeKind.Scalar, value ?? "", quoted, line);
    public static UnityYamlNode Mapping(int line = 0) => new(UnityYamlNodeKind.Mapping, null, false, line);
    public static UnityYamlNode Sequence(int line = 0) => new(UnityYamlNodeKind.Sequence, null, false, line);

    /// <summary><c>{fileID: N}</c>: a reference to object N of the same file (0: none).</summary>
    public static UnityYamlNode LocalReference(long fileId, int line = 0)
    {
        var node = Mapping(line);
        node.TryAdd("fileID", Scalar(fileId.ToString(CultureInfo.InvariantCulture), line: line));
        return node;
    }

    internal bool TryAdd(string key, UnityYamlNode value)
    {
        if (!IsMapping) throw new InvalidOperationException($"a {Kind} node (line {Line}) holds no keys");
        if (!_byKey.TryAdd(key, value)) return false;
        _entries.Add(new(key, value));
        return true;
    }

    internal void Add(UnityYamlNode item)
    {
        if (!IsSequence) throw new InvalidOperationException($"a {Kind} node (line {Line}) holds no items");
        _items.Add(item);
    }

    /// <summary>The child under <paramref name="key"/> of a mapping, or null.</summary>
    public UnityYamlNode? this[string? key]
    {
        get
        {
            if (_byKey == null || key == null) return null;
            return _byKey.TryGetValue(key, out var value) ? value : null;
        }
    }

    /// <summary>The item at <paramref name="index"/> of a sequence, or null.</summary>
    public UnityYamlNode? this[int index] => _items != null && index >= 0 && index < _items.Count ? _items[index] : null;

    /// <summary>
    /// Follows a dotted path: <c>"m_Shadows.m_Type"</c>, <c>"m_Component[0].component"</c>, <c>"phases[1].RestDensity"</c>.
    /// Returns null when any step is missing.
    /// </summary>
    public UnityYamlNode? At(string? path)
    {
        if (string.IsNullOrEmpty(path)) return this;
        UnityYamlNode? node = this;
        foreach (var part in path.Split('.'))
        {
            var name = part;
            var indices = new List<int>();
            while (name.EndsWith(']'))
            {
                int open = name.LastIndexOf('[');
                if (open < 0 || !int.TryParse(name.AsSpan(open + 1, name.Length - open - 2), NumberStyles.Integer, CultureInfo.InvariantCulture, out var i))
                    return null;
                indices.Insert(0, i);
                name = name[..open];
            }
            if (name.Length > 0) node = node?[name];
            foreach (var i in indices) node = node?[i];
            if (node == null) return null;
        }
        return node;
    }

    public bool Has(string path) => At(path) != null;

    [return: NotNullIfNotNull(nameof(fallback))]
    public string? GetString(string path, string? fallback = null)
    {
        var n = At(path);
        return n != null && n.IsScalar ? n.Value : fallback;
    }

    public bool TryGetDouble(string path, out double value)
    {
        value = 0;
        var n = At(path);
        return n != null && n.IsScalar && TryParseNumber(n.Value, out value);
    }

    public float GetFloat(string path) => (float)GetDouble(path);

    /// <summary>The fallback stands in for a missing key only: a key that holds no number is an error, as without one.</summary>
    public float GetFloat(string path, float fallback) => At(path) == null ? fallback : GetFloat(path);

    public double GetDouble(string path) =>
        TryGetDouble(path, out var v) ? v : throw Missing(path, "a number");

    public long GetLong(string path) =>
        TryGetLong(path, out var v) ? v : throw Missing(path, "an integer");

    public long GetLong(string path, long fallback) => TryGetLong(path, out var v) ? v : fallback;

    public int GetInt(string path)
    {
        var v = GetLong(path);
        return v is >= int.MinValue and <= int.MaxValue ? (int)v : throw Missing(path, "a 32-bit integer");
    }

    public int GetInt(string path, int fallback) =>
        TryGetLong(path, out var v) && v is >= int.MinValue and <= int.MaxValue ? (int)v : fallback;

    public bool TryGetLong(string path, out long value)
    {
        value = 0;
        var n = At(path);
        return n != null && n.IsScalar && long.TryParse(n.Value, NumberStyles.Integer, CultureInfo.InvariantCulture, out value);
    }

    /// <summary>Unity writes bools as 0/1.</summary>
    public bool GetBool(string path) => GetLong(path) != 0;

    /// <summary>This node as one of the flags Unity writes as 0 or 1 (m_IsActive, m_Enabled); null for any other text,
    /// which the integrity check and the scene reader refuse rather than read as one or the other.</summary>
    public bool? AsFlag => this is { IsScalar: true, Value: "1" } ? true : this is { IsScalar: true, Value: "0" } ? false : null;

    public bool GetBool(string path, bool fallback) => TryGetLong(path, out var v) ? v != 0 : fallback;

    /// <summary>Reads <c>{x: 1, y: 2, z: 3}</c>.</summary>
    public Vector3 GetVector3(string path)
    {
        var n = Require(path);
        return new Vector3(n.GetFloat("x"), n.GetFloat("y"), n.GetFloat("z"));
    }

    public Vector3 GetVector3(string path, Vector3 fallback) => At(path) is { IsMapping: true } ? GetVector3(path) : fallback;

    /// <summary>Reads <c>{x: 1, y: 2}</c>.</summary>
    public Vector2 GetVector2(string path)
    {
        var n = Require(path);
        return new Vector2(n.GetFloat("x"), n.GetFloat("y"));
    }

    /// <summary>Reads <c>{x, y, z, w}</c>.</summary>
    public Vector4 GetVector4(string path)
    {
        var n = Require(path);
        return new Vector4(n.GetFloat("x"), n.GetFloat("y"), n.GetFloat("z"), n.GetFloat("w"));
    }

    /// <summary>Reads a Unity quaternion <c>{x, y, z, w}</c>.</summary>
    public Quaternion GetQuaternion(string path)
    {
        var n = Require(path);
        return new Quaternion(n.GetFloat("x"), n.GetFloat("y"), n.GetFloat("z"), n.GetFloat("w"));
    }

    /// <summary>Reads a Unity colour <c>{r, g, b, a}</c> as (r, g, b, a).</summary>
    public Vector4 GetColor(string path)
    {
        var n = Require(path);
        return new Vector4(n.GetFloat("r"), n.GetFloat("g"), n.GetFloat("b"), n.GetFloat("a", 1f));
    }

    /// <summary>Reads <c>{fileID: N, guid: G, type: T}</c>; null when the path is missing or is not a reference.</summary>
    public UnityReference? GetReference(string path) => UnityReference.TryFrom(At(path), out var r) ? r : null;

    /// <summary>True when this node is a <c>{fileID: ...}</c> reference.</summary>
    public bool IsReference => IsMapping && this["fileID"] is { IsScalar: true };

    /// <summary>This node and every node below it, depth first.</summary>
    public IEnumerable<UnityYamlNode> DescendantsAndSelf()
    {
        yield return this;
        foreach (var e in Entries)
            foreach (var d in e.Value.DescendantsAndSelf()) yield return d;
        foreach (var i in Items)
            foreach (var d in i.DescendantsAndSelf()) yield return d;
    }

    /// <summary>Every <c>{fileID, guid?, type?}</c> reference in this subtree, with the key path where it sits.</summary>
    public IEnumerable<(string Path, UnityReference Reference)> References(string prefix = "")
    {
        if (UnityReference.TryFrom(this, out var r))
        {
            yield return (prefix, r);
            yield break;
        }
        foreach (var e in Entries)
            foreach (var x in e.Value.References(prefix.Length == 0 ? e.Key : prefix + "." + e.Key)) yield return x;
        for (int i = 0; i < Items.Count; i++)
            foreach (var x in Items[i].References(prefix + "[" + i.ToString(CultureInfo.InvariantCulture) + "]")) yield return x;
    }

    /// <summary>
    /// A deep copy of this subtree, each node at its own line, and in <paramref name="sourceFile"/> where it names no
    /// file of its own (null: where the original is), unless <paramref name="replace"/>, asked for each node with its
    /// property path as Unity writes one in a prefab override (<c>block.size.x</c>, a sequence's item
    /// <c>list.Array.data[2]</c>), returns a node to take its place (used as it is, not copied).
    /// </summary>
    public UnityYamlNode CopyFrom(string? sourceFile, Func<string, UnityYamlNode, UnityYamlNode?> replace) => CopyFrom(sourceFile, replace, "");

    UnityYamlNode CopyFrom(string? sourceFile, Func<string, UnityYamlNode, UnityYamlNode?> replace, string path)
    {
        if (replace(path, this) is { } replacement) return replacement;
        var copy = new UnityYamlNode(Kind, Value, IsQuoted, Line, SourceFile ?? sourceFile);
        foreach (var e in Entries)
            copy.TryAdd(e.Key, e.Value.CopyFrom(sourceFile, replace, path.Length == 0 ? e.Key : path + "." + e.Key));
        for (int i = 0; i < Items.Count; i++)
            copy.Add(Items[i].CopyFrom(sourceFile, replace, path + ".Array.data[" + i.ToString(CultureInfo.InvariantCulture) + "]"));
        return copy;
    }

    public static bool TryParseNumber(string? text, out double value)
    {
        switch (text)
        {
            case "Infinity": case "inf": case ".inf": value = double.PositiveInfinity; return true;
            case "-Infinity": case "-inf": case "-.inf": value = double.NegativeInfinity; return true;
            case "NaN": case "nan": case ".nan": value = double.NaN; return true;
        }
        return double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out value);
    }

    UnityYamlNode Require(string path)
    {
        var n = At(path);
        if (n == null || !n.IsMapping) throw Missing(path, "a mapping");
        return n;
    }

    Exception Missing(string path, string what) =>
        new FormatException($"'{path}' is not {what} (node at line {Line}{(SourceFile != null ? " of " + SourceFile : "")}{(At(path) is { IsScalar: true } s ? $", found '{s.Value}'" : "")})");

    public override string ToString() => Kind switch
    {
        UnityYamlNodeKind.Scalar => Value ?? "",
        UnityYamlNodeKind.Mapping => "{" + string.Join(", ", Entries.Select(e => e.Key + ": " + e.Value)) + "}",
        _ => "[" + string.Join(", ", Items) + "]",
    };
}
