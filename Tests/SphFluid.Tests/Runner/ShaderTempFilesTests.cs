using System;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Runner
{
    /// <summary>A run leaves nothing behind in the temp folder: each kernel compile used to create an empty
    /// sphfluid-spirv-&lt;pid&gt; folder there and never removed it.</summary>
    public sealed class ShaderTempFilesTests
    {
        [Test]
        public void CompilingAKernelLeavesNoFolderOrFileInTheTempFolder()
        {
            string scratch = RunnerPaths.ScratchFolder("temp-files");
            string path = Path.Combine(scratch, "Leftover.compute");
            File.WriteAllText(path, "#pragma kernel Main\nRWStructuredBuffer<float> _Out;\n[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID) { _Out[0] = 3.0f; }\n");
            var dirs = new[] { scratch };
            var compiler = new ShaderCompiler(Path.Combine(scratch, "Cache"));
            string temp = Path.GetTempPath();
            string[] before = Directory.GetFileSystemEntries(temp, "sphfluid-spirv-*");

            uint[] words;
            try { words = compiler.Compile(ComputeSource.Load(path, dirs), "Main", Array.Empty<string>(), dirs); }
            catch (ComputeException e) when (e.Message.Contains("was not found on PATH")) { Assert.Ignore(e.Message); return; }

            Assert.That(compiler.CompileCount, Is.EqualTo(1), "a fresh cache compiles");
            Assert.That(words.Length, Is.GreaterThan(5), "SPIR-V came back");
            Assert.That(Directory.GetFileSystemEntries(temp, "sphfluid-spirv-*").Except(before), Is.Empty, "the compile output is deleted");
            // The old per-process folder, once made by any compile of this test process, stayed until the machine was cleaned.
            Assert.That(Directory.Exists(Path.Combine(temp, "sphfluid-spirv-" + Environment.ProcessId)), Is.False);
        }
    }
}
