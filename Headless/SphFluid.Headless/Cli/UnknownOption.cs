using System;
using System.CommandLine;
using System.Linq;

namespace SphFluid.Headless.Cli;

/// <summary>
/// The refusal of an option a command does not have, naming the nearest one it has. The commands spell alike options
/// apart on purpose (simulate's one <c>--particles-scale</c>, bench's and study's lists <c>--particles-scales</c>;
/// simulate's <c>--solver</c>, study's <c>--solvers</c>), so a reader who carries one command's spelling to the next
/// is told the other's rather than sent to read the help.
/// </summary>
public static class UnknownOption
{
    public static string Message(Command command, string token)
    {
        string? nearest = Nearest(command, token);
        string hint = nearest == null ? "" : $"; did you mean {nearest}?";
        return $"{command.Name}: unknown option {token}{hint} (see sphfluid {command.Name} --help)";
    }

    /// <summary>The command's option within two edits of the token (a value given as <c>--name=value</c> aside), and
    /// within a third of its length, so that a short stranger such as <c>--fast</c> is not matched to <c>--out</c>.</summary>
    static string? Nearest(Command command, string token)
    {
        int eq = token.IndexOfAny(new[] { '=', ':' });
        string given = eq > 0 ? token[..eq] : token;
        return command.Options
            .Select(o => o.Name)
            .Where(n => n.StartsWith("--", StringComparison.Ordinal) && n != given)
            .Select(n => (Name: n, Distance: Edits(given.ToLowerInvariant(), n)))
            .Where(c => c.Distance <= Math.Min(2, c.Name.Length / 3))
            .OrderBy(c => c.Distance)
            .Select(c => c.Name)
            .FirstOrDefault();
    }

    /// <summary>Levenshtein distance: insertions, deletions and substitutions.</summary>
    static int Edits(string a, string b)
    {
        var row = new int[b.Length + 1];
        for (int j = 0; j <= b.Length; j++) row[j] = j;
        for (int i = 1; i <= a.Length; i++)
        {
            int diagonal = row[0];
            row[0] = i;
            for (int j = 1; j <= b.Length; j++)
            {
                int above = row[j];
                row[j] = Math.Min(Math.Min(row[j] + 1, row[j - 1] + 1), diagonal + (a[i - 1] == b[j - 1] ? 0 : 1));
                diagonal = above;
            }
        }
        return row[b.Length];
    }
}
