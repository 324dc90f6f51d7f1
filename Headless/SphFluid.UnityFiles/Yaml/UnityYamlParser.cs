using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using System.Text.RegularExpressions;
using YamlDotNet.Core;
using YamlDotNet.Core.Events;

namespace SphFluid.UnityFiles.Yaml;

/// <summary>
/// Reads Unity's serialized YAML. YamlDotNet parses the text; this layer adds what is Unity's own:
/// the <c>--- !u!&lt;classId&gt; &amp;&lt;fileId&gt;</c> headers (with the <c> stripped</c> suffix no YAML parser
/// accepts), one root key per document, no duplicate keys, no anchors, aliases or tags inside a document, and a
/// nesting-depth limit. Every refusal is a <see cref="UnityYamlException"/> naming the file and line.
/// The work is linear in the size of the text: YamlDotNet's scanner and parser are iterative state machines and the
/// tree is built from their events with an explicit stack, so no input can exhaust the call stack.
/// </summary>
public static partial class UnityYamlParser
{
    /// <summary>Deepest nesting of mappings and sequences accepted. Unity writes at most about ten levels
    /// (prefab modifications); far deeper text is hostile or broken.</summary>
    public const int MaxDepth = 64;

    [GeneratedRegex(@"^--- !u!(?<class>\d+) &(?<file>-?\d+)(?<stripped> stripped)?\s*$")]
    private static partial Regex DocumentHeader();

    /// <summary>Parses a Unity serialized file (.unity, .prefab, .mat, .asset, ProjectSettings/*.asset).</summary>
    public static UnityYamlFile ParseFile(string text, string? path = null)
    {
        // The whole file goes through one YamlDotNet parser as a plain multi-document stream: each Unity header
        // becomes a bare '---' on the same line (so line numbers stay the file's) and is read here instead.
        var lines = new LineCursor(text);
        var yaml = new StringBuilder(text.Length);
        var headers = new List<string>();
        var documents = new List<(int ClassId, long FileId, bool Stripped, int Line)>();
        while (lines.Next())
        {
            var line = lines.Current;
            if (documents.Count == 0 && !line.StartsWith("---", StringComparison.Ordinal))
            {
                var t = line.TrimEnd().ToString();
                if (t.Length > 0 && !t.StartsWith('#'))
                {
                    if (!t.StartsWith('%')) throw new UnityYamlException(path, lines.Number, $"content before the first '--- !u!' document: '{Shorten(t)}'");
                    headers.Add(t);
                }
                yaml.Append('\n');
                continue;
            }
            if (line.StartsWith("---", StringComparison.Ordinal))
            {
                documents.Add(ReadHeader(line.TrimEnd().ToString(), lines.Number, path));
                yaml.Append("---\n");
                continue;
            }
            CheckIndentation(line, lines.Number, path);
            yaml.Append(line).Append('\n');
        }
        var roots = Parse(yaml.ToString(), path, documents.Count);
        var result = new List<UnityDocument>(documents.Count);
        for (int i = 0; i < documents.Count; i++)
        {
            var (classId, fileId, stripped, line) = documents[i];
            var body = (i < roots.Count ? roots[i] : null) ?? UnityYamlNode.Mapping(line);
            if (!body.IsMapping) throw new UnityYamlException(path, body.Line, "a document must be a mapping");
            if (body.Entries.Count != 1)
                throw new UnityYamlException(path, line, $"document &{fileId} must have exactly one root key (the type name), found {body.Entries.Count}");
            result.Add(new UnityDocument(classId, fileId, body.Entries[0].Key, body.Entries[0].Value, stripped, line));
        }
        return new UnityYamlFile(path, headers, result);
    }

    /// <summary>Parses plain block YAML with no document markers (.meta files, ProjectVersion.txt).</summary>
    public static UnityYamlNode ParseBlock(string text, string? path = null)
    {
        var lines = new LineCursor(text);
        while (lines.Next()) CheckIndentation(lines.Current, lines.Number, path);
        var roots = Parse(text, path, 1);
        var root = (roots.Count > 0 ? roots[0] : null) ?? UnityYamlNode.Mapping(1);
        if (!root.IsMapping) throw new UnityYamlException(path, root.Line, "a document must be a mapping");
        return root;
    }

    static (int ClassId, long FileId, bool Stripped, int Line) ReadHeader(string header, int line, string? path)
    {
        var m = DocumentHeader().Match(header);
        if (!m.Success) throw new UnityYamlException(path, line, $"document header '{Shorten(header)}' is not '--- !u!<classId> &<fileId>'");
        if (!long.TryParse(m.Groups["file"].Value, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out long fileId) ||
            !int.TryParse(m.Groups["class"].Value, NumberStyles.None, CultureInfo.InvariantCulture, out int classId))
            throw new UnityYamlException(path, line, $"document header '{Shorten(header)}': class id or fileID out of range");
        return (classId, fileId, m.Groups["stripped"].Success, line);
    }

    /// <summary>YAML forbids tabs in indentation; YamlDotNet reports them at the enclosing node, so they are found here
    /// to name the very line.</summary>
    static void CheckIndentation(ReadOnlySpan<char> line, int number, string? path)
    {
        int i = 0;
        while (i < line.Length && line[i] == ' ') i++;
        if (i < line.Length && line[i] == '\t' && line.Trim().Length > 0)
            throw new UnityYamlException(path, number, "tab in indentation (YAML allows spaces only)");
    }

    /// <summary>The root node of each YAML document in <paramref name="yaml"/> (null for an empty one); more than
    /// <paramref name="expected"/> documents is an error.</summary>
    static List<UnityYamlNode?> Parse(string yaml, string? path, int expected)
    {
        var builder = new TreeBuilder(path, expected);
        var parser = new Parser(new StringReader(yaml));
        try
        {
            while (parser.MoveNext())
                if (parser.Current is { } e) builder.Accept(e);
        }
        catch (YamlException e)
        {
            throw builder.Translate(e.Message, (int)Math.Min(int.MaxValue, e.Start.Line), scannerGaveUp: false);
        }
        catch (Exception e) when (e is InvalidOperationException || e.GetType() == typeof(Exception))
        {
            // YamlDotNet's ScanPlainScalar throws a bare exception instead of a YamlException on some malformed flow
            // collections (e.g. "b: {x: 1,\nc: []"; its issue #541): still a located error, never a crash.
            throw builder.Translate("the YAML scanner stopped on malformed text", builder.LastLine, scannerGaveUp: true);
        }
        return builder.Roots;
    }

    static string Shorten(string s) => s.Length <= 60 ? s : s[..57] + "...";

    /// <summary>Builds <see cref="UnityYamlNode"/>s from parser events with an explicit stack.</summary>
    sealed class TreeBuilder(string? path, int expectedDocuments)
    {
        readonly Stack<Open> _open = new();
        bool _rootSet;

        /// <summary>A mapping or sequence still being filled, and for a mapping the key waiting for its value.</summary>
        sealed class Open(UnityYamlNode node, bool flow)
        {
            public UnityYamlNode Node { get; } = node;
            public bool Flow { get; } = flow;
            public string? Key { get; set; }
            public int KeyLine { get; set; }
        }

        /// <summary>The root of each document so far; null for an empty one.</summary>
        public List<UnityYamlNode?> Roots { get; } = new();

        static int Line(ParsingEvent e) => (int)Math.Min(int.MaxValue, e.Start.Line);

        /// <summary>Line where the last event ended: where the parser was when it gave up.</summary>
        public int LastLine { get; private set; } = 1;

        public void Accept(ParsingEvent e)
        {
            LastLine = (int)Math.Min(int.MaxValue, e.End.Line);
            switch (e)
            {
                case StreamStart or StreamEnd or DocumentEnd:
                    return;
                case DocumentStart:
                    if (Roots.Count >= expectedDocuments)
                        throw Error(Line(e), "a YAML document without a '--- !u!<classId> &<fileId>' header");
                    Roots.Add(null);
                    _rootSet = false;
                    return;
                case AnchorAlias:
                    throw Error(Line(e), "anchors, aliases and tags inside a document are not part of Unity's YAML");
                case Comment:
                    return;
            }
            if (e is NodeEvent node && (!node.Anchor.IsEmpty || (!node.Tag.IsEmpty && !IsImplicitTag(node))))
                throw Error(Line(e), "anchors, aliases and tags inside a document are not part of Unity's YAML");
            switch (e)
            {
                case Scalar s:
                    if (_open.Count > 0 && _open.Peek().Node.IsMapping && _open.Peek().Key == null)
                    {
                        _open.Peek().Key = s.Value;
                        _open.Peek().KeyLine = Line(e);
                        return;
                    }
                    bool quoted = s.Style is ScalarStyle.SingleQuoted or ScalarStyle.DoubleQuoted or ScalarStyle.Literal or ScalarStyle.Folded;
                    Attach(UnityYamlNode.Scalar(s.Value, quoted, Line(e)), Line(e));
                    return;
                case MappingStart ms:
                    Push(UnityYamlNode.Mapping(StartLine(e)), ms.Style == MappingStyle.Flow, Line(e));
                    return;
                case SequenceStart ss:
                    Push(UnityYamlNode.Sequence(StartLine(e)), ss.Style == SequenceStyle.Flow, Line(e));
                    return;
                case MappingEnd or SequenceEnd:
                    _open.Pop();
                    return;
            }
        }

        /// <summary>The line a mapping or sequence is said to start on: its key's, where it is a key's value. A block one
        /// opens on the line below its key (Unity writes a serialized struct's fields there), and an error about the field
        /// as a whole (an axis of zero length) would otherwise point at its first member's line.</summary>
        int StartLine(ParsingEvent e) =>
            _open.Count > 0 && _open.Peek().Node.IsMapping && _open.Peek().Key != null ? _open.Peek().KeyLine : Line(e);

        static bool IsImplicitTag(NodeEvent node) => node is Scalar { IsPlainImplicit: true } or Scalar { IsQuotedImplicit: true }
            || node is MappingStart { IsImplicit: true } || node is SequenceStart { IsImplicit: true };

        void Push(UnityYamlNode node, bool flow, int line)
        {
            if (_open.Count >= MaxDepth)
                throw Error(line, $"nested deeper than {MaxDepth} levels of mappings and sequences (Unity writes about ten)");
            Attach(node, line);
            _open.Push(new Open(node, flow));
        }

        void Attach(UnityYamlNode node, int line)
        {
            if (_open.Count == 0)
            {
                // An empty document reads as one empty scalar: keep it as "no root".
                if (_rootSet || Roots.Count == 0) throw Error(line, "unexpected content after the document's root");
                _rootSet = true;
                if (!(node.IsScalar && node.IsEmpty)) Roots[^1] = node;
                return;
            }
            var parent = _open.Peek();
            if (parent.Node.IsSequence)
            {
                parent.Node.Add(node);
                return;
            }
            if (parent.Key == null) throw Error(line, "a key must be plain text, not a mapping or a sequence");
            if (!parent.Node.TryAdd(parent.Key, node))
                throw Error(parent.KeyLine, $"duplicate key '{Shorten(parent.Key)}'");
            parent.Key = null;
        }

        UnityYamlException Error(int line, string reason) => new(path, line, reason);

        /// <summary>
        /// YamlDotNet's message, reworded where the cause is clearer from what is still open: an unclosed flow
        /// collection is reported where it opened, not where the text ran out.
        /// </summary>
        public UnityYamlException Translate(string message, int line, bool scannerGaveUp)
        {
            var flow = _open.Count > 0 && _open.Peek().Flow ? _open.Peek() : null;
            if (flow != null && (scannerGaveUp || message.Contains("did not find expected", StringComparison.Ordinal)))
            {
                char bracket = flow.Node.IsMapping ? '{' : '[';
                return Error(flow.Node.Line, $"unclosed '{bracket}': no matching '{(bracket == '{' ? '}' : ']')}' {(scannerGaveUp ? "after" : "before")} line {line} ({message.TrimEnd('.')})");
            }
            if (message.Contains("quoted scalar", StringComparison.Ordinal) &&
                (message.Contains("end of stream", StringComparison.Ordinal) || message.Contains("document indicator", StringComparison.Ordinal) ||
                 message.Contains("wrong indentation", StringComparison.Ordinal)))
            {
                string? key = _open.Count > 0 ? _open.Peek().Key : null;
                string what = key == null ? "a quoted value" : $"the value of '{Shorten(key)}' (line {_open.Peek().KeyLine})";
                return Error(line, $"unclosed quoted string: {what} has no closing quote before this line ({message.TrimEnd('.')})");
            }
            if (message.Contains("found invalid mapping", StringComparison.Ordinal) || message.Contains("did not find expected key", StringComparison.Ordinal))
                return Error(line, $"unexpected indentation or content: expected 'key: value' in line with its siblings ({message.TrimEnd('.')})");
            return Error(line, message.TrimEnd('.'));
        }
    }

    /// <summary>Walks the lines of a text without splitting it (a CR before LF belongs to the break).</summary>
    sealed class LineCursor(string text)
    {
        int _start, _length, _next;

        /// <summary>1-based number of the current line.</summary>
        public int Number { get; private set; }

        public ReadOnlySpan<char> Current => text.AsSpan(_start, _length);

        public bool Next()
        {
            if (_next >= text.Length) return false;
            _start = _next;
            int end = text.IndexOf('\n', _next);
            if (end < 0) end = text.Length;
            _next = end + 1;
            _length = end - _start;
            if (_length > 0 && text[_start + _length - 1] == '\r') _length--;
            Number++;
            return true;
        }
    }
}
