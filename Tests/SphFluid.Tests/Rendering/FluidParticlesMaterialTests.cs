using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Tests.Rendering
{
    /// <summary>
    /// FluidParticles.mat uses the particle shader (by the guid in its .meta) and holds a valid value for every
    /// number the shader's Properties block declares - and nothing the shader does not know.
    /// </summary>
    public sealed class FluidParticlesMaterialTests
    {
        const string MaterialRelativePath = "Packages/com.sphfluid.fluid/Materials/FluidParticles.mat";
        const string ShaderRelativePath = "Packages/com.sphfluid.fluid/Shaders/FluidParticles.shader";

        static string At(string relative) => Path.Combine(GpuTestDevice.RepoRoot, relative);

        static UnityYamlNode Material()
        {
            var file = UnityYamlFile.Load(At(MaterialRelativePath));
            var material = file.Documents.Single();
            Assert.That(material.ClassId, Is.EqualTo(21));
            Assert.That(material.FileId, Is.EqualTo(2100000L));
            return material.Root;
        }

        /// <summary>The entries of one m_SavedProperties list ("m_Floats", "m_Colors", ...) by property name.</summary>
        static Dictionary<string, UnityYamlNode> Saved(UnityYamlNode material, string list)
        {
            var result = new Dictionary<string, UnityYamlNode>();
            var node = material.At("m_SavedProperties." + list);
            if (node == null) return result;
            foreach (var item in node.Items)
                foreach (var entry in item.Entries)
                    result[entry.Key] = entry.Value;
            return result;
        }

        [Test]
        public void Material_references_the_particle_shader_by_its_meta_guid()
        {
            var material = Material();
            var shader = material.GetReference("m_Shader");
            Assert.That(shader, Is.Not.Null);
            Assert.That(shader.Guid, Is.EqualTo(UnityMeta.GuidOf(At(ShaderRelativePath))));
            Assert.That(shader.FileId, Is.EqualTo(4800000L));
            Assert.That(shader.Type, Is.EqualTo(3));
            Assert.That(material.GetString("m_Name"), Is.EqualTo("FluidParticles"));
            Assert.That(UnityMeta.Load(At(MaterialRelativePath + ".meta")).MainObjectFileId, Is.EqualTo(2100000L));
        }

        [Test]
        public void The_package_resources_give_every_fluid_the_material_and_both_pipelines_shaders()
        {
            const string resources = "Packages/com.sphfluid.fluid/Runtime/Resources/SphFluidResources.asset";
            const string universalShader = "Packages/com.sphfluid.fluid/Shaders/FluidParticlesUniversal.shader";
            var root = UnityYamlFile.Load(At(resources)).Documents.Single().Root;
            Assert.That(root.GetReference("m_Script").OrFail("m_Script").Guid, Is.EqualTo(UnityMeta.GuidOf(At("Packages/com.sphfluid.fluid/Runtime/FluidResources.cs"))));
            Assert.That(root.GetReference("particleMaterial").OrFail("particleMaterial").Guid, Is.EqualTo(UnityMeta.GuidOf(At(MaterialRelativePath))), "particleMaterial");
            var universal = root.GetReference("universalParticleShader").OrFail("universalParticleShader");
            Assert.That(universal.Guid, Is.EqualTo(UnityMeta.GuidOf(At(universalShader))), "universalParticleShader: the particles would not draw in URP");
            Assert.That(universal.FileId, Is.EqualTo(4800000L));
            foreach (string scene in Directory.GetFiles(At("Assets/FluidDemo/Scenes"), "*.unity"))
                Assert.That(File.ReadAllText(scene), Does.Not.Contain("particleMaterial:"), scene + ": a Fluid has no per-component material slot");
        }

        [Test]
        public void Every_numeric_property_has_a_material_value_inside_its_range()
        {
            var material = Material();
            var floats = Saved(material, "m_Floats");
            var ints = Saved(material, "m_Ints");
            var colors = Saved(material, "m_Colors");
            var problems = new List<string>();
            foreach (var property in ShaderLabSource.Load(At(ShaderRelativePath)).Properties)
            {
                if (property.IsNumber)
                {
                    // Unity stores Float/Range/Int in m_Floats and only Integer in m_Ints.
                    var list = property.Type == "Integer" ? ints : floats;
                    if (!list.TryGetValue(property.Name, out var value)) { problems.Add(property.Name + ": no material entry"); continue; }
                    if (value.Value == null) { problems.Add(property.Name + ": the material entry is not a number"); continue; }
                    float v = float.Parse(value.Value, CultureInfo.InvariantCulture);
                    if (property.RangeMin is float min && property.RangeMax is float max && (v < min || v > max))
                        problems.Add(property.Name + " = " + v + " outside its Range(" + property.RangeMin + ", " + property.RangeMax + ")");
                }
                else if (property.IsVector && !colors.ContainsKey(property.Name))
                {
                    problems.Add(property.Name + ": no m_Colors entry");
                }
                // Textures may be absent: Unity binds the declared default ("white", "black", ...).
            }
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
        }

        [Test]
        public void Material_holds_no_value_the_shader_does_not_declare()
        {
            var material = Material();
            var declared = new HashSet<string>(ShaderLabSource.Load(At(ShaderRelativePath)).Properties.Select(p => p.Name));
            var stale = new[] { "m_Floats", "m_Ints", "m_Colors", "m_TexEnvs" }
                .SelectMany(list => Saved(material, list).Keys.Select(k => list + "." + k + (declared.Contains(k) ? "" : " (unknown)")))
                .Where(k => k.EndsWith("(unknown)"))
                .ToList();
            Assert.That(stale, Is.Empty, "material entries for properties the shader does not declare (a typo?)");
        }
    }
}
