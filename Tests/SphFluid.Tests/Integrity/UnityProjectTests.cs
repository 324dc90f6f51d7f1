using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.UnityFiles.Assets;

namespace SphFluid.Tests.Integrity
{
    public sealed class UnityProjectTests
    {
        [Test]
        public void Resolves_guids_scripts_and_scenes_both_ways()
        {
            using (var synthetic = new SyntheticProject())
            {
                var project = new UnityProject(synthetic.Root);
                var shaderGuid = synthetic.GuidOf(SyntheticProject.ShaderPath);
                Assert.That(project.AssetPathOf(shaderGuid), Is.EqualTo(SyntheticProject.ShaderPath));
                Assert.That(project.GuidOf(SyntheticProject.ShaderPath), Is.EqualTo(shaderGuid));
                Assert.That(project.GuidOf(synthetic.Abs(SyntheticProject.ShaderPath)), Is.EqualTo(shaderGuid));
                Assert.That(project.ScriptGuid("FluidEmitter"), Is.EqualTo(synthetic.GuidOf(SyntheticProject.ScriptPath)));
                Assert.That(project.Scenes, Is.EqualTo(new[] { SyntheticProject.ScenePath }));
                Assert.That(project.BuildScenes, Is.EqualTo(new[] { SyntheticProject.ScenePath }));

                var scene = project.LoadScene("Main");
                var emitter = scene.Behaviours(project.ScriptGuid("FluidEmitter")).Single();
                Assert.That(project.AssetPathOf(emitter.Root.GetReference("splash")), Is.EqualTo(SyntheticProject.ShaderPath));
                Assert.That(emitter.Root.GetFloat("rate"), Is.EqualTo(2f));
                Assert.That(scene.GameObjectOf(emitter).OrFail("the emitter's GameObject").Name, Is.EqualTo("Container"));
                Assert.That(scene.FindGameObject("Ball").OrFail("Ball").World.Position.Y, Is.EqualTo(3f));
                Assert.That(() => project.LoadScene("Nowhere"), Throws.TypeOf<FileNotFoundException>().With.Message.Contains("Main"));
            }
        }

        /// <summary>The index read a .meta that was a link to nothing as the whole project's failure: every scene of the
        /// project was refused over one asset's .meta ("file error, the command stopped"), where Unity logs that asset.</summary>
        [Test]
        public void An_unreadable_meta_leaves_its_asset_unresolved_and_the_rest_indexed()
        {
            using (var synthetic = new SyntheticProject())
            {
                synthetic.Write("Assets/Notes.txt", "notes\n");
                try { File.CreateSymbolicLink(synthetic.Abs("Assets/Notes.txt.meta"), "nowhere"); }
                catch (IOException e) { Assert.Ignore("no symbolic links here: " + e.Message); }

                var project = new UnityProject(synthetic.Root);

                Assert.That(project.GuidOf("Assets/Notes.txt"), Is.Null);
                Assert.That(project.AssetPathOf(synthetic.GuidOf(SyntheticProject.ShaderPath)), Is.EqualTo(SyntheticProject.ShaderPath));
                Assert.That(() => project.Meta(synthetic.Abs("Assets/Notes.txt.meta")), Throws.InstanceOf<FileNotFoundException>(),
                    "the scene's integrity check still reads, and reports, the .meta itself");
            }
        }

        /// <summary>A scene's integrity check reads every .meta of the project, as the index does: it takes the index's,
        /// so that each is read once (a project of 30 000 assets read each twice at every run's start).</summary>
        [Test]
        public void The_index_hands_out_the_metas_it_read_and_reads_another_when_asked()
        {
            using (var synthetic = new SyntheticProject())
            {
                string meta = synthetic.Abs(SyntheticProject.ShaderPath + ".meta");
                var project = new UnityProject(synthetic.Root);

                var first = project.Meta(meta);
                Assert.That(project.Meta(meta), Is.SameAs(first));
                Assert.That(first.Guid, Is.EqualTo(synthetic.GuidOf(SyntheticProject.ShaderPath)));
                synthetic.AddAsset("Assets/Later.txt", "later\n", SyntheticProject.DefaultImporter);
                Assert.That(project.Meta(synthetic.Abs("Assets/Later.txt.meta")).Guid, Is.EqualTo(synthetic.GuidOf("Assets/Later.txt")),
                    "a .meta the index did not see is read when asked for");
            }
        }
    }
}
