using System;
using System.Collections.Generic;
using System.IO;
using IoPath = System.IO.Path;
using System.Linq;
using System.Text;
using System.Text.RegularExpressions;
using SphFluid.Headless.Cli;

namespace SphFluid.Headless.Output;

/// <summary>
/// The folder a run writes into, and the only files of it the run may touch. Every file the runner writes is
/// first recorded in a manifest (<see cref="ManifestName"/>) in that folder; a later run deletes exactly the
/// files an earlier run's manifest lists, so stale frames, CSV and summary never outlive their run. A file the
/// runner would write but that no manifest lists belongs to someone else: the run refuses the folder rather
/// than overwrite it. A run holds its manifest open, locked against every other, until it is disposed: two runs given
/// one folder (two runs of one scene started at once share its default --out) would each delete the other's files and
/// leave a manifest that lists only one run's, so the second is refused while the first runs.
/// </summary>
public sealed class OutputFolder : IDisposable
{
    /// <summary>The manifest of the files sphfluid wrote here, one file name a line.</summary>
    public const string ManifestName = ".sphfluid-outputs";

    // Every name the runner may write. Anything else in the folder is never looked at.
    static readonly Regex OwnName = new(@"^(frame_\d{4,}\.png|top_\d{4,}\.png|layering\.(png|svg)|bench-scaling\.(png|svg)|study\.(csv|md)|study-pareto\.(png|svg)|diagnostics\.csv|summary\.txt|particles_\d{4,}\.(vtu|ply)|particles\.pvd)$", RegexOptions.CultureInvariant);

    readonly HashSet<string> _written = new(StringComparer.Ordinal);
    readonly FileStream _manifest;
    readonly bool _madeManifest;
    readonly IReadOnlyList<string> _madeFolders;

    OutputFolder(string path, FileStream manifest, bool madeManifest, IReadOnlyList<string> madeFolders)
    {
        Path = path;
        _manifest = manifest;
        _madeManifest = madeManifest;
        _madeFolders = madeFolders;
    }

    /// <summary>The folder, as given.</summary>
    public string Path { get; }

    /// <summary>Whether <paramref name="fileName"/> is a name the runner writes.</summary>
    public static bool IsRunnerName(string fileName) => OwnName.IsMatch(fileName);

    /// <summary>
    /// Creates the folder if needed and removes the files an earlier run recorded in its manifest. Refuses
    /// (<see cref="UsageException"/> naming <paramref name="option"/>) an empty path, a path that is a file,
    /// a folder holding a runner-named file that no manifest claims or a folder under a runner's file name (the run
    /// would fail at that file part-way), and a manifest that is not a plain file: the run writes it, and a link there
    /// would have it write through to whatever file the link names. A claim refused, or failed, leaves none of the
    /// folders it made for the path.
    /// </summary>
    public static OutputFolder Claim(string path, string option, string command)
    {
        if (string.IsNullOrWhiteSpace(path))
            throw new UsageException($"{command}: {option} needs a folder path (was empty)");
        try
        {
            if (File.Exists(path))
            {
                // A link that loops, or leads to a file or nowhere, reads as a file here: say it is a link.
                if (new FileInfo(path).LinkTarget is string target)
                    throw new UsageException($"{command}: {option} '{path}' is a symbolic link to '{target}' that does not lead to a folder; " +
                        "give a folder or a new path (nothing was changed)");
                throw new UsageException($"{command}: {option} '{path}' is a file, not a folder");
            }
            // Creating it would fail with "Could not find a part of the path", which does not say which part.
            if (FileAmongParents(path) is string parent)
                throw new UsageException($"{command}: {option} '{path}' lies under '{parent}', which is a file, not a folder");
            var madeFolders = MissingFolders(path);
            try
            {
                Directory.CreateDirectory(path);
                return ClaimFolder(path, option, command, madeFolders);
            }
            catch
            {
                // Refused, or failed past the folders (a manifest path longer than the system allows), the claim leaves
                // none of the folders it made.
                RemoveEmpty(madeFolders);
                throw;
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            throw new UsageException($"{command}: {option} '{path}' cannot be used as the output folder: {e.Message}");
        }
    }

    /// <summary>The claim of folder <paramref name="path"/>, which exists: its manifest opened and locked, the earlier
    /// run's outputs removed; refused as <see cref="Claim"/> says.</summary>
    static OutputFolder ClaimFolder(string path, string option, string command, IReadOnlyList<string> madeFolders)
    {
        string manifestPath = IoPath.Combine(path, ManifestName);
        if (Directory.Exists(manifestPath) || new FileInfo(manifestPath).LinkTarget != null)
            throw new UsageException($"{command}: {option} '{path}' holds a {ManifestName} that is a link or a folder, not the plain file " +
                "sphfluid writes; choose an empty or new folder (nothing was changed)");
        bool manifestExisted = File.Exists(manifestPath);
        var manifest = OpenHeld(manifestPath, path, option, command);
        try
        {
            if (FirstNames(Directory.EnumerateDirectories(path), IsRunnerName) is string folders)
                throw new UsageException($"{command}: {option} '{path}' holds a folder named {folders}, where sphfluid writes a file; " +
                    "choose an empty or new folder (nothing was changed)");
            var claimed = ReadManifest(manifest);
            if (FirstNames(Directory.EnumerateFiles(path), name => IsRunnerName(name) && !claimed.Contains(name)) is string foreign)
                throw new UsageException($"{command}: {option} '{path}' already holds {foreign} that sphfluid did not write; " +
                    "choose an empty or new folder (nothing was deleted)");
            foreach (string name in claimed)
            {
                string file = IoPath.Combine(path, name);
                if (File.Exists(file)) File.Delete(file);
            }
            manifest.SetLength(0);
            manifest.Position = 0;
            return new OutputFolder(path, manifest, madeManifest: !manifestExisted, madeFolders);
        }
        catch
        {
            manifest.Dispose();
            // A refused folder keeps nothing of the run, not even the empty manifest it opened to lock.
            if (!manifestExisted) File.Delete(manifestPath);
            throw;
        }
    }

    /// <summary>The manifest, opened (made where there is none) and locked against every other open until the run
    /// disposes it; held by another run, the folder is refused.</summary>
    static FileStream OpenHeld(string manifestPath, string path, string option, string command)
    {
        try
        {
            return new FileStream(manifestPath, FileMode.OpenOrCreate, FileAccess.ReadWrite, FileShare.None);
        }
        catch (IOException e) when (IsHeldByAnother(e))
        {
            throw new UsageException($"{command}: {option} '{path}' is in use by another sphfluid run (it holds {ManifestName} open); " +
                "give another folder, or wait for that run to end (nothing was changed)");
        }
        catch (FileNotFoundException e) when (Directory.Exists(path))
        {
            // A folder of a system file system (/proc, /sys) answers a new file with "not found", which reads as if the
            // folder were missing.
            throw new UsageException($"{command}: {option} '{path}' is a folder in which no file can be made (making {ManifestName} " +
                $"there failed: {e.Message.TrimEnd('.')}); give a folder on a disk (nothing was changed)");
        }
    }

    /// <summary>A sharing violation: EWOULDBLOCK from the advisory lock .NET takes on Unix, ERROR_SHARING_VIOLATION or
    /// ERROR_LOCK_VIOLATION on Windows.</summary>
    static bool IsHeldByAnother(IOException e) =>
        OperatingSystem.IsWindows() ? (e.HResult & 0xFFFF) is 32 or 33 : e.HResult is 11 or 35;

    /// <summary>The nearest folder of <paramref name="path"/>'s that is a file, or null.</summary>
    static string? FileAmongParents(string path)
    {
        for (string? dir = IoPath.GetDirectoryName(IoPath.GetFullPath(path)); !string.IsNullOrEmpty(dir); dir = IoPath.GetDirectoryName(dir))
            if (File.Exists(dir)) return dir;
        return null;
    }

    /// <summary>The folders of <paramref name="path"/> (it included) that do not exist yet, the deepest first.</summary>
    static List<string> MissingFolders(string path)
    {
        var missing = new List<string>();
        string? dir = IoPath.TrimEndingDirectorySeparator(IoPath.GetFullPath(path));
        for (; !string.IsNullOrEmpty(dir) && !Directory.Exists(dir); dir = IoPath.GetDirectoryName(dir))
            missing.Add(dir);
        return missing;
    }

    /// <summary>The first three names of <paramref name="entries"/> that <paramref name="match"/>, in order, and how many
    /// more; null where none does.</summary>
    static string? FirstNames(IEnumerable<string> entries, Func<string, bool> match)
    {
        var names = entries.Select(entry => IoPath.GetFileName(entry)).Where(match).OrderBy(name => name, StringComparer.Ordinal).ToList();
        if (names.Count == 0) return null;
        return string.Join(", ", names.Take(3)) + (names.Count > 3 ? $" and {names.Count - 3} more" : "");
    }

    /// <summary>The full path for <paramref name="fileName"/>, recorded in the manifest before anything is written to it.</summary>
    public string PathOf(string fileName)
    {
        if (!IsRunnerName(fileName))
            throw new ArgumentException($"OutputFolder: '{fileName}' is not a name the runner writes", nameof(fileName));
        if (_written.Add(fileName))
        {
            // Flushed at once, so that a run that dies leaves every file it began listed for the next run to remove.
            _manifest.Write(Encoding.UTF8.GetBytes(fileName + "\n"));
            _manifest.Flush();
        }
        return IoPath.Combine(Path, fileName);
    }

    /// <summary>
    /// Writes <paramref name="fileName"/> whole or not at all: where <paramref name="write"/> fails, what it had written
    /// is removed, so that no truncated file is left to pass for an output; a failed write to the disk (a full one)
    /// becomes an <see cref="IOException"/> that names the file.
    /// </summary>
    public void Write(string fileName, Action<Stream> write)
    {
        string path = PathOf(fileName);
        FileStream file;
        try
        {
            file = File.Create(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // Nothing was made, so there is no part to remove (a folder taken away mid-run).
            throw new IOException($"cannot write {path}: {e.Message}", e);
        }
        try
        {
            using (file) write(file);
        }
        catch (Exception e)
        {
            string? kept = null;
            try
            {
                File.Delete(path);
            }
            catch (Exception cleanup) when (cleanup is IOException or UnauthorizedAccessException)
            {
                kept = cleanup.Message;
            }
            if (e is not (IOException or UnauthorizedAccessException)) throw;
            throw new IOException($"cannot write {path}: {e.Message}; the part written "
                + (kept == null ? "was removed" : $"could not be removed ({kept})"), e);
        }
    }

    /// <summary><see cref="Write"/> of <paramref name="text"/> in UTF-8 without a byte order mark.</summary>
    public void WriteText(string fileName, string text)
    {
        byte[] bytes = new UTF8Encoding(false).GetBytes(text);
        Write(fileName, file => file.Write(bytes));
    }

    /// <summary>Bytes free to this user on the disk that holds <paramref name="folder"/> (an existing folder), or null
    /// where the system does not say.</summary>
    public static long? FreeBytes(string folder)
    {
        try
        {
            return new DriveInfo(IoPath.GetFullPath(folder)).AvailableFreeSpace;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException)
        {
            return null;
        }
    }

    static HashSet<string> ReadManifest(FileStream manifest)
    {
        var names = new HashSet<string>(StringComparer.Ordinal);
        using var reader = new StreamReader(manifest, Encoding.UTF8, detectEncodingFromByteOrderMarks: false, bufferSize: 4096, leaveOpen: true);
        for (string? line = reader.ReadLine(); line != null; line = reader.ReadLine())
        {
            // Only bare runner names count: a manifest edited to name "../x" or "notes.txt" deletes nothing.
            string name = line.Trim();
            if (IsRunnerName(name)) names.Add(name);
        }
        return names;
    }

    /// <summary>Releases the manifest, and with it the folder, to the next run. A run that wrote nothing (it stopped before
    /// its first output: no Vulkan device, a bad environment variable) leaves nothing it made, neither the empty manifest
    /// nor the folders the claim created for it; a manifest or folder that was there before stays.</summary>
    public void Dispose()
    {
        bool leaveNothing = _written.Count == 0 && _madeManifest;
        string manifestPath = IoPath.Combine(Path, ManifestName);
        // Unlinked while still held where the system allows it (Unix), so that no other run opens it in between.
        if (leaveNothing && !OperatingSystem.IsWindows()) TryRemove(() => File.Delete(manifestPath));
        _manifest.Dispose();
        if (!leaveNothing) return;
        if (OperatingSystem.IsWindows()) TryRemove(() => File.Delete(manifestPath));
        RemoveEmpty(_madeFolders);
    }

    /// <summary>Removes the folders a claim made, deepest first; one that something else has put a file in since is not
    /// empty and stays.</summary>
    static void RemoveEmpty(IEnumerable<string> madeFolders)
    {
        foreach (string folder in madeFolders) TryRemove(() => Directory.Delete(folder, recursive: false));
    }

    /// <summary>Tidying after a run that wrote nothing: what cannot be removed is left as it is.</summary>
    static void TryRemove(Action remove)
    {
        try
        {
            remove();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
        }
    }
}
