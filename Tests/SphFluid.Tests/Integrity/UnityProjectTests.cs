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
    }
}
