namespace SphFluid.UnityFiles.Integrity;

/// <summary>One thing Unity would complain about (or silently break on), naming the file (repo-relative, '/' separators).</summary>
public sealed record IntegrityProblem(string Path, string Message)
{
    public override string ToString() => $"{Path}: {Message}";
}
