using System.Text;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Text that came from a scene file or a command line, made safe to print. A name or value may hold control
    /// characters (a scene's double-quoted "\e[2J" is an escape sequence once parsed, and a binary file's bytes are
    /// quoted as read); written to a terminal as they are, they would clear it, recolour it, or move the cursor back over
    /// the error that quotes them, and a right-to-left override would show a name backwards. Each such character is
    /// written instead as a C# escape, \u001B, so the reader sees what the file holds.
    /// </summary>
    public static class PrintableText
    {
        /// <summary>False for the characters a terminal acts on rather than shows: the C0 and C1 controls and DEL
        /// (char.IsControl), and Unicode's bidirectional formatting controls, which reorder the text around them.</summary>
        public static bool IsPrintable(char c) =>
            !char.IsControl(c) && c != '\u061C' && c != '\u200E' && c != '\u200F'
            && (c < '\u202A' || c > '\u202E') && (c < '\u2066' || c > '\u2069');

        /// <summary>Index of the first character that is not <see cref="IsPrintable"/>, or -1.</summary>
        public static int FirstUnprintable(string text)
        {
            for (int i = 0; i < text.Length; i++)
                if (!IsPrintable(text[i])) return i;
            return -1;
        }

        /// <summary><paramref name="text"/> with every unprintable character written as \uXXXX. With
        /// <paramref name="keepLineBreaks"/>, '\n' stays (a message's own layout: a list of problems, one a line).</summary>
        public static string Escape(string text, bool keepLineBreaks = false)
        {
            if (text == null) return null;
            int first = FirstUnprintable(text);
            if (first < 0) return text;
            var b = new StringBuilder(text.Length + 16);
            b.Append(text, 0, first);
            for (int i = first; i < text.Length; i++)
            {
                char c = text[i];
                if (IsPrintable(c) || (keepLineBreaks && c == '\n')) b.Append(c);
                else b.Append("\\u").Append(((int)c).ToString("X4", System.Globalization.CultureInfo.InvariantCulture));
            }
            return b.ToString();
        }
    }
}
