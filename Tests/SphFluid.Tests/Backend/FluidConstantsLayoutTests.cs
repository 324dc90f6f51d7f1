using System;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>
    /// The C# <see cref="FluidConstants"/> is uploaded byte for byte into <c>cbuffer FluidConstants</c>
    /// (Shaders/Include/FluidConstants.hlsl): every field must sit where the compiled kernels read its namesake, with
    /// its size, and nothing may be declared on one side only. The offsets come from the SPIR-V of both programs that
    /// bind the buffer, compiled with every keyword on.
    /// </summary>
    public sealed class FluidConstantsLayoutTests
    {
        static readonly FieldInfo[] Fields = typeof(FluidConstants).GetFields(BindingFlags.Public | BindingFlags.Instance);

        static SpirvUniformBlock BlockOf(string program, string kernel, params string[] keywords)
        {
            string shaders = Path.Combine(GpuTestDevice.RepoRoot, "Packages", "com.sphfluid.fluid", "Shaders");
            var dirs = new[] { shaders };
            var source = ComputeSource.Load(Path.Combine(shaders, program + ".compute"), dirs);
            uint[] words;
            try { words = new ShaderCompiler().Compile(source, kernel, keywords, dirs); }
            catch (Compute.ComputeException e) when (e.Message.Contains("was not found on PATH")) { Assert.Ignore(e.Message); return null; }
            var block = SpirvReflection.Read(words).UniformBlocks.FirstOrDefault(b => b.Resource.Name == "FluidConstants");
            Assert.That(block, Is.Not.Null, $"{program}.compute kernel {kernel} reads no cbuffer FluidConstants");
            return block;
        }

        static object[] Programs() => new object[]
        {
            new object[] { "FluidSolver", "Forces", new[] { "MULTIPHASE", "SURFACE_TENSION", "XSPH", "OBSTACLES" } },
            new object[] { "FluidSolver", "BoundarySolveError", new string[0] },
            new object[] { "FluidDiagnostics", "DiagnosticsPartial", new string[0] },
        };

        [TestCaseSource(nameof(Programs))]
        public void EveryFieldSitsWhereTheKernelReadsIt(string program, string kernel, string[] keywords)
        {
            var block = BlockOf(program, kernel, keywords);
            foreach (var field in Fields)
            {
                string name = "_" + field.Name;
                if (!block.Members.TryGetValue(name, out var member)) continue; // a kernel may not read every value
                Assert.That((int)Marshal.OffsetOf<FluidConstants>(field.Name), Is.EqualTo(member.Offset), $"offset of {name}");
                Assert.That(Marshal.SizeOf(field.FieldType), Is.EqualTo(member.Size), $"size of {name}");
            }
        }

        [TestCaseSource(nameof(Programs))]
        public void TheKernelReadsNothingTheStructLacks(string program, string kernel, string[] keywords)
        {
            var block = BlockOf(program, kernel, keywords);
            var declared = Fields.Select(f => "_" + f.Name).ToArray();
            Assert.That(block.Members.Keys, Is.SubsetOf(declared));
            Assert.That(block.Size, Is.LessThanOrEqualTo(FluidConstants.Bytes));
        }

        [Test]
        public void TheStructIsTheWholeCbufferAndEveryFieldIsDeclaredInIt()
        {
            var block = BlockOf("FluidSolver", "Forces", "MULTIPHASE", "SURFACE_TENSION", "XSPH", "OBSTACLES");
            // glslang keeps every member of a cbuffer a kernel uses, so the reflection of one kernel lists the whole block.
            Assert.That(block.Members.Keys, Is.EquivalentTo(Fields.Select(f => "_" + f.Name)));
            Assert.That(Marshal.SizeOf<FluidConstants>(), Is.EqualTo(FluidConstants.Bytes));
            Assert.That(block.Size, Is.EqualTo(FluidConstants.Bytes), "the cbuffer rounded up to whole 16-byte rows");
        }
    }
}
