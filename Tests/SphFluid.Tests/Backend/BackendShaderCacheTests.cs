using System.IO;
using NUnit.Framework;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>Compiled variants are cached on disk by content, so a rerun never recompiles.</summary>
    public sealed class BackendShaderCacheTests
    {
        string _dir;

        [SetUp]
        public void CreateScratchFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "sphfluid-cache-" + TestContext.CurrentContext.Test.ID);
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void Clean() => Directory.Delete(_dir, true);

        [Test]
        public void SecondLoadOfAProgramDoesNotRunGlslang()
        {
            var device = GpuTestDevice.Shared;
            device.LoadProgram("BackendSmoke");
            int before = device.Compiler.CompileCount;
            device.LoadProgram("BackendSmoke");
            Assert.That(device.Compiler.CompileCount, Is.EqualTo(before));
        }

        [Test]
        public void AFreshCompilerReadsTheDiskCacheAndAnIncludeChangeRecompiles()
        {
            string shaders = Path.Combine(_dir, "Shaders");
            Directory.CreateDirectory(Path.Combine(shaders, "Include"));
            string include = Path.Combine(shaders, "Include", "Value.hlsl");
            File.WriteAllText(include, "static const float Value = 1.0f;\n");
            string path = Path.Combine(shaders, "Cached.compute");
            File.WriteAllText(path,
                "#pragma kernel Main\n#include \"Include/Value.hlsl\"\nRWStructuredBuffer<float> _Out;\n" +
                "[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID) { _Out[0] = Value; }\n");
            string cache = Path.Combine(_dir, "Cache");
            var dirs = new[] { shaders };

            var first = new ShaderCompiler(cache);
            var words = first.Compile(ComputeSource.Load(path, dirs), "Main", new string[0], dirs);
            Assert.That(first.CompileCount, Is.EqualTo(1));

            var second = new ShaderCompiler(cache);
            var again = second.Compile(ComputeSource.Load(path, dirs), "Main", new string[0], dirs);
            Assert.That(second.CompileCount, Is.EqualTo(0), "a rerun reads the cache");
            Assert.That(again, Is.EqualTo(words));

            second.Compile(ComputeSource.Load(path, dirs), "Main", new[] { "SOME_KEYWORD" }, dirs);
            Assert.That(second.CompileCount, Is.EqualTo(1), "another variant is another entry");

            File.WriteAllText(include, "static const float Value = 2.0f;\n");
            second.Compile(ComputeSource.Load(path, dirs), "Main", new string[0], dirs);
            Assert.That(second.CompileCount, Is.EqualTo(2), "an edited include invalidates the entry");
        }

        /// <summary>A cache folder that cannot be written costs every run its compiles, so it is named; the probe leaves
        /// nothing behind.</summary>
        [Test]
        public void ACacheThatCannotBeWrittenIsNamed_AWritableOneKeepsNoProbe()
        {
            string file = Path.Combine(_dir, "a-file");
            File.WriteAllText(file, "not a folder");
            Assert.That(new ShaderCompiler(file).CacheProblem(), Does.Contain(file));
            Assert.That(new ShaderCompiler(Path.Combine(file, "below")).CacheProblem(), Is.Not.Null);

            string writable = Path.Combine(_dir, "writable");
            Assert.That(new ShaderCompiler(writable).CacheProblem(), Is.Null);
            Assert.That(Directory.GetFileSystemEntries(writable), Is.Empty);
        }

        /// <summary>A blank SPHFLUID_SHADER_CACHE or XDG_CACHE_HOME is unset, not a folder named by its blanks in the
        /// working folder; a relative XDG_CACHE_HOME is passed over (the XDG specification); a relative
        /// SPHFLUID_SHADER_CACHE is the user's own choice and kept.</summary>
        [TestCase(null, null, "/home/u/.cache/sphfluid-spirv")]
        [TestCase(" ", "\t", "/home/u/.cache/sphfluid-spirv")]
        [TestCase("", "/x/cache", "/x/cache/sphfluid-spirv")]
        [TestCase("  ", "relative/cache", "/home/u/.cache/sphfluid-spirv")]
        [TestCase("spirv", "/x/cache", "spirv")]
        [TestCase("/c/spirv", null, "/c/spirv")]
        public void TheCacheFolderComesFromTheFirstVariableThatNamesOne(string? shaderCache, string? xdgCacheHome, string expected)
        {
            Assert.That(ShaderCompiler.CacheDirectoryFrom(shaderCache, xdgCacheHome, "/home/u"), Is.EqualTo(expected));
        }

        /// <summary>A run that opens its device says so on its error stream, before it pays for the compiles.</summary>
        [Test]
        public void ARunWhoseCacheCannotBeWrittenIsWarned()
        {
            _ = GpuTestDevice.Shared; // ignored where no Vulkan driver exists
            string file = Path.Combine(_dir, "a-file");
            File.WriteAllText(file, "not a folder");
            string? before = System.Environment.GetEnvironmentVariable("SPHFLUID_SHADER_CACHE");
            var warnings = new StringWriter();
            try
            {
                System.Environment.SetEnvironmentVariable("SPHFLUID_SHADER_CACHE", file);
                DeviceFactory.GivenOrOpen(null, Path.Combine(GpuTestDevice.RepoRoot, "Packages", FluidPackage.Name), null, "simulate", warnings, out var owned);
                owned?.Dispose();
            }
            finally
            {
                System.Environment.SetEnvironmentVariable("SPHFLUID_SHADER_CACHE", before);
            }
            Assert.That(warnings.ToString(), Does.StartWith($"simulate: warning: the shader cache '{file}' cannot be written (")
                .And.Contain("set SPHFLUID_SHADER_CACHE to a folder it can write"));
        }
    }
}
