using System.Collections.Generic;
using System.Text;

namespace SphFluid.Vulkan;

/// <summary>
/// Unity compiles compute shaders with Microsoft's HLSL compilers, where a global declared <c>const</c>
/// without an initializer (<c>const uint numParticles;</c>) is an ordinary uniform in <c>$Globals</c>
/// that the host sets; only <c>static const</c> is a compile-time constant. glslang instead reads it
/// as a constant, warns, and zero-initialises it, which silently turns every use into 0. This drops
/// the <c>const</c> of such declarations (keeping every other character in place, so line and column
/// numbers of errors stay true) before glslang sees the text.
/// </summary>
public static class ConstGlobals
{
    /// <summary>The text with each file-scope <c>const</c> declaration that has no initializer made settable.</summary>
    public static string MakeSettable(string text)
    {
        var tokens = Tokens(text);
        var result = new StringBuilder(text);
        int depth = 0;
        bool statementStart = true;
        for (int k = 0; k < tokens.Count; k++)
        {
            var (start, value) = tokens[k];
            if (value == "const" && depth == 0 && statementStart && HasNoInitializer(tokens, k + 1))
                for (int c = start; c < start + value.Length; c++) result[c] = ' ';
            switch (value)
            {
                case "{": case "(": case "[": depth++; statementStart = false; break;
                case ")": case "]": depth--; statementStart = false; break;
                case "}": depth--; statementStart = depth == 0; break;
                case ";": statementStart = depth == 0; break;
                // Storage words before const leave the statement's start open: "uniform const uint n;".
                case "uniform": case "extern": break;
                default: statementStart = false; break;
            }
        }
        return result.ToString();
    }

    /// <summary>True when the declaration that starts at token <paramref name="from"/> ends at a ';' with no
    /// initializer, no function signature and no <c>static</c> (which keeps it a true constant).</summary>
    static bool HasNoInitializer(List<(int Start, string Value)> tokens, int from)
    {
        for (int k = from; k < tokens.Count; k++)
        {
            switch (tokens[k].Value)
            {
                case ";": return true;
                case "=": case "(": case "{": case "static": return false;
            }
        }
        return false;
    }

    /// <summary>Identifiers and single punctuation characters with their offsets; comments, string and
    /// character literals and preprocessor lines are skipped.</summary>
    static List<(int Start, string Value)> Tokens(string s)
    {
        var tokens = new List<(int, string)>();
        bool lineStart = true;
        int i = 0;
        while (i < s.Length)
        {
            char c = s[i];
            if (c == '\n') { lineStart = true; i++; continue; }
            if (char.IsWhiteSpace(c)) { i++; continue; }
            if (c == '/' && i + 1 < s.Length && s[i + 1] == '/')
            {
                while (i < s.Length && s[i] != '\n') i++;
                continue;
            }
            if (c == '/' && i + 1 < s.Length && s[i + 1] == '*')
            {
                int end = s.IndexOf("*/", i + 2, System.StringComparison.Ordinal);
                i = end < 0 ? s.Length : end + 2;
                continue;
            }
            if (c == '#' && lineStart)
            {
                // A directive runs to the end of the line, continued by a trailing backslash.
                while (i < s.Length && s[i] != '\n') i += s[i] == '\\' && i + 1 < s.Length ? 2 : 1;
                continue;
            }
            lineStart = false;
            if (c == '"' || c == '\'')
            {
                int j = i + 1;
                while (j < s.Length && s[j] != c && s[j] != '\n') j += s[j] == '\\' ? 2 : 1;
                tokens.Add((i, c.ToString()));
                i = j + 1;
                continue;
            }
            if (char.IsLetter(c) || c == '_')
            {
                int j = i;
                while (j < s.Length && (char.IsLetterOrDigit(s[j]) || s[j] == '_')) j++;
                tokens.Add((i, s.Substring(i, j - i)));
                i = j;
                continue;
            }
            if (char.IsDigit(c))
            {
                int j = i;
                while (j < s.Length && (char.IsLetterOrDigit(s[j]) || s[j] == '.')) j++;
                tokens.Add((i, s.Substring(i, j - i)));
                i = j;
                continue;
            }
            tokens.Add((i, c.ToString()));
            i++;
        }
        return tokens;
    }
}
