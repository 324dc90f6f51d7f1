using System;

namespace SphFluid.UnityFiles.Yaml;

/// <summary>The text is not YAML that Unity would load; names the file and 1-based line.</summary>
public sealed class UnityYamlException : FormatException
{
    public UnityYamlException(string? path, int line, string reason)
        : base($"{path ?? "<text>"}:{line}: {reason}")
    {
        Path = path;
        LineNumber = line;
        Reason = reason;
    }

    /// <summary>The file, or null for text parsed without one.</summary>
    public string? Path { get; }
    public int LineNumber { get; }
    public string Reason { get; }
}
