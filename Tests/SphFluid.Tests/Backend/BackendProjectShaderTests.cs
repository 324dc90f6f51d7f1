using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>
    /// The project's own kernels, every variant: they compile to valid SPIR-V, every structured buffer's
    /// element stride (packed as D3D packs it) equals the C# struct that fills it (or, for plain HLSL types,
    /// the D3D size Unity uses), and, because their structs are built from whole 16-byte groups, the
    /// packing is also std430's, so they run on a device without scalar block layout.
    /// </summary>
    public sealed class BackendProjectShaderTests
    {
        [Test]
        public void EveryProjectKernelVariantCompilesWithStridesThatMatchItsCSharpStruct()
        {
            var device = GpuTestDevice.Shared;
            string shaders = Path.Combine(GpuTestDevice.RepoRoot, "Packages", "com.sphfluid.fluid", "Shaders");
            var files = Directory.GetFiles(shaders, "*.compute").OrderBy(f => f, StringComparer.Ordinal).ToList();
            Assume.That(files, Is.Not.Empty, "no project .compute files yet");
            var csharpStructs = typeof(ComputeException).Assembly.GetTypes()
                .Where(t => t.IsValueType && !t.IsEnum && !t.IsPrimitive)
                .GroupBy(t => t.Name).ToDictionary(g => g.Key, g => g.First());

            var problems = new List<string>();
            int checkedBuffers = 0;
            foreach (string file in files)
            {
                var program = (VulkanProgram)device.LoadProgram(Path.GetFileNameWithoutExtension(file));
                program.CompileAllVariants();
                foreach (var combo in program.KeywordCombinations())
                {
                    foreach (string keyword in program.Keywords) device.SetKeyword(program, keyword, combo.Contains(keyword));
                    for (int k = 0; k < program.KernelNames.Count; k++)
                    {
                        foreach (var buffer in program.Reflect(k).Resources.Where(r => r.Kind == SpirvResourceKind.StorageBuffer))
                        {
                            checkedBuffers++;
                            string where = Path.GetFileName(file) + " " + program.KernelNames[k] + " [" + string.Join(" ", combo) + "] " + buffer.Name;
                            string? problem = StrideProblem(buffer, csharpStructs);
                            if (problem != null && !problems.Any(p => p.EndsWith(buffer.Name + ": " + problem, StringComparison.Ordinal)))
                                problems.Add(where + ": " + problem);
                        }
                    }
                }
            }
            Assert.That(checkedBuffers, Is.GreaterThan(0));
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
        }

        [Test]
        public void EveryProjectKernelVariantNeedsNoScalarBlockLayout()
        {
            var device = GpuTestDevice.Shared;
            string shaders = Path.Combine(GpuTestDevice.RepoRoot, "Packages", "com.sphfluid.fluid", "Shaders");
            var dirs = new[] { shaders };
            var notStd430 = new List<string>();
            int variants = 0;
            foreach (string file in Directory.GetFiles(shaders, "*.compute").OrderBy(f => f, StringComparer.Ordinal))
            {
                var program = (VulkanProgram)device.LoadProgram(Path.GetFileNameWithoutExtension(file));
                var source = ComputeSource.Load(file, dirs);
                foreach (var combo in program.KeywordCombinations())
                {
                    var keywords = source.VariantKeywords(combo.ToList());
                    foreach (var kernel in source.Kernels)
                    {
                        variants++;
                        var words = device.Compiler.Compile(source, kernel.Name, kernel.Defines.Concat(keywords).ToList(), dirs);
                        if (!StructuredBufferPacking.FollowsStd430(words))
                            notStd430.Add(Path.GetFileName(file) + " " + kernel.Name + " [" + string.Join(" ", combo) + "]");
                    }
                }
            }
            Assert.That(variants, Is.GreaterThan(0));
            Assert.That(notStd430, Is.Empty, "variants whose buffers need scalar block layout:\n" + string.Join("\n", notStd430));
        }

        [Test]
        public void Float3ElementsAreCaught()
        {
            var float3 = new SpirvResource("_Positions", SpirvResourceKind.StorageBuffer, 0, 0, 16, false, "float3", false);
            Assert.That(StrideProblem(float3, new Dictionary<string, Type>()), Does.Contain("16").And.Contain("12"));
            var float4 = new SpirvResource("_Positions", SpirvResourceKind.StorageBuffer, 0, 0, 16, false, "float4", false);
            Assert.That(StrideProblem(float4, new Dictionary<string, Type>()), Is.Null);
        }

        static string? StrideProblem(SpirvResource buffer, Dictionary<string, Type> csharpStructs)
        {
            if (buffer.ElementIsStruct)
            {
                if (csharpStructs.TryGetValue(buffer.ElementType, out var type))
                {
                    int size = Marshal.SizeOf(type);
                    return size == buffer.ArrayStride ? null
                        : "struct " + buffer.ElementType + " is " + buffer.ArrayStride + " bytes in SPIR-V but C# " + type.FullName + " is " + size;
                }
                return buffer.ArrayStride % 16 == 0 ? null
                    : "struct " + buffer.ElementType + " (no C# struct of that name) is " + buffer.ArrayStride + " bytes, not whole 16-byte groups";
            }
            int d3d = D3DSize(buffer.ElementType);
            return d3d == buffer.ArrayStride ? null
                : buffer.ElementType + " elements are " + buffer.ArrayStride + " bytes in SPIR-V but " + d3d + " in D3D/Unity (the backend must pack structured buffers as D3D does)";
        }

        /// <summary>D3D's structured-buffer size of a plain HLSL type: "uint" 4, "float3" 12, "float4x4" 64.</summary>
        static int D3DSize(string hlslType)
        {
            string digits = new string(hlslType.SkipWhile(char.IsLetter).ToArray());
            int scalar = hlslType.StartsWith("double", StringComparison.Ordinal) ? 8 : hlslType.StartsWith("half", StringComparison.Ordinal) ? 2 : 4;
            if (digits.Length == 0) return scalar;
            return digits.Split('x').Select(int.Parse).Aggregate(scalar, (a, n) => a * n);
        }
    }
}
