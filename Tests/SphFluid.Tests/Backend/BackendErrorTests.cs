using System.IO;
using NUnit.Framework;
using SphFluid.Compute;

namespace SphFluid.Tests.Backend
{
    /// <summary>Mistakes are reported with the name of what is wrong and where.</summary>
    public sealed class BackendErrorTests
    {
        string _dir;

        [SetUp]
        public void CreateScratchFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "sphfluid-backend-" + TestContext.CurrentContext.Test.ID);
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void Clean() => Directory.Delete(_dir, true);

        [Test]
        public void HlslSyntaxErrorReportsFileAndLine()
        {
            // Written at test time so no broken shader sits in a folder other tools scan.
            string path = Path.Combine(_dir, "Broken.compute");
            File.WriteAllText(path,
                "#pragma kernel Main\n" +
                "RWStructuredBuffer<float> _Out;\n" +
                "[numthreads(1, 1, 1)]\n" +
                "void Main(uint3 id : SV_DispatchThreadID)\n" +
                "{\n" +
                "    _Out[0] = undeclaredThing;\n" +
                "}\n");
            var error = Assert.Throws<ComputeException>(() => GpuTestDevice.Shared.LoadProgram(path));
            Assert.That(error.Message, Does.Contain(path + ":6:").And.Contain("undeclaredThing"));
        }

        [Test]
        public void ErrorInAnIncludedFileNamesThatFile()
        {
            Directory.CreateDirectory(Path.Combine(_dir, "Include"));
            string include = Path.Combine(_dir, "Include", "BrokenMaths.hlsl");
            File.WriteAllText(include, "float Twice(float x)\n{\n    return 2.0f * x\n}\n");
            string path = Path.Combine(_dir, "UsesBrokenMaths.compute");
            File.WriteAllText(path,
                "#pragma kernel Main\n#include \"Include/BrokenMaths.hlsl\"\nRWStructuredBuffer<float> _Out;\n" +
                "[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID) { _Out[0] = Twice(1.0f); }\n");
            var error = Assert.Throws<ComputeException>(() => GpuTestDevice.Shared.LoadProgram(path));
            Assert.That(error.Message, Does.Contain("BrokenMaths.hlsl:4:"));
        }

        [Test]
        public void MissingProgramIsNamed()
        {
            Assert.That(() => GpuTestDevice.Shared.LoadProgram("NoSuchProgramAnywhere"),
                Throws.TypeOf<ComputeException>().With.Message.Contains("NoSuchProgramAnywhere"));
        }

        [Test]
        public void UnknownKernelIsNamed()
        {
            var program = GpuTestDevice.Shared.LoadProgram("BackendSmoke");
            Assert.That(program.HasKernel("NoSuchKernel"), Is.False);
            Assert.That(() => program.FindKernel("NoSuchKernel"),
                Throws.TypeOf<ComputeException>().With.Message.Contains("NoSuchKernel"));
        }

        [Test]
        public void PragmaKernelWithoutAFunctionIsReported()
        {
            string path = Path.Combine(_dir, "MissingEntry.compute");
            File.WriteAllText(path,
                "#pragma kernel Main\n#pragma kernel Forgotten\nRWStructuredBuffer<float> _Out;\n" +
                "[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID) { _Out[0] = 1.0f; }\n");
            Assert.That(() => GpuTestDevice.Shared.LoadProgram(path),
                Throws.TypeOf<ComputeException>().With.Message.Contains("Forgotten"));
        }
    }
}
