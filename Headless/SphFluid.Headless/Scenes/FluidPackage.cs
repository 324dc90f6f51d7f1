using System;
using System.IO;
using System.Linq;
using System.Text.Json;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Headless.Scenes;

/// <summary>
/// The fluid's Unity package as this runner was built from it. The runner reads a scene's components by the field names
/// of this version's scripts and runs the kernels of the scene's project with this version's constants, so the project's
/// copy of the package (embedded, or the one Package Manager put in Library/PackageCache for a git URL) must be this
/// version: another would be read and run with the wrong layout.
/// </summary>
public static class FluidPackage
{
    public const string Name = "com.sphfluid.fluid";

    /// <summary>The version in the package.json this runner was built with (an embedded resource).</summary>
    public static string Version { get; } = BuiltVersion();

    /// <summary>The folder of the package the scene's project uses, whose Shaders/ the run compiles.</summary>
    /// <exception cref="SceneException">The project has no copy of the package, or one of another version.</exception>
    public static string FolderFor(string scenePath, UnityProject project)
    {
        string folder = project.PackageFolder(Name) ?? throw new SceneException(Missing(scenePath, project));
        string manifest = Path.Combine(folder, "package.json");
        string? version;
        // Read as the scene is, bounded: a package.json that is a pipe or a device must not hang the run.
        try { version = EmbeddedPackage.Parse(UnityTextFile.Read(manifest), manifest).Version; }
        catch (Exception e) when (e is FormatException or JsonException or IOException or UnauthorizedAccessException)
        {
            throw new SceneException($"{manifest}: cannot be read as the {Name} package's manifest: {e.Message}", e);
        }
        if (version != Version)
            throw new SceneException($"{scenePath}: its project uses {Name} {version ?? "(no version)"} ({folder}), and this runner " +
                $"is built from {Version}, whose field names and kernel constants it uses: run the scene with a runner built from the same version");
        return folder;
    }

    /// <summary>Why the project has no one copy of the package: none, or several in the cache, of which the one Unity uses
    /// cannot be told from the files.</summary>
    static string Missing(string scenePath, UnityProject project)
    {
        var cached = project.CachedCopies(Name);
        return cached.Count > 1
            ? $"{scenePath}: the project at {project.Root} holds {cached.Count} copies of {Name} in Library/PackageCache " +
              $"({string.Join(", ", cached.Select(Path.GetFileName))}), and which one Unity uses cannot be told: close the editor, " +
              "delete Library/PackageCache and let Unity resolve its packages again"
            : $"{scenePath}: the project at {project.Root} has no {Name} package (neither Packages/{Name}/ nor " +
              $"Library/PackageCache/{Name}@<version>/ with a package.json)";
    }

    /// <summary>The guid of the package's Runtime/<paramref name="className"/>.cs, by its path: a project may hold a script
    /// of the same file name (a game's own Fluid.cs), which is another class.</summary>
    public static string? ScriptGuid(UnityProject project, string packageFolder, string className) =>
        project.GuidOf(Path.Combine(packageFolder, "Runtime", className + ".cs"));

    static string BuiltVersion()
    {
        using var stream = typeof(FluidPackage).Assembly.GetManifestResourceStream("package.json")
            ?? throw new InvalidOperationException("the runner was built without its package.json resource");
        using var reader = new StreamReader(stream);
        return EmbeddedPackage.Parse(reader.ReadToEnd()).Version
            ?? throw new InvalidOperationException("the runner's package.json has no version");
    }
}
