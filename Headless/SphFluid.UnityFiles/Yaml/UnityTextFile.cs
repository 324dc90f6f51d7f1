using System;
using System.IO;
using System.Text;

namespace SphFluid.UnityFiles.Yaml;

/// <summary>
/// Reads a Unity text file only when it is a regular file of bounded size. A FIFO blocks on open, /dev/zero never
/// ends and /proc files lie about their size: all three report a length of 0, so they are refused before opening,
/// with the empty file. The read itself also stops past <see cref="MaxBytes"/>, in case the file grows meanwhile.
/// </summary>
public static class UnityTextFile
{
    /// <summary>Largest file read: 16 MiB, about a thousand times the shipped scenes (14 to 18 KB).</summary>
    public const long MaxBytes = 16L << 20;

    static string Limit => $"a text file of 1 byte to {MaxBytes >> 20} MiB";

    /// <exception cref="IOException">The path is missing, a folder, not a regular file, empty or too large;
    /// the message names the path and the allowed size.</exception>
    public static string Read(string path) => Read(path, Target(path));

    static string Read(string path, FileInfo target)
    {
        if (target.Length == 0)
            throw new IOException($"{path}: is empty or not a regular file (a device, a pipe or a /proc file); expected {Limit}");
        if (target.Length > MaxBytes)
            throw new IOException($"{path}: is {target.Length} bytes; expected {Limit}");

        using var stream = new FileStream(target.FullName, FileMode.Open, FileAccess.Read, FileShare.ReadWrite);
        var bytes = new byte[Math.Min(target.Length, MaxBytes) + 1];
        int read = 0, n;
        while (read < bytes.Length && (n = stream.Read(bytes, read, bytes.Length - read)) > 0) read += n;
        if (read > MaxBytes) throw new IOException($"{path}: grew past {MaxBytes} bytes while being read; expected {Limit}");
        using var reader = new StreamReader(new MemoryStream(bytes, 0, read), Encoding.UTF8, detectEncodingFromByteOrderMarks: true);
        return reader.ReadToEnd();
    }

    /// <summary>A project file that may be empty (an empty script or .meta is a file like any other): as <see cref="Read"/>,
    /// but a length of 0 reads as empty without the file being opened, so a pipe or a device in its place cannot block.</summary>
    public static string ReadMayBeEmpty(string path) => Target(path) is var target && target.Length == 0 ? "" : Read(path, target);

    /// <summary>The length of the file <paramref name="path"/> ends at (through links); 0 for a pipe or a device.</summary>
    public static long LengthOf(string path) => Target(path).Length;

    static FileInfo Target(string path)
    {
        // One status read for the common case, a regular file: a project reads tens of thousands of .metas, and each
        // question to the file system costs microseconds.
        var info = new FileInfo(path);
        if (!info.Exists && Directory.Exists(path)) throw new IOException($"{path}: is a folder; expected {Limit}");
        if (!info.Exists) throw new FileNotFoundException($"{path}: no such file", path);
        if ((info.Attributes & FileAttributes.ReparsePoint) == 0) return info;
        // A link's own length is the length of its target's name: judge the file it ends at.
        var target = info.LinkTarget != null ? File.ResolveLinkTarget(path, returnFinalTarget: true) as FileInfo : info;
        if (target == null || !target.Exists) throw new FileNotFoundException($"{path}: is a link to nothing", path);
        return target;
    }
}
