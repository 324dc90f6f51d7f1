using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using System.Text.RegularExpressions;

namespace SphFluid.UnityFiles.Yaml;

/// <summary>
/// Parses the YAML subset Unity writes: <c>--- !u!&lt;classId&gt; &amp;&lt;fileId&gt;</c> documents, block mappings,
/// block sequences (also at the same indent as their key), flow maps/sequences, plain and quoted scalars, empty values.
/// Anything outside that subset (tabs for indentation, bad nesting, duplicate keys) is an error with file and line,
/// because Unity refuses such files too.
/// </summary>
public sealed partial class UnityYamlParser
{
    [GeneratedRegex(@"^--- !u!(?<class>\d+) &(?<file>-?\d+)(?<stripped> stripped)?\s*$")]
    private static partial Regex DocumentHeader();

    readonly string _path;
    readonly List<SourceLine> _lines;
    int _pos;
    int _end;

    struct SourceLine
    {
        public int Number;
        public int Indent;
        public string Text;
    }

    UnityYamlParser(string path, List<SourceLine> lines)
    {
        _path = path;
        _lines = lines;
    }

    /// <summary>Parses a Unity serialized file (.unity, .prefab, .mat, .asset, ProjectSettings/*.asset).</summary>
    public static UnityYamlFile ParseFile(string text, string path = null)
    {
        var raw = SplitLines(text);
        var headers = new List<string>();
        var documents = new List<UnityDocument>();
        int i = 0;
        while (i < raw.Count && !raw[i].StartsWith("---", StringComparison.Ordinal))
        {
            var t = raw[i].TrimEnd();
            if (t.Length > 0 && !t.StartsWith('#'))
            {
                if (!t.StartsWith('%')) throw new UnityYamlException(path, i + 1, $"content before the first '--- !u!' document: '{Shorten(t)}'");
                headers.Add(t);
            }
            i++;
        }
        while (i < raw.Count)
        {
            var header = raw[i].TrimEnd();
            var m = DocumentHeader().Match(header);
            if (!m.Success) throw new UnityYamlException(path, i + 1, $"document header '{Shorten(header)}' is not '--- !u!<classId> &<fileId>'");
            int headerLine = i + 1;
            int start = ++i;
            while (i < raw.Count && !raw[i].StartsWith("---", StringComparison.Ordinal)) i++;
            var parser = new UnityYamlParser(path, Prepare(raw, start, i, path));
            var body = parser.ParseDocumentBody(headerLine);
            if (body.Entries.Count != 1)
                throw new UnityYamlException(path, headerLine, $"document &{m.Groups["file"].Value} must have exactly one root key (the type name), found {body.Entries.Count}");
            documents.Add(new UnityDocument(
                int.Parse(m.Groups["class"].Value, CultureInfo.InvariantCulture),
                long.Parse(m.Groups["file"].Value, CultureInfo.InvariantCulture),
                body.Entries[0].Key,
                body.Entries[0].Value,
                m.Groups["stripped"].Success,
                headerLine));
        }
        return new UnityYamlFile(path, headers, documents);
    }

    /// <summary>Parses plain block YAML with no document markers (.meta files, ProjectVersion.txt).</summary>
    public static UnityYamlNode ParseBlock(string text, string path = null)
    {
        var raw = SplitLines(text);
        var parser = new UnityYamlParser(path, Prepare(raw, 0, raw.Count, path));
        return parser.ParseDocumentBody(1);
    }

    static List<string> SplitLines(string text)
    {
        var lines = new List<string>(text.Split('\n'));
        for (int i = 0; i < lines.Count; i++)
            if (lines[i].EndsWith('\r')) lines[i] = lines[i][..^1];
        if (lines.Count > 0 && lines[^1].Length == 0) lines.RemoveAt(lines.Count - 1);
        return lines;
    }

    static List<SourceLine> Prepare(List<string> raw, int start, int end, string path)
    {
        var lines = new List<SourceLine>(end - start);
        for (int i = start; i < end; i++)
        {
            var text = raw[i];
            int indent = 0;
            while (indent < text.Length && text[indent] == ' ') indent++;
            if (indent < text.Length && text[indent] == '\t')
                throw new UnityYamlException(path, i + 1, "tab in indentation (YAML allows spaces only)");
            var content = text[indent..].TrimEnd(' ', '\t');
            if (content.Length == 0 || content[0] == '#') continue;
            lines.Add(new SourceLine { Number = i + 1, Indent = indent, Text = content });
        }
        return lines;
    }

    UnityYamlNode ParseDocumentBody(int headerLine)
    {
        _pos = 0;
        _end = _lines.Count;
        if (_end == 0) return UnityYamlNode.Mapping(headerLine);
        if (_lines[0].Indent != 0) throw Error(_lines[0], "the root key must start at column 1");
        var node = ParseNode(0);
        if (_pos < _end) throw Error(_lines[_pos], $"unexpected indentation or content '{Shorten(_lines[_pos].Text)}'");
        if (!node.IsMapping) throw Error(_lines[0], "a document must be a mapping");
        return node;
    }

    UnityYamlNode ParseNode(int indent)
    {
        var line = _lines[_pos];
        if (IsSequenceItem(line.Text)) return ParseSequence(line.Indent);
        if (SplitKey(line.Text, out _, out _)) return ParseMapping(line.Indent);
        _pos++;
        return ParseInlineValue(line.Text, line, indent - 1);
    }

    UnityYamlNode ParseMapping(int indent)
    {
        var map = UnityYamlNode.Mapping(_lines[_pos].Number);
        while (_pos < _end)
        {
            var line = _lines[_pos];
            if (line.Indent < indent) break;
            if (line.Indent > indent) throw Error(line, $"unexpected indentation (expected column {indent + 1})");
            if (IsSequenceItem(line.Text)) break;
            if (!SplitKey(line.Text, out var key, out var rest))
                throw Error(line, $"expected 'key: value', found '{Shorten(line.Text)}'");
            _pos++;
            UnityYamlNode value;
            if (rest.Length == 0)
            {
                if (_pos < _end && _lines[_pos].Indent > indent) value = ParseNode(_lines[_pos].Indent);
                else if (_pos < _end && _lines[_pos].Indent == indent && IsSequenceItem(_lines[_pos].Text)) value = ParseSequence(indent);
                else value = UnityYamlNode.Scalar("", false, line.Number);
            }
            else
            {
                value = ParseInlineValue(rest, line, indent);
            }
            if (!map.TryAdd(key, value)) throw Error(line, $"duplicate key '{key}'");
        }
        return map;
    }

    UnityYamlNode ParseSequence(int indent)
    {
        var seq = UnityYamlNode.Sequence(_lines[_pos].Number);
        while (_pos < _end)
        {
            var line = _lines[_pos];
            if (line.Indent != indent || !IsSequenceItem(line.Text)) break;
            var rest = line.Text.Length == 1 ? "" : line.Text[1..];
            int spaces = 0;
            while (spaces < rest.Length && rest[spaces] == ' ') spaces++;
            rest = rest[spaces..];
            if (rest.Length == 0)
            {
                _pos++;
                if (_pos < _end && _lines[_pos].Indent > indent) seq.Add(ParseNode(_lines[_pos].Indent));
                else seq.Add(UnityYamlNode.Scalar("", false, line.Number));
                continue;
            }
            // "- key: v" opens a mapping whose keys sit at the column after "- ": re-read the rest of the line at that column.
            int contentIndent = indent + 1 + spaces;
            _lines[_pos] = new SourceLine { Number = line.Number, Indent = contentIndent, Text = rest };
            seq.Add(ParseNode(contentIndent));
        }
        return seq;
    }

    /// <summary>A value that starts on the current line (already consumed); continuation lines must be deeper than <paramref name="ownerIndent"/>.</summary>
    UnityYamlNode ParseInlineValue(string text, SourceLine line, int ownerIndent)
    {
        char c = text[0];
        if (c == '{' || c == '[')
        {
            var sb = new StringBuilder(text);
            while (!FlowBalanced(sb.ToString()))
            {
                if (_pos >= _end || _lines[_pos].Indent <= ownerIndent) throw Error(line, "unclosed flow collection");
                sb.Append(' ').Append(_lines[_pos++].Text);
            }
            var flow = new FlowReader(sb.ToString(), this, line);
            var node = flow.ReadValue();
            flow.ExpectEnd();
            return node;
        }
        if (c == '\'' || c == '"')
        {
            var sb = new StringBuilder(text);
            while (!QuotedClosed(sb.ToString()))
            {
                if (_pos >= _end || _lines[_pos].Indent <= ownerIndent) throw Error(line, "unclosed quoted string");
                sb.Append('\n').Append(_lines[_pos++].Text);
            }
            var all = sb.ToString();
            int close = QuotedEnd(all);
            if (all[(close + 1)..].Trim().Length > 0) throw Error(line, $"text after closing quote: '{Shorten(all)}'");
            return UnityYamlNode.Scalar(Unquote(all[..(close + 1)], line), true, line.Number);
        }
        if (c == '|' || c == '>')
        {
            var parts = new List<string>();
            while (_pos < _end && _lines[_pos].Indent > ownerIndent) parts.Add(_lines[_pos++].Text);
            return UnityYamlNode.Scalar(string.Join(c == '|' ? "\n" : " ", parts), true, line.Number);
        }
        if (c == '&' || c == '*' || (c == '!' && text.Length > 1))
            throw Error(line, $"anchors, aliases and tags inside a document are not part of Unity's YAML: '{Shorten(text)}'");
        // In YAML " #" ends a plain scalar (the rest is a comment), so "Water #1" unquoted reads as "Water", as in Unity.
        var plain = new StringBuilder(StripComment(text));
        while (_pos < _end && _lines[_pos].Indent > ownerIndent && ownerIndent >= 0)
            plain.Append(' ').Append(StripComment(_lines[_pos++].Text));
        return UnityYamlNode.Scalar(plain.ToString().TrimEnd(), false, line.Number);
    }

    static string StripComment(string text)
    {
        int hash = text.IndexOf(" #", StringComparison.Ordinal);
        return hash < 0 ? text : text[..hash];
    }

    static bool IsSequenceItem(string text) => text == "-" || text.StartsWith("- ", StringComparison.Ordinal);

    /// <summary>Splits <c>key: rest</c> (key plain or quoted); false for scalars and flow collections.</summary>
    static bool SplitKey(string text, out string key, out string rest)
    {
        key = null;
        rest = null;
        if (text.Length == 0 || text[0] == '{' || text[0] == '[' || text[0] == '-' && (text.Length == 1 || text[1] == ' ')) return false;
        int colon;
        if (text[0] == '\'' || text[0] == '"')
        {
            int close = QuotedEnd(text);
            if (close < 0 || close + 1 >= text.Length || text[close + 1] != ':') return false;
            colon = close + 1;
            key = UnquoteSimple(text[..(close + 1)]);
        }
        else
        {
            colon = -1;
            for (int i = 0; i < text.Length; i++)
            {
                if (text[i] == ':' && (i + 1 == text.Length || text[i + 1] == ' ')) { colon = i; break; }
                if (text[i] == ' ' && i + 1 < text.Length && text[i + 1] == '#') return false;
            }
            if (colon <= 0) return false;
            key = text[..colon].TrimEnd();
        }
        if (colon + 1 < text.Length && text[colon + 1] != ' ') return false;
        rest = colon + 1 < text.Length ? text[(colon + 1)..].Trim() : "";
        return true;
    }

    static bool FlowBalanced(string text)
    {
        int depth = 0;
        char quote = '\0';
        for (int i = 0; i < text.Length; i++)
        {
            char c = text[i];
            if (quote != '\0')
            {
                if (quote == '"' && c == '\\') { i++; continue; }
                if (c == quote)
                {
                    if (quote == '\'' && i + 1 < text.Length && text[i + 1] == '\'') { i++; continue; }
                    quote = '\0';
                }
                continue;
            }
            if ((c == '\'' || c == '"') && (i == 0 || " ,[{:".IndexOf(text[i - 1]) >= 0)) quote = c;
            else if (c == '{' || c == '[') depth++;
            else if (c == '}' || c == ']') depth--;
        }
        return depth <= 0 && quote == '\0';
    }

    static bool QuotedClosed(string text) => QuotedEnd(text) > 0;

    /// <summary>Index of the quote that closes the string opening at 0, or -1.</summary>
    static int QuotedEnd(string text)
    {
        char q = text[0];
        for (int i = 1; i < text.Length; i++)
        {
            if (q == '"' && text[i] == '\\') { i++; continue; }
            if (text[i] == q)
            {
                if (q == '\'' && i + 1 < text.Length && text[i + 1] == '\'') { i++; continue; }
                return i;
            }
        }
        return -1;
    }

    static string UnquoteSimple(string quoted) =>
        quoted[0] == '\'' ? quoted[1..^1].Replace("''", "'") : quoted[1..^1].Replace("\\\"", "\"").Replace("\\\\", "\\");

    string Unquote(string quoted, SourceLine line)
    {
        var body = FoldLines(quoted[1..^1], quoted[0] == '"');
        if (quoted[0] == '\'') return body.Replace("''", "'");
        var sb = new StringBuilder(body.Length);
        for (int i = 0; i < body.Length; i++)
        {
            char c = body[i];
            if (c != '\\') { sb.Append(c); continue; }
            if (++i >= body.Length) throw Error(line, "backslash at end of a double-quoted string");
            char e = body[i];
            switch (e)
            {
                case 'n': sb.Append('\n'); break;
                case 't': sb.Append('\t'); break;
                case 'r': sb.Append('\r'); break;
                case '0': sb.Append('\0'); break;
                case 'a': sb.Append('\a'); break;
                case 'b': sb.Append('\b'); break;
                case 'e': sb.Append('\u001b'); break;
                case ' ': sb.Append(' '); break;
                case '/': sb.Append('/'); break;
                case '\\': sb.Append('\\'); break;
                case '"': sb.Append('"'); break;
                case '\u0001': break; // escaped line break marker from FoldLines: join without space
                case 'x': sb.Append(Hex(body, ref i, 2, line)); break;
                case 'u': sb.Append(Hex(body, ref i, 4, line)); break;
                case 'U': sb.Append(Hex(body, ref i, 8, line)); break;
                default: throw Error(line, $"unknown escape '\\{e}' in a double-quoted string");
            }
        }
        return sb.ToString();
    }

    string Hex(string s, ref int i, int digits, SourceLine line)
    {
        if (i + digits > s.Length - 1) throw Error(line, "truncated escape in a double-quoted string");
        var hex = s.Substring(i + 1, digits);
        if (!int.TryParse(hex, NumberStyles.HexNumber, CultureInfo.InvariantCulture, out var code)) throw Error(line, $"bad escape '{hex}'");
        i += digits;
        return char.ConvertFromUtf32(code);
    }

    /// <summary>YAML line folding inside quoted scalars: one break is a space, an empty line is a newline.</summary>
    static string FoldLines(string body, bool doubleQuoted)
    {
        if (body.IndexOf('\n') < 0) return body;
        var parts = body.Split('\n');
        var sb = new StringBuilder(parts[0].TrimEnd(' '));
        for (int i = 1; i < parts.Length; i++)
        {
            var p = parts[i].Trim(' ');
            if (doubleQuoted && sb.Length > 0 && sb[^1] == '\\' && (sb.Length < 2 || sb[^2] != '\\'))
            {
                sb.Append('\u0001');
                sb.Append(p);
            }
            else sb.Append(' ').Append(p);
        }
        return sb.ToString();
    }

    UnityYamlException Error(SourceLine line, string message) => new(_path, line.Number, message);

    static string Shorten(string s) => s.Length <= 60 ? s : s[..57] + "...";

    /// <summary>Reads one flow collection or scalar: <c>{fileID: 1, guid: abc, type: 3}</c>, <c>[1, 2]</c>.</summary>
    sealed class FlowReader
    {
        readonly string _text;
        readonly UnityYamlParser _owner;
        readonly SourceLine _line;
        int _i;

        public FlowReader(string text, UnityYamlParser owner, SourceLine line)
        {
            _text = text;
            _owner = owner;
            _line = line;
        }

        public void ExpectEnd()
        {
            SkipSpaces();
            if (_i < _text.Length) throw _owner.Error(_line, $"unexpected '{Shorten(_text[_i..])}' after a flow collection");
        }

        public UnityYamlNode ReadValue()
        {
            SkipSpaces();
            if (_i >= _text.Length) return UnityYamlNode.Scalar("", false, _line.Number);
            char c = _text[_i];
            if (c == '{') return ReadMapping();
            if (c == '[') return ReadSequence();
            if (c == '\'' || c == '"')
            {
                int close = QuotedEnd(_text[_i..]);
                if (close < 0) throw _owner.Error(_line, "unclosed quoted string in a flow collection");
                var quoted = _text.Substring(_i, close + 1);
                _i += close + 1;
                return UnityYamlNode.Scalar(_owner.Unquote(quoted, _line), true, _line.Number);
            }
            int start = _i;
            while (_i < _text.Length && _text[_i] != ',' && _text[_i] != '}' && _text[_i] != ']') _i++;
            return UnityYamlNode.Scalar(_text[start.._i].Trim(), false, _line.Number);
        }

        UnityYamlNode ReadMapping()
        {
            var map = UnityYamlNode.Mapping(_line.Number);
            _i++;
            while (true)
            {
                SkipSpaces();
                if (_i >= _text.Length) throw _owner.Error(_line, "unclosed '{'");
                if (_text[_i] == '}') { _i++; return map; }
                var key = ReadKey();
                SkipSpaces();
                UnityYamlNode value;
                if (_i < _text.Length && _text[_i] == ':')
                {
                    _i++;
                    value = ReadValue();
                }
                else value = UnityYamlNode.Scalar("", false, _line.Number);
                if (!map.TryAdd(key, value)) throw _owner.Error(_line, $"duplicate key '{key}' in a flow mapping");
                SkipSpaces();
                if (_i < _text.Length && _text[_i] == ',') { _i++; continue; }
                if (_i < _text.Length && _text[_i] == '}') { _i++; return map; }
                throw _owner.Error(_line, $"expected ',' or '}}' in '{Shorten(_text)}'");
            }
        }

        UnityYamlNode ReadSequence()
        {
            var seq = UnityYamlNode.Sequence(_line.Number);
            _i++;
            while (true)
            {
                SkipSpaces();
                if (_i >= _text.Length) throw _owner.Error(_line, "unclosed '['");
                if (_text[_i] == ']') { _i++; return seq; }
                seq.Add(ReadValue());
                SkipSpaces();
                if (_i < _text.Length && _text[_i] == ',') { _i++; continue; }
                if (_i < _text.Length && _text[_i] == ']') { _i++; return seq; }
                throw _owner.Error(_line, $"expected ',' or ']' in '{Shorten(_text)}'");
            }
        }

        string ReadKey()
        {
            if (_text[_i] == '\'' || _text[_i] == '"')
            {
                int close = QuotedEnd(_text[_i..]);
                if (close < 0) throw _owner.Error(_line, "unclosed quoted key");
                var k = UnquoteSimple(_text.Substring(_i, close + 1));
                _i += close + 1;
                return k;
            }
            int start = _i;
            while (_i < _text.Length && _text[_i] != ',' && _text[_i] != '}' &&
                   !(_text[_i] == ':' && (_i + 1 == _text.Length || " ,}]".IndexOf(_text[_i + 1]) >= 0))) _i++;
            var key = _text[start.._i].Trim();
            if (key.Length == 0) throw _owner.Error(_line, $"empty key in '{Shorten(_text)}'");
            return key;
        }

        void SkipSpaces()
        {
            while (_i < _text.Length && (_text[_i] == ' ' || _text[_i] == '\n')) _i++;
        }
    }
}
