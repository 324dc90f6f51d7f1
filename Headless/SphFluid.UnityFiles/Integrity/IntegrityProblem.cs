namespace SphFluid.UnityFiles.Integrity;

/// <summary>One thing Unity would complain about (or silently break on), naming the file (repo-relative, '/' separators)
/// and, where one place is at fault, its 1-based line (0 when the problem is the file as a whole).</summary>
public sealed record IntegrityProblem(string Path, string Message, int Line = 0)
{
    public override string ToString() => Line > 0 ? $"{Path}:{Line}: {Message}" : $"{Path}: {Message}";
}
