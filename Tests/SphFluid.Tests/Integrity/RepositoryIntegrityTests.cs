using System;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Xml.Linq;
using NUnit.Framework;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Integrity;

namespace SphFluid.Tests.Integrity
{
    /// <summary>The real project, as Unity would open it, and the structural wall between engine-free and Unity code.</summary>
    public sealed class RepositoryIntegrityTests
    {
        static string RepoRoot => AssetIntegrity.FindProjectRoot(TestContext.CurrentContext.TestDirectory);

        static string At(string relativePath) => Path.Combine(RepoRoot, relativePath);

        [Test]
        public void Unity_would_open_the_project_without_asset_problems()
        {
            var problems = AssetIntegrity.Check(RepoRoot);
            Assert.That(problems.Count, Is.Zero, AssetIntegrity.Describe(problems));
        }

        [Test]
        public void Manifest_names_the_packages_at_the_kit_versions_for_2022_3()
        {
            var manifest = PackageManifest.Load(At("Packages/manifest.json"));
            Assert.That(manifest.VersionOf("com.unity.inputsystem"), Is.EqualTo("1.7.0"));
            Assert.That(manifest.VersionOf("com.unity.mathematics"), Is.EqualTo("1.2.6"));
            Assert.That(manifest.VersionOf("com.unity.test-framework"), Is.EqualTo("1.1.33"));
            Assert.That(manifest.VersionOf("com.unity.ugui"), Is.EqualTo("1.0.0"));
            Assert.That(manifest.Dependencies.Keys.Count(k => k.StartsWith("com.unity.modules.", StringComparison.Ordinal)), Is.EqualTo(31));
            Assert.That(manifest.Has("com.unity.modules.accessibility"), Is.False);
            Assert.That(ProjectVersion.Load(At("ProjectSettings/ProjectVersion.txt")).Stream, Is.EqualTo("2022.3"));
        }

        [Test]
        public void The_fluid_is_an_embedded_package_a_project_can_add_by_git_url()
        {
            var package = EmbeddedPackage.Load(At("Packages/com.sphfluid.fluid/package.json"));
            Assert.That(package.Problems("com.sphfluid.fluid"), Is.Empty);
            Assert.That(package.Name, Is.EqualTo("com.sphfluid.fluid"));
            Assert.That(package.Unity, Is.EqualTo("2022.3"));
            var manifest = PackageManifest.Load(At("Packages/manifest.json"));
            foreach (var (name, version) in package.Dependencies)
                Assert.That(manifest.VersionOf(name), Is.EqualTo(version), $"package.json dependency {name}");
            Assert.That(manifest.Testables, Does.Contain("com.sphfluid.fluid"), "the package's tests run in the Test Runner");
            foreach (var file in new[] { "LICENSE", "CHANGELOG.md", "Documentation~/index.md" })
                Assert.That(File.Exists(At("Packages/com.sphfluid.fluid/" + file)), Is.True, file);
            Assert.That(File.ReadAllText(At("Packages/com.sphfluid.fluid/LICENSE")), Does.StartWith("MIT License"));
            Assert.That(File.ReadAllText(At("Packages/com.sphfluid.fluid/CHANGELOG.md")), Does.Contain("## [" + package.Version + "]"),
                "the changelog describes the package's version");
        }

        [Test]
        public void The_package_holds_the_library_assemblies_and_the_demo_stays_in_assets()
        {
            string Name(string path) => AssemblyDefinition.Load(At(path)).Name;
            var inPackage = Directory.GetFiles(At("Packages/com.sphfluid.fluid"), "*.asmdef", SearchOption.AllDirectories)
                .Select(f => AssemblyDefinition.Load(f).Name).OrderBy(n => n, StringComparer.Ordinal);
            Assert.That(inPackage, Is.EqualTo(new[] { "SphFluid.Core", "SphFluid.Editor", "SphFluid.Runtime", "SphFluid.Tests.Core", "SphFluid.Tests.EditMode", "SphFluid.Tests.PlayMode" }));
            var packageAssemblies = inPackage.ToHashSet();
            foreach (var file in Directory.GetFiles(At("Packages/com.sphfluid.fluid"), "*.asmdef", SearchOption.AllDirectories))
                foreach (var reference in AssemblyDefinition.Load(file).References.Where(r => r.StartsWith("SphFluid.", StringComparison.Ordinal)))
                    Assert.That(packageAssemblies, Does.Contain(reference),
                        $"{Path.GetFileName(file)} references {reference}, which a project that adds only the package lacks");
            Assert.That(Name("Assets/FluidDemo/Scripts/SphFluid.Demo.asmdef"), Is.EqualTo("SphFluid.Demo"));
            Assert.That(Directory.GetFiles(At("Assets/FluidDemo/Scenes"), "*.unity"), Is.Not.Empty);
        }

        [Test]
        public void Core_assembly_is_engine_free_in_unity()
        {
            var core = AssemblyDefinition.Load(At("Packages/com.sphfluid.fluid/Runtime/Core/SphFluid.Core.asmdef"));
            Assert.That(core.Name, Is.EqualTo("SphFluid.Core"));
            Assert.That(core.NoEngineReferences, Is.True);
            Assert.That(core.References, Is.Empty);
        }

        [Test]
        public void Core_test_assembly_is_an_engine_free_edit_mode_test_assembly()
        {
            var tests = AssemblyDefinition.Load(At("Packages/com.sphfluid.fluid/Tests/Core/SphFluid.Tests.Core.asmdef"));
            Assert.That(tests.Name, Is.EqualTo("SphFluid.Tests.Core"));
            Assert.That(tests.References, Is.EquivalentTo(new[] { "SphFluid.Core", "UnityEngine.TestRunner", "UnityEditor.TestRunner" }));
            Assert.That(tests.IncludePlatforms, Is.EqualTo(new[] { "Editor" }));
            Assert.That(tests.OverrideReferences, Is.True);
            Assert.That(tests.PrecompiledReferences, Is.EqualTo(new[] { "nunit.framework.dll" }));
            Assert.That(tests.DefineConstraints, Is.EqualTo(new[] { "UNITY_INCLUDE_TESTS" }));
            Assert.That(tests.AutoReferenced, Is.False);
            Assert.That(tests.NoEngineReferences, Is.True);
        }

        [TestCase("Packages/com.sphfluid.fluid/Runtime/Core")]
        [TestCase("Packages/com.sphfluid.fluid/Tests/Core")]
        public void Engine_free_code_never_mentions_the_engine(string folder)
        {
            // The test asmdef's TestRunner references are assemblies of the test framework, not engine code.
            var offenders = Directory.GetFiles(At(folder), "*", SearchOption.AllDirectories)
                .Where(f => !f.EndsWith(".meta", StringComparison.Ordinal))
                .Where(f =>
                {
                    var text = File.ReadAllText(f).Replace("\"UnityEngine.TestRunner\"", "").Replace("\"UnityEditor.TestRunner\"", "");
                    return text.Contains("UnityEngine") || text.Contains("UnityEditor");
                })
                .Select(f => Path.GetRelativePath(RepoRoot, f))
                .ToList();
            Assert.That(offenders, Is.Empty, "engine-free code mentions UnityEngine/UnityEditor:\n  " + string.Join("\n  ", offenders));
        }

        [Test]
        public void Engine_free_folders_hold_no_nested_assembly()
        {
            var nested = Directory.GetFiles(At("Packages/com.sphfluid.fluid/Runtime/Core"), "*.asm*", SearchOption.AllDirectories)
                .Concat(Directory.GetFiles(At("Packages/com.sphfluid.fluid/Tests/Core"), "*.asm*", SearchOption.AllDirectories))
                .Where(f => !f.EndsWith(".meta", StringComparison.Ordinal))
                .Select(f => Path.GetRelativePath(RepoRoot, f).Replace('\\', '/'))
                .OrderBy(f => f, StringComparer.Ordinal)
                .ToList();
            Assert.That(nested, Is.EqualTo(new[] { "Packages/com.sphfluid.fluid/Runtime/Core/SphFluid.Core.asmdef", "Packages/com.sphfluid.fluid/Tests/Core/SphFluid.Tests.Core.asmdef" }));
        }

        [Test]
        public void Headless_core_project_compiles_exactly_the_unity_core_folder()
        {
            var project = XDocument.Load(At("Headless/SphFluid.Core/SphFluid.Core.csproj"));
            var properties = project.Descendants("PropertyGroup").Elements().ToDictionary(e => e.Name.LocalName, e => e.Value);
            Assert.That(properties["EnableDefaultCompileItems"], Is.EqualTo("false"));
            Assert.That(properties["TargetFramework"], Is.EqualTo("netstandard2.1"));
            Assert.That(properties["LangVersion"], Is.EqualTo("9.0"));
            var compiled = project.Descendants("Compile").Select(e => (string)e.Attribute("Include")).ToList();
            Assert.That(compiled, Is.EqualTo(new[] { "$(RepoRoot)/Packages/com.sphfluid.fluid/Runtime/Core/**/*.cs" }));
            Assert.That(project.Descendants("Reference").Concat(project.Descendants("PackageReference")).Concat(project.Descendants("ProjectReference")), Is.Empty);
        }

        [Test]
        public void Headless_test_project_compiles_exactly_the_unity_core_tests()
        {
            var project = XDocument.Load(At("Tests/SphFluid.Tests/SphFluid.Tests.csproj"));
            var shared = project.Descendants("Compile").Select(e => (string)e.Attribute("Include")).Where(i => i != null && i.Contains("Packages/")).ToList();
            Assert.That(shared, Is.EqualTo(new[] { "$(RepoRoot)/Packages/com.sphfluid.fluid/Tests/Core/**/*.cs" }));
            Assert.That(project.Descendants("LangVersion").Single().Value, Is.EqualTo("9.0"));
        }

        [Test]
        public void Compiled_core_references_no_engine_assembly()
        {
            var core = Assembly.Load("SphFluid.Core");
            var references = core.GetReferencedAssemblies().Select(a => a.Name).ToList();
            Assert.That(references, Has.Member("netstandard"));
            Assert.That(references.Where(r => r.StartsWith("Unity", StringComparison.Ordinal)), Is.Empty);
        }

        [Test]
        public void Assets_hold_no_build_outputs_or_dotnet_projects()
        {
            var dirs = Directory.GetDirectories(At("Assets"), "*", SearchOption.AllDirectories)
                .Where(d => Path.GetFileName(d).Equals("bin", StringComparison.OrdinalIgnoreCase) || Path.GetFileName(d).Equals("obj", StringComparison.OrdinalIgnoreCase));
            var files = Directory.GetFiles(At("Assets"), "*", SearchOption.AllDirectories)
                .Where(f => f.EndsWith(".csproj", StringComparison.OrdinalIgnoreCase) || f.EndsWith(".sln", StringComparison.OrdinalIgnoreCase));
            var offenders = dirs.Concat(files).Select(p => Path.GetRelativePath(RepoRoot, p)).ToList();
            Assert.That(offenders, Is.Empty, string.Join("\n", offenders));
        }
    }
}
