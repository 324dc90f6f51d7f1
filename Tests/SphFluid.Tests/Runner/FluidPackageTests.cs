using System;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless.Scenes;
using SphFluid.UnityFiles.Assets;

namespace SphFluid.Tests.Runner
{
    /// <summary>
    /// Where the runner finds the fluid package of a scene's project. A project that added the fluid by git URL has no
    /// Packages/com.sphfluid.fluid: Package Manager put the package in Library/PackageCache/com.sphfluid.fluid@hash, and
    /// the runner refused every one of its scenes for script guids "no .meta in the project has". Each test copies the
    /// project and changes where the package is, its version, or what else the project holds.
    /// </summary>
    public sealed class FluidPackageTests
    {
        const string CachedName = FluidPackage.Name + "@1a2b3c4d5e";

        [Test]
        public void ASceneOfAProjectWithTheCachedPackageIsReadThroughIt()
        {
            string root = ProjectWithTheCachedPackage();

            var scene = SceneLoader.Load(Path.Combine(root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity"), new UnityProject(root));

            Assert.That(scene.Description.Phases().Select(p => p.Name).ToArray(), Is.EqualTo(new[] { "Water", "Oil" }));
            Assert.That(scene.PackageFolder, Is.EqualTo(Path.Combine(root, "Library", "PackageCache", CachedName)), "whose Shaders/ the run compiles");
        }

        /// <summary>Two cached copies leave it open which one Unity uses: neither is guessed at.</summary>
        [Test]
        public void TwoCachedCopiesAreRefusedNamingBoth()
        {
            string root = ProjectWithTheCachedPackage();
            CopyFolder(Path.Combine(root, "Library", "PackageCache", CachedName), Path.Combine(root, "Library", "PackageCache", FluidPackage.Name + "@ffff"));
            string scene = Path.Combine(root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity");

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(scene, new UnityProject(root)))!;

            Assert.That(e.Message, Is.EqualTo($"{scene}: the project at {root} holds 2 copies of {FluidPackage.Name} in " +
                $"Library/PackageCache ({CachedName}, {FluidPackage.Name}@ffff), and which one Unity uses cannot be told: close the " +
                "editor, delete Library/PackageCache and let Unity resolve its packages again"));
        }

        [Test]
        public void AnEmbeddedPackageIsTheOneUsedWhereTheCacheHoldsOneToo()
        {
            string root = RunnerPaths.ProjectCopy("package-cache");
            CopyFolder(Path.Combine(root, "Packages", FluidPackage.Name), Path.Combine(root, "Library", "PackageCache", CachedName));

            var scene = SceneLoader.Load(Path.Combine(root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity"), new UnityProject(root));

            Assert.That(scene.PackageFolder, Is.EqualTo(Path.Combine(root, "Packages", FluidPackage.Name)));
        }

        /// <summary>The runner reads fields and fills kernel constants as its own version declares them.</summary>
        [Test]
        public void APackageOfAnotherVersionIsRefusedNamingBoth()
        {
            string root = ProjectWithTheCachedPackage();
            string manifest = Path.Combine(root, "Library", "PackageCache", CachedName, "package.json");
            File.WriteAllText(manifest, File.ReadAllText(manifest).Replace($"\"version\": \"{FluidPackage.Version}\"", "\"version\": \"0.1.0\""));
            string scene = Path.Combine(root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity");

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(scene, new UnityProject(root)))!;

            Assert.That(e.Message, Is.EqualTo($"{scene}: its project uses {FluidPackage.Name} 0.1.0 ({Path.Combine(root, "Library", "PackageCache", CachedName)}), " +
                $"and this runner is built from {FluidPackage.Version}, whose field names and kernel constants it uses: run the scene with a runner " +
                "built from the same version"));
        }

        [Test]
        public void AProjectWithoutThePackageIsRefusedForIt()
        {
            string root = RunnerPaths.ProjectCopy("package-cache");
            Directory.Delete(Path.Combine(root, "Packages", FluidPackage.Name), recursive: true);
            string scene = Path.Combine(root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity");

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(scene, new UnityProject(root)))!;

            Assert.That(e.Message, Does.StartWith($"{scene}: the project at {root} has no {FluidPackage.Name} package"));
        }

        [Test]
        public void AManifestThatIsNotJsonIsRefusedNamingIt()
        {
            string root = ProjectWithTheCachedPackage();
            string manifest = Path.Combine(root, "Library", "PackageCache", CachedName, "package.json");
            File.WriteAllText(manifest, "{ \"name\": \"com.sphfluid.fluid\", ");
            string scene = Path.Combine(root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity");

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(scene, new UnityProject(root)))!;

            Assert.That(e.Message, Does.StartWith($"{manifest}: cannot be read as the {FluidPackage.Name} package's manifest: "));
        }

        /// <summary>A pipe blocks whoever opens it: the manifest is judged before it is opened, as a scene is.</summary>
        [Test]
        public void AManifestThatIsAPipeIsRefusedWithoutOpeningIt()
        {
            string root = ProjectWithTheCachedPackage();
            string manifest = Path.Combine(root, "Library", "PackageCache", CachedName, "package.json");
            RunnerPaths.Pipe(manifest);
            string scene = Path.Combine(root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity");

            var e = Assert.Throws<SceneException>(() => SceneLoader.Load(scene, new UnityProject(root)))!;

            Assert.That(e.Message, Does.Contain($"{manifest}: is empty or not a regular file (a device, a pipe or a /proc file)"));
        }

        /// <summary>Unity binds a component to its script by guid; a game's own Fluid.cs is another class.</summary>
        [Test]
        public void AGamesOwnScriptOfTheSameFileNameIsNotTheFluids()
        {
            string root = RunnerPaths.ProjectCopy("package-cache");
            string script = Path.Combine(root, "Assets", "FluidDemo", "Scripts", "Fluid.cs");
            File.WriteAllText(script, "namespace Game { public sealed class Fluid : UnityEngine.MonoBehaviour { } }\n");
            File.WriteAllText(script + ".meta", File.ReadAllText(Path.Combine(root, "Assets", "FluidDemo", "Scripts", "OrbitCamera.cs.meta"))
                .Replace(new UnityProject(root).GuidOf("Assets/FluidDemo/Scripts/OrbitCamera.cs")!, "5d1c0e2f8a9b4c3d8e7f6a5b4c3d2e1f"));

            var scene = SceneLoader.Load(Path.Combine(root, "Assets", "FluidDemo", "Scenes", "OilAndWater.unity"), new UnityProject(root));

            Assert.That(scene.SimulatorObject, Is.EqualTo("Fluid"));
        }

        static string ProjectWithTheCachedPackage()
        {
            string root = RunnerPaths.ProjectCopy("package-cache");
            string embedded = Path.Combine(root, "Packages", FluidPackage.Name);
            CopyFolder(embedded, Path.Combine(root, "Library", "PackageCache", CachedName));
            Directory.Delete(embedded, recursive: true);
            return root;
        }

        static void CopyFolder(string from, string to)
        {
            foreach (string file in Directory.EnumerateFiles(from, "*", SearchOption.AllDirectories))
            {
                string copy = Path.Combine(to, Path.GetRelativePath(from, file));
                Directory.CreateDirectory(Path.GetDirectoryName(copy)!);
                File.Copy(file, copy);
            }
        }
    }
}
