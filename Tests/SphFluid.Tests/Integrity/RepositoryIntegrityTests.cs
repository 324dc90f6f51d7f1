using System;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Xml.Linq;
using NUnit.Framework;
using SphFluid.Headless.Scenes;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Integrity;
using SphFluid.UnityFiles.Scenes;
using SphFluid.UnityFiles.Yaml;

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
            string? Name(string path) => AssemblyDefinition.Load(At(path)).Name;
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

        const string UrpSample = "Packages/com.sphfluid.fluid/Samples~/UniversalRenderPipeline";

        [Test]
        public void The_package_offers_a_urp_sample_that_the_built_in_demo_does_not_need()
        {
            var package = EmbeddedPackage.Load(At("Packages/com.sphfluid.fluid/package.json"));
            Assert.That(package.Samples.Select(s => s.Path), Is.EqualTo(new[] { "Samples~/UniversalRenderPipeline" }));
            Assert.That(package.Samples[0].DisplayName, Is.EqualTo("Universal Render Pipeline"));
            Assert.That(package.Dependencies.Keys, Has.No.Member("com.unity.render-pipelines.universal"), "URP stays optional for the package");
            Assert.That(PackageManifest.Load(At("Packages/manifest.json")).Has("com.unity.render-pipelines.universal"), Is.False,
                "the Built-in demo project must not be forced onto URP");
            Assert.That(File.ReadAllText(At(UrpSample + "/README.md")), Does.Contain("Graphics").And.Contain("Quality").And.Contain("FluidURP"),
                "the sample says where its pipeline asset goes");
        }

        [Test]
        public void The_urp_sample_asset_turns_on_the_opaque_texture_and_renders_with_its_own_renderer()
        {
            var asset = UnityYamlFile.Load(At(UrpSample + "/Settings/FluidURP.asset")).Documents.Single();
            Assert.That(asset.ScriptGuid, Is.EqualTo("bf2edee5c58d82540a51f03df9d42094"), "UniversalRenderPipelineAsset");
            Assert.That(asset.Root.GetInt("k_AssetVersion"), Is.EqualTo(11), "the asset version URP 14 writes");
            Assert.That(asset.Root.GetInt("m_RequireOpaqueTexture"), Is.EqualTo(1), "the refraction reads _CameraOpaqueTexture");
            var renderers = asset.Root["m_RendererDataList"].OrFail("m_RendererDataList").Items;
            var renderer = renderers[asset.Root.GetInt("m_DefaultRendererIndex")].GetReference("");
            Assert.That(renderer, Is.EqualTo(new UnityReference(11400000, UnityMeta.GuidOf(At(UrpSample + "/Settings/FluidURP_Renderer.asset")), 2)));
            var rendererData = UnityYamlFile.Load(At(UrpSample + "/Settings/FluidURP_Renderer.asset")).Documents.Single();
            Assert.That(rendererData.ScriptGuid, Is.EqualTo("de640fe3d0db1804a85f9fc8f5cadab6"), "UniversalRendererData");
            Assert.That(rendererData.Root.GetInt("m_RenderingMode"), Is.Zero, "Forward");
        }

        [Test]
        public void The_urp_sample_scene_holds_the_oil_and_water_fluid_and_only_package_scripts()
        {
            var project = new UnityProject(RepoRoot);
            var scene = UnityScene.Load(At(UrpSample + "/OilAndWaterURP.unity"));
            Assert.That(scene.Behaviours(project.ScriptGuid("Fluid")).Count(), Is.EqualTo(1));
            Assert.That(scene.Behaviours(project.ScriptGuid("FluidContainer")).Count(), Is.EqualTo(1));
            var phases = scene.Behaviours(project.ScriptGuid("SpawnBox")).Select(b => b.Root.GetString(RuntimeScripts.Spawn + ".Phase.Name")).OrderBy(n => n, StringComparer.Ordinal);
            Assert.That(phases, Is.EqualTo(new[] { "Oil", "Water" }));
            Assert.That(scene.FindGameObject("Main Camera"), Is.Not.Null);
            Assert.That(scene.FindGameObject("Directional Light"), Is.Not.Null);
            foreach (var behaviour in scene.Behaviours())
                Assert.That(project.AssetPathOf(behaviour.ScriptGuid), Does.StartWith("Packages/com.sphfluid.fluid/Runtime/"),
                    $"{behaviour}: an imported sample can use only what the package ships (the demo's scripts stay in Assets/)");
        }

        [Test]
        public void The_runtime_assembly_uses_urp_only_when_the_project_has_it()
        {
            var runtime = AssemblyDefinition.Load(At("Packages/com.sphfluid.fluid/Runtime/SphFluid.Runtime.asmdef"));
            Assert.That(runtime.VersionDefines, Is.EqualTo(new[] { new VersionDefine("com.unity.render-pipelines.universal", "14.0.0", "SPHFLUID_URP") }));
            Assert.That(runtime.References, Does.Contain("Unity.RenderPipelines.Universal.Runtime").And.Contain("Unity.RenderPipelines.Core.Runtime"));
            // A name outside the symbol's branch would break every project without URP.
            var unguarded = Directory.GetFiles(At("Packages/com.sphfluid.fluid/Runtime"), "*.cs", SearchOption.AllDirectories)
                .SelectMany(f => UrpLinesOutsideTheDefine(f).Select(line => $"{Path.GetRelativePath(RepoRoot, f)}:{line}"))
                .ToList();
            Assert.That(unguarded, Is.Empty, "URP names outside #if SPHFLUID_URP:\n  " + string.Join("\n  ", unguarded));
            var urpCode = Directory.GetFiles(At("Packages/com.sphfluid.fluid/Runtime"), "*.cs", SearchOption.AllDirectories)
                .Where(f => File.ReadAllText(f).Contains("#if SPHFLUID_URP", StringComparison.Ordinal)).Select(Path.GetFileName);
            Assert.That(urpCode, Is.EqualTo(new[] { "UniversalOpaqueTexture.cs" }));
        }

        /// <summary>Line numbers that name URP's API where SPHFLUID_URP is not known to be defined.</summary>
        static System.Collections.Generic.IEnumerable<int> UrpLinesOutsideTheDefine(string file)
        {
            var guarded = new System.Collections.Generic.Stack<bool>();
            var lines = File.ReadAllLines(file);
            for (int i = 0; i < lines.Length; i++)
            {
                var line = lines[i].Trim();
                if (line.StartsWith("#if", StringComparison.Ordinal)) guarded.Push(line == "#if SPHFLUID_URP");
                else if (line.StartsWith("#el", StringComparison.Ordinal) && guarded.Count > 0) { guarded.Pop(); guarded.Push(false); }
                else if (line.StartsWith("#endif", StringComparison.Ordinal) && guarded.Count > 0) guarded.Pop();
                else if (!guarded.Contains(true) && !line.StartsWith("//", StringComparison.Ordinal) &&
                         System.Text.RegularExpressions.Regex.IsMatch(line, @"Rendering\.Universal|UniversalAdditional\w+Data|UniversalRenderPipeline\w*|CameraRenderType|CameraOverrideOption"))
                    yield return i + 1;
            }
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
            var compiled = project.Descendants("Compile").Select(e => (string?)e.Attribute("Include")).ToList();
            Assert.That(compiled, Is.EqualTo(new[] { "$(RepoRoot)/Packages/com.sphfluid.fluid/Runtime/Core/**/*.cs" }));
            Assert.That(project.Descendants("Reference").Concat(project.Descendants("PackageReference")).Concat(project.Descendants("ProjectReference")), Is.Empty);
        }

        [Test]
        public void Headless_test_project_compiles_exactly_the_unity_core_tests()
        {
            // As Unity compiles them: C# 9, no nullable context, SphFluid.Core and NUnit only.
            var project = XDocument.Load(At("Tests/SphFluid.Tests.Core/SphFluid.Tests.Core.csproj"));
            var properties = project.Descendants("PropertyGroup").Elements().ToDictionary(e => e.Name.LocalName, e => e.Value);
            Assert.That(properties["EnableDefaultCompileItems"], Is.EqualTo("false"));
            Assert.That(properties["LangVersion"], Is.EqualTo("9.0"));
            Assert.That(properties["Nullable"], Is.EqualTo("disable"));
            Assert.That(properties["AssemblyName"], Is.EqualTo("SphFluid.Tests.Core"));
            var compiled = project.Descendants("Compile").Select(e => (string?)e.Attribute("Include")).ToList();
            Assert.That(compiled, Is.EqualTo(new[] { "$(RepoRoot)/Packages/com.sphfluid.fluid/Tests/Core/**/*.cs" }));
            var projects = project.Descendants("ProjectReference").Select(e => (string?)e.Attribute("Include")).ToList();
            Assert.That(projects, Is.EqualTo(new[] { "../../Headless/SphFluid.Core/SphFluid.Core.csproj" }));
            var packages = project.Descendants("PackageReference").Select(e => (string?)e.Attribute("Include")).ToList();
            Assert.That(packages, Is.EquivalentTo(new[] { "Microsoft.NET.Test.Sdk", "NUnit", "NUnit3TestAdapter", "NUnit.Analyzers" }));
            Assert.That(project.Descendants("Reference"), Is.Empty);
        }

        [Test]
        public void Headless_test_project_compiles_none_of_the_unity_files()
        {
            // The shared files are SphFluid.Tests.Core's alone: compiled here too, they would meet this project's
            // nullable context, which Unity never applies to them.
            var project = XDocument.Load(At("Tests/SphFluid.Tests/SphFluid.Tests.csproj"));
            var compiled = project.Descendants("Compile").Select(e => (string?)e.Attribute("Include") ?? "").ToList();
            Assert.That(compiled.Where(i => i.Contains("Packages/")), Is.Empty);
            Assert.That(project.Descendants("Nullable").Single().Value, Is.EqualTo("enable"));
        }

        [Test]
        public void The_test_script_runs_both_test_projects()
        {
            string script = File.ReadAllText(At("Headless/test.sh"));
            Assert.That(script, Does.Contain("Tests/SphFluid.Tests.Core/SphFluid.Tests.Core.csproj"));
            Assert.That(script, Does.Contain("Tests/SphFluid.Tests/SphFluid.Tests.csproj"));
            string solution = File.ReadAllText(At("Headless/SphFluid.sln"));
            Assert.That(solution, Does.Contain(@"..\Tests\SphFluid.Tests.Core\SphFluid.Tests.Core.csproj"));
            Assert.That(solution, Does.Contain(@"..\Tests\SphFluid.Tests\SphFluid.Tests.csproj"));
        }

        [Test]
        public void The_test_script_runs_the_long_dfsph_runs_beside_the_rest_and_nothing_twice()
        {
            // Two processes at once: one filter and its complement, so every test runs exactly once.
            string script = File.ReadAllText(At("Headless/test.sh"));
            string category = TestProcesses.LongRuns;
            Assert.That(script, Does.Contain($"filter=\"TestCategory={category}\""));
            Assert.That(script, Does.Contain($"filter=\"TestCategory!={category}\""));
        }

        [Test]
        public void The_test_script_fails_a_run_whose_unvalidated_runs_used_a_variant_no_validated_test_ran()
        {
            // The physics and layering runs skip the validation layer on the grounds that shorter validated tests record the
            // same passes; the script holds them to it from what each process's teardown wrote.
            string script = File.ReadAllText(At("Headless/test.sh"));
            Assert.That(script, Does.Contain(GpuTestDevice.VariantsFolderVariable + "=\"$scratch/variants-$half\""));
            Assert.That(script, Does.Contain("comm -23 <(cat \"$scratch\"/variants-*/unvalidated.txt"));
            Assert.That(script, Does.Contain("<(cat \"$scratch\"/variants-*/validated.txt"));
        }

        [Test]
        public void Compiled_core_references_no_engine_assembly()
        {
            var core = Assembly.Load("SphFluid.Core");
            var references = core.GetReferencedAssemblies().Select(a => a.Name ?? "").ToList();
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
