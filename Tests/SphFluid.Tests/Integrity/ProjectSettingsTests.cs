using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Integrity;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Tests.Integrity
{
    /// <summary>The hand-written ProjectSettings say what the project needs (unity-kit §1), read back through the parser.</summary>
    public sealed class ProjectSettingsTests
    {
        static string RepoRoot => AssetIntegrity.FindProjectRoot(TestContext.CurrentContext.TestDirectory);

        static UnityDocument Settings(string file) =>
            UnityYamlFile.Load(Path.Combine(RepoRoot, "ProjectSettings", file)).Documents.Single();

        [Test]
        public void Project_opens_in_the_editor_it_names()
        {
            var version = ProjectVersion.Load(Path.Combine(RepoRoot, "ProjectSettings/ProjectVersion.txt"));
            Assert.That(version.EditorVersion, Is.EqualTo("2022.3.62f2"));
            Assert.That(version.EditorVersionWithRevision, Is.EqualTo("2022.3.62f2 (7670c08855a9)"));
        }

        [Test]
        public void Player_uses_the_input_system_linear_colour_d3d11_mono_and_net_standard()
        {
            var player = Settings("ProjectSettings.asset");
            var root = player.Root;
            Assert.That(player.ClassId, Is.EqualTo(129));
            Assert.That(root.GetInt("serializedVersion"), Is.EqualTo(26));
            Assert.That(root.GetString("productName"), Is.EqualTo("SPH Fluid"));
            Assert.That(root.GetInt("activeInputHandler"), Is.EqualTo(1));
            Assert.That(root.GetInt("m_ActiveColorSpace"), Is.EqualTo(1));
            Assert.That(root.GetString("m_BuildTargetGraphicsAPIs[0].m_BuildTarget"), Is.EqualTo("WindowsStandaloneSupport"));
            Assert.That(root.GetString("m_BuildTargetGraphicsAPIs[0].m_APIs"), Is.EqualTo("02000000"));
            Assert.That(root.GetInt("m_BuildTargetGraphicsAPIs[0].m_Automatic"), Is.EqualTo(0));
            Assert.That(root.GetInt("scriptingBackend.Standalone"), Is.EqualTo(0));
            Assert.That(root.GetInt("apiCompatibilityLevel"), Is.EqualTo(6));
            Assert.That(root.GetBool("runInBackground"), Is.True);
        }

        [Test]
        public void Editor_serializes_text_and_shows_meta_files()
        {
            var editor = Settings("EditorSettings.asset");
            Assert.That(editor.ClassId, Is.EqualTo(159));
            Assert.That(editor.Root.GetInt("serializedVersion"), Is.EqualTo(12));
            Assert.That(editor.Root.GetInt("m_SerializationMode"), Is.EqualTo(2));
            var versionControl = Settings("VersionControlSettings.asset");
            Assert.That(versionControl.ClassId, Is.EqualTo(890905787));
            Assert.That(versionControl.Root.GetString("m_Mode"), Is.EqualTo("Visible Meta Files"));
        }

        [Test]
        public void Every_scene_of_the_project_is_in_the_build()
        {
            var scenesFolder = Path.Combine(RepoRoot, "Assets/FluidDemo/Scenes");
            var scenes = Directory.Exists(scenesFolder)
                ? Directory.GetFiles(scenesFolder, "*.unity", SearchOption.AllDirectories)
                    .Select(f => Path.GetRelativePath(RepoRoot, f).Replace('\\', '/')).OrderBy(f => f).ToList()
                : new System.Collections.Generic.List<string>();
            if (scenes.Count == 0) Assert.Ignore("no scenes under Assets/FluidDemo/Scenes yet");
            var build = Settings("EditorBuildSettings.asset").Root["m_Scenes"].OrFail("m_Scenes").Items
                .Where(s => s.GetBool("enabled")).Select(s => s.GetString("path")).ToList();
            Assert.That(build, Is.SupersetOf(scenes), "scenes missing from ProjectSettings/EditorBuildSettings.asset");
        }
    }
}
