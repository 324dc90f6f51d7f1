using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Rendering
{
    /// <summary>
    /// Both particle shaders' HLSL (Built-in and URP) compiles (vertex and fragment stage, both depth
    /// conventions) with glslang against the smallest stand-in for Unity's built-ins, so a syntax or type error
    /// is caught in CI instead of in the editor; and each keeps the contract the Unity side draws it with.
    /// </summary>
    public sealed class FluidParticlesShaderTests
    {
        const string BuiltInShader = "Packages/com.sphfluid.fluid/Shaders/FluidParticles.shader";
        const string UniversalShader = "Packages/com.sphfluid.fluid/Shaders/FluidParticlesUniversal.shader";
        /// <summary>The shader the single-shader tests (the deliberately broken program) take.</summary>
        const string ShaderRelativePath = BuiltInShader;

        /// <summary>Every pipeline's particle shader: the tests that take one run for each.</summary>
        static readonly string[] ParticleShaders = { BuiltInShader, UniversalShader };

        /// <summary>Stand-in platforms: D3D11/Vulkan/Metal-like (reversed Z) and OpenGL Core-like.</summary>
        static readonly string[][] Platforms = { new string[0], new[] { "SPHFLUID_STANDIN_OPENGL=1" } };

        /// <summary>Uniforms the render pipeline sets each frame, never a material: they need no Properties entry.</summary>
        static readonly string[] PipelineUniforms = { "_FluidBackground", "_CameraOpaqueTexture", "_MainLightPosition", "_MainLightColor" };

        static string ShaderPath => Path.Combine(GpuTestDevice.RepoRoot, ShaderRelativePath);

        static ShaderLabSource Shader(string relativePath) => ShaderLabSource.Load(Path.Combine(GpuTestDevice.RepoRoot, relativePath));

        /// <summary>The program as the compiler reads it, the project's includes inlined (not Unity's).</summary>
        static string Expanded(ShaderLabProgram program) => program.WithLocalIncludes(GlslangShaderCheck.ShaderDir);

        [TestCaseSource(nameof(ParticleShaders))]
        public void Every_program_compiles_for_vertex_and_fragment_stage_on_both_depth_conventions(string relativePath)
        {
            GlslangShaderCheck.RequireTool("glslangValidator");
            GlslangShaderCheck.RequireTool("spirv-val");
            var shader = Shader(relativePath);
            Assert.That(shader.Programs, Is.Not.Empty, relativePath + " has no HLSLPROGRAM block");

            string work = GlslangShaderCheck.NewWorkDir();
            try
            {
                var failures = new List<string>();
                int compiled = 0;
                for (int p = 0; p < shader.Programs.Count; p++)
                {
                    var program = shader.Programs[p];
                    string hlsl = Path.Combine(work, Path.GetFileNameWithoutExtension(relativePath) + ".program" + p + ".hlsl");
                    File.WriteAllText(hlsl, program.WithLineDirective(relativePath));
                    foreach (var defines in Platforms)
                    {
                        foreach (var (stage, entry) in new[] { ("vert", program.VertexEntry), ("frag", program.FragmentEntry) })
                        {
                            if (entry == null)
                            {
                                failures.Add(relativePath + ":" + program.FirstLine + ": program has no #pragma " + (stage == "vert" ? "vertex" : "fragment"));
                                continue;
                            }
                            var result = GlslangShaderCheck.CompileStage(hlsl, stage, entry, defines, work);
                            if (result.Succeeded) compiled++;
                            else failures.Add("[" + (defines.Length == 0 ? "reversed-Z platform" : string.Join(" ", defines)) + "] " + result.Messages);
                        }
                    }
                }
                Assert.That(failures, Is.Empty, string.Join("\n\n", failures));
                Assert.That(compiled, Is.EqualTo(shader.Programs.Count * 2 * Platforms.Length));
            }
            finally
            {
                GlslangShaderCheck.DeleteWorkDir(work);
            }
        }

        [Test]
        public void A_broken_program_fails_with_the_shader_file_and_line()
        {
            GlslangShaderCheck.RequireTool("glslangValidator");
            GlslangShaderCheck.RequireTool("spirv-val");
            string text = File.ReadAllText(ShaderPath);
            var original = ShaderLabSource.Parse(text, ShaderPath).Programs[0];
            string[] programLines = original.Source.Split('\n');
            // The fragment stage calls the shader's own BackgroundBehind: break that, a line of the .shader itself.
            int functionLine = Array.FindIndex(programLines, l => Regex.IsMatch(l, "\\bBackgroundBehind\\s*\\("));
            Assume.That(functionLine, Is.GreaterThanOrEqualTo(0), "no BackgroundBehind( line to break");
            int braceLine = Array.FindIndex(programLines, functionLine, l => l.Trim() == "{");
            programLines[braceLine + 1] = "float brokenOnPurpose = notDeclaredAnywhere;" + programLines[braceLine + 1];
            var broken = new ShaderLabProgram(string.Join("\n", programLines), original.FirstLine)
            {
                VertexEntry = original.VertexEntry,
                FragmentEntry = original.FragmentEntry,
            };
            int expectedLine = original.FirstLine + braceLine + 1;

            string work = GlslangShaderCheck.NewWorkDir();
            try
            {
                string hlsl = Path.Combine(work, "Broken.hlsl");
                File.WriteAllText(hlsl, broken.WithLineDirective(ShaderRelativePath));
                var result = GlslangShaderCheck.CompileStage(hlsl, "frag", broken.FragmentEntry.OrFail("#pragma fragment"), new string[0], work);
                Assert.That(result.Succeeded, Is.False);
                Assert.That(result.Messages, Does.Contain(ShaderRelativePath + ":" + expectedLine + ":"));
                Assert.That(result.Messages, Does.Contain("notDeclaredAnywhere"));
            }
            finally
            {
                GlslangShaderCheck.DeleteWorkDir(work);
            }
        }

        [TestCaseSource(nameof(ParticleShaders))]
        public void No_implicit_vector_truncation_that_FXC_would_warn_about(string relativePath)
        {
            GlslangShaderCheck.RequireTool("glslangValidator");
            var program = Shader(relativePath).Programs[0];
            string work = GlslangShaderCheck.NewWorkDir();
            try
            {
                string hlsl = Path.Combine(work, "FluidParticles.hlsl");
                File.WriteAllText(hlsl, program.WithLineDirective(relativePath));
                var problems = new List<string>();
                foreach (var defines in Platforms)
                {
                    foreach (var (stage, entry) in new[] { ("vert", program.VertexEntry.OrFail("#pragma vertex")), ("frag", program.FragmentEntry.OrFail("#pragma fragment")) })
                    {
                        string tree = GlslangShaderCheck.IntermediateTree(hlsl, stage, entry, defines, work);
                        problems.AddRange(ImplicitTruncationLint.Find(tree).Select(p => stage + " " + p));
                    }
                }
                Assert.That(problems.Distinct().ToList(), Is.Empty, "lines of " + relativePath + " or its includes");
            }
            finally
            {
                GlslangShaderCheck.DeleteWorkDir(work);
            }
        }

        [Test]
        public void Truncation_lint_finds_a_float4_assigned_to_a_float3_and_passes_explicit_swizzles()
        {
            GlslangShaderCheck.RequireTool("glslangValidator");
            string work = GlslangShaderCheck.NewWorkDir();
            try
            {
                string hlsl = Path.Combine(work, "Truncation.hlsl");
                File.WriteAllText(hlsl, "float4 _A;\nfloat4 frag() : SV_Target\n{\n    float3 good = _A.xyz;\n    float3 bad = _A;\n    float alsoBad = _A.xy;\n    return float4(good + bad, alsoBad);\n}\n");
                var problems = ImplicitTruncationLint.Find(GlslangShaderCheck.IntermediateTree(hlsl, "frag", "frag", new string[0], work));
                Assert.That(problems.Count, Is.EqualTo(2), string.Join("\n", problems));
                Assert.That(problems[0], Does.StartWith("line 5: 4-component"));
                Assert.That(problems[1], Does.StartWith("line 6: 2-component"));
            }
            finally
            {
                GlslangShaderCheck.DeleteWorkDir(work);
            }
        }

        [TestCaseSource(nameof(ParticleShaders))]
        public void Vertex_stage_reads_the_particle_and_phase_buffers_with_the_CSharp_strides(string relativePath)
        {
            GlslangShaderCheck.RequireTool("glslangValidator");
            GlslangShaderCheck.RequireTool("spirv-val");
            var program = Shader(relativePath).Programs[0];
            string work = GlslangShaderCheck.NewWorkDir();
            try
            {
                string hlsl = Path.Combine(work, "FluidParticles.hlsl");
                File.WriteAllText(hlsl, program.WithLineDirective(relativePath));
                var result = GlslangShaderCheck.CompileStage(hlsl, "vert", program.VertexEntry.OrFail("#pragma vertex"), new string[0], work);
                Assert.That(result.SpirvPath, Is.Not.Null, result.Messages);

                byte[] bytes = File.ReadAllBytes(result.SpirvPath);
                var reflection = SpirvReflection.Read(MemoryMarshal.Cast<byte, uint>(bytes));
                var buffers = reflection.Resources.Where(r => r.Kind == SpirvResourceKind.StorageBuffer).ToDictionary(r => r.Name, r => r);
                Assert.That(buffers.Keys, Is.EquivalentTo(new[] { "_Particles", "_Phases" }));
                Assert.That(buffers["_Particles"].ArrayStride, Is.EqualTo(Marshal.SizeOf<Particle>()));
                Assert.That(buffers["_Phases"].ArrayStride, Is.EqualTo(Marshal.SizeOf<PhaseProperties>()));
                Assert.That(buffers["_Particles"].ReadOnly && buffers["_Phases"].ReadOnly, Is.True, "the draw must only read the solver's buffers");
            }
            finally
            {
                GlslangShaderCheck.DeleteWorkDir(work);
            }
        }

        [TestCaseSource(nameof(ParticleShaders))]
        public void Shader_keeps_the_contract_the_Unity_side_draws_it_with(string relativePath)
        {
            var shader = Shader(relativePath);
            Assert.That(shader.Programs.Count, Is.EqualTo(1));
            var program = shader.Programs[0];
            string source = Expanded(program);
            Assert.That(program.VertexEntry, Is.EqualTo("vert"));
            Assert.That(program.FragmentEntry, Is.EqualTo("frag"));
            Assert.That(program.Target, Is.EqualTo("4.5"), "StructuredBuffer in the vertex stage needs #pragma target 4.5");
            Assert.That(program.Source, Does.Contain("#include \"UnityCG.cginc\""));
            Assert.That(program.Source, Does.Contain("#include \"Include/FluidParticlesPass.hlsl\""), "the pass is shared by every pipeline's shader");
            Assert.That(source, Does.Match("StructuredBuffer<Particle>\\s+_Particles\\s*;"));
            Assert.That(source, Does.Match("StructuredBuffer<PhaseProperties>\\s+_Phases\\s*;"));
            Assert.That(source, Does.Match("vert\\s*\\(\\s*uint\\s+\\w+\\s*:\\s*SV_VertexID\\s*,\\s*uint\\s+\\w+\\s*:\\s*SV_InstanceID\\s*\\)"));
            Assert.That(source, Does.Contain("SV_Depth"));
            Assert.That(shader.Text, Does.Match("\"Queue\"\\s*=\\s*\"Transparent\""));
        }

        [Test]
        public void Built_in_shader_refracts_its_GrabPass_and_serves_only_the_Built_in_pipeline()
        {
            var shader = Shader(BuiltInShader);
            Assert.That(shader.Name, Is.EqualTo("SphFluid/Particles"));
            Assert.That(shader.Text, Does.Match("GrabPass\\s*\\{\\s*\"_FluidBackground\"\\s*\\}"));
            Assert.That(shader.Programs[0].Source, Does.Match("Texture2D\\s+_FluidBackground\\s*;"));
            Assert.That(shader.Text, Does.Match("\"LightMode\"\\s*=\\s*\"ForwardBase\""));
            // A RenderPipeline tag would hide the SubShader from the Built-in pipeline.
            Assert.That(shader.Text, Does.Not.Contain("\"RenderPipeline\""));
        }

        [Test]
        public void Universal_shader_refracts_the_opaque_texture_and_needs_no_URP_package()
        {
            var shader = Shader(UniversalShader);
            string text = shader.Text;
            Assert.That(shader.Name, Is.EqualTo("SphFluid/ParticlesUniversal"));
            Assert.That(text, Does.Match("\"RenderPipeline\"\\s*=\\s*\"UniversalPipeline\""));
            Assert.That(text, Does.Match("\"LightMode\"\\s*=\\s*\"UniversalForward\""), "a pass URP's forward renderer draws");
            Assert.That(text, Does.Not.Match("GrabPass\\s*\\{"), "URP ignores GrabPass");
            Assert.That(shader.Programs[0].Source, Does.Match("Texture2D\\s+_CameraOpaqueTexture\\s*;"));
            Assert.That(shader.Programs[0].Source, Does.Match("SamplerState\\s+sampler_CameraOpaqueTexture\\s*;"));
            Assert.That(Expanded(shader.Programs[0]), Does.Not.Contain("Packages/"),
                "an include from a package would break the shader's import in a Built-in project without URP");
            Assert.That(text, Does.Contain("Opaque Texture"), "the shader says what the URP asset must enable");
        }

        [Test]
        public void Both_shaders_declare_the_same_properties_so_one_material_serves_either()
        {
            string Describe(ShaderLabProperty p) => p.Name + " " + p.Type + " [" + p.RangeMin + ", " + p.RangeMax + "] = " + p.Default;
            var builtIn = Shader(BuiltInShader).Properties.Select(Describe).ToList();
            var universal = Shader(UniversalShader).Properties.Select(Describe).ToList();
            Assert.That(builtIn, Is.Not.Empty);
            Assert.That(universal, Is.EqualTo(builtIn));
        }

        [TestCaseSource(nameof(ParticleShaders))]
        public void Every_material_parameter_the_HLSL_reads_is_a_declared_property_and_back(string relativePath)
        {
            var shader = Shader(relativePath);
            var declared = shader.Properties.Select(p => p.Name).ToList();
            Assert.That(declared, Is.Unique);

            // Top-level uniforms of the program that are not Unity built-ins: they must be Properties, or a
            // material could not hold their value and they would read 0 in the player.
            var uniforms = new List<string>();
            foreach (var program in shader.Programs)
            {
                foreach (Match m in Regex.Matches(Expanded(program), "^[ \\t]*(?:float|float2|float3|float4|int|uint|half|half4|Texture2D)\\s+(_[A-Z]\\w*)\\s*;", RegexOptions.Multiline))
                    uniforms.Add(m.Groups[1].Value);
            }
            Assert.That(uniforms.Except(PipelineUniforms).Except(declared).ToList(), Is.Empty, "uniforms without a Properties entry");
            Assert.That(declared.Except(uniforms).ToList(), Is.Empty, "Properties the HLSL never declares (they would do nothing)");
        }

        [TestCaseSource(nameof(ParticleShaders))]
        public void Every_property_default_lies_in_its_range(string relativePath)
        {
            foreach (var property in Shader(relativePath).Properties.Where(p => p.Type == "Range"))
            {
                float value = float.Parse(property.Default, System.Globalization.CultureInfo.InvariantCulture);
                var (min, max) = property.Range;
                Assert.That(value, Is.InRange(min, max), property.Name + " (line " + property.Line + ")");
            }
        }

        [TestCaseSource(nameof(ParticleShaders))]
        public void Optional_DXC_compiles_both_stages_when_installed(string relativePath)
        {
            if (GlslangShaderCheck.FindOnPath("dxc") == null) Assert.Ignore("dxc (DirectX Shader Compiler) is not installed: optional second compiler");
            var program = Shader(relativePath).Programs[0];
            string work = GlslangShaderCheck.NewWorkDir();
            try
            {
                string hlsl = Path.Combine(work, "FluidParticles.hlsl");
                File.WriteAllText(hlsl, program.WithLineDirective(relativePath));
                foreach (var (profile, entry) in new[] { ("vs_6_0", program.VertexEntry.OrFail("#pragma vertex")), ("ps_6_0", program.FragmentEntry.OrFail("#pragma fragment")) })
                {
                    var (exit, output) = GlslangShaderCheck.Run("dxc", new[] { "-T", profile, "-E", entry,
                        "-I", GlslangShaderCheck.StandInIncludeDir, "-I", GlslangShaderCheck.ShaderDir, "-Fo", Path.Combine(work, entry + ".dxil"), hlsl });
                    Assert.That(exit, Is.EqualTo(0), "dxc " + profile + ":\n" + output);
                }
            }
            finally
            {
                GlslangShaderCheck.DeleteWorkDir(work);
            }
        }
    }
}
