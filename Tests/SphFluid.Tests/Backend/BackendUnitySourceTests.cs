using System.IO;
using System.Linq;
using System.Numerics;
using System.Text;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>
    /// A .compute file written as Unity accepts it runs unchanged: a byte-order mark, "#pragma kernel K;",
    /// a kernel's own define, uninitialised const globals set from the host, a named cbuffer, and texture
    /// kernels beside buffer kernels (BackendTextureTests runs those); the one that reads a typed buffer fails alone
    /// at its dispatch.
    /// </summary>
    public sealed class BackendUnitySourceTests
    {
        string _dir;

        [SetUp]
        public void CreateScratchFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "sphfluid-unity-source-" + TestContext.CurrentContext.Test.ID);
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void Clean() => Directory.Delete(_dir, true);

        [Test]
        public void TheTestShaderReallyStartsWithAByteOrderMark()
        {
            string path = Path.Combine(GpuTestDevice.RepoRoot, "Tests", "SphFluid.Tests", "Backend", "Shaders", "BackendUnitySource.compute");
            Assert.That(File.ReadAllBytes(path).Take(3).ToArray(), Is.EqualTo(new byte[] { 0xEF, 0xBB, 0xBF }));
        }

        [Test]
        public void KernelNamesStopAtTheSemicolon()
        {
            var program = (VulkanProgram)GpuTestDevice.Shared.LoadProgram("BackendUnitySource");
            Assert.That(program.KernelNames, Is.EqualTo(new[] { "Scale", "ScaleTwice", "FillVolume", "ReadVolume", "FillPlane", "SampleVolume", "ReadTyped" }));
        }

        [Test]
        public void ConstGlobalsAndANamedCbufferAreSetFromTheHost()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnitySource");
            var input = Enumerable.Range(0, 100).Select(i => 0.5f * i - 7f).ToArray();
            var once = Run(device, program, "Scale", input);
            var twice = Run(device, program, "ScaleTwice", input);
            // gain 3, offset (1, 2, 4) weighted 0.5: every value becomes v * 3^n + 3.5.
            for (int i = 0; i < input.Length; i++)
            {
                Assert.That(once[i], Is.EqualTo(input[i] * 3f + 3.5f).Within(1e-4f), "Scale, value " + i);
                Assert.That(twice[i], Is.EqualTo(input[i] * 9f + 3.5f).Within(1e-4f), "ScaleTwice (SCALE_TIMES=2), value " + i);
            }
        }

        [Test]
        public void ATypedBufferKernelFailsAloneAtItsDispatchNamingKernelResourceAndWhy()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendUnitySource");
            var error = Assert.Throws<ComputeException>(() => device.Dispatch(program, program.FindKernel("ReadTyped"), 1, 1, 1));
            Assert.That(error.Message, Does.Contain("ReadTyped").And.Contain("'_Typed' (Buffer)").And.Contain("no typed buffers"));
            var after = Run(device, program, "Scale", new[] { 1f, 2f });
            Assert.That(after, Is.EqualTo(new[] { 6.5f, 9.5f }).Within(1e-5f), "the buffer kernels still run after the refusal");
        }

        [Test]
        public void AByteOrderMarkAndAConstGlobalInAnIncludedFileAreHandledToo()
        {
            Directory.CreateDirectory(Path.Combine(_dir, "Include"));
            File.WriteAllText(Path.Combine(_dir, "Include", "Factor.hlsl"), "const float factor;\nfloat Scaled(float x) { return factor * x; }\n", new UTF8Encoding(true));
            string path = Path.Combine(_dir, "UsesFactor.compute");
            File.WriteAllText(path,
                "#pragma kernel Main // the only kernel\n#include \"Include/Factor.hlsl\"\nRWStructuredBuffer<float> _Out;\n" +
                "[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID) { _Out[0] = Scaled(2.0f); }\n", new UTF8Encoding(true));
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram(path);
            int kernel = program.FindKernel("Main");
            using (var output = device.CreateBuffer("Out", 1, sizeof(float)))
            {
                device.SetBuffer(program, kernel, device.PropertyId("_Out"), output);
                device.SetFloat(program, device.PropertyId("factor"), 1.25f);
                device.Dispatch(program, kernel, 1, 1, 1);
                var result = new float[1];
                output.GetData(result);
                Assert.That(result[0], Is.EqualTo(2.5f));
            }
        }

        [Test]
        public void AConstThatGlslangWouldZeroIsAnErrorWithFileAndLine()
        {
            string path = Path.Combine(_dir, "LocalConst.compute");
            File.WriteAllText(path,
                "#pragma kernel Main\nRWStructuredBuffer<float> _Out;\n[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID)\n{\n" +
                "    const float k;\n    _Out[0] = k + 1.0f;\n}\n");
            var error = Assert.Throws<ComputeException>(() => GpuTestDevice.Shared.LoadProgram(path));
            Assert.That(error.Message, Does.Contain(path + ":6:").And.Contain("'k'").And.Contain("zero initializing").And.Contain("Main"));
        }

        [Test]
        public void ErrorsNameTheOriginalFileNeverThePreparedCopyGlslangRead()
        {
            string path = Path.Combine(_dir, "Faults.compute");
            File.WriteAllText(path, "#pragma kernel Main\nRWStructuredBuffer<float> _Out;\n[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID) { _Out[0] = missing; }\n");
            var syntax = Assert.Throws<ComputeException>(() => GpuTestDevice.Shared.LoadProgram(path));
            Assert.That(syntax.Message, Does.Contain(path + ":4:").And.Not.Contain("sphfluid-spirv-"));
            File.WriteAllText(path, "#pragma kernel Main\n#pragma kernel Absent\nRWStructuredBuffer<float> _Out;\n[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID) { _Out[0] = 1.0f; }\n");
            var entry = Assert.Throws<ComputeException>(() => GpuTestDevice.Shared.LoadProgram(path));
            Assert.That(entry.Message, Does.Contain("Absent").And.Not.Contain("sphfluid-spirv-"));
        }

        [Test]
        public void StructMemberInitializersThatGlslangIgnoresAreAnError()
        {
            string path = Path.Combine(_dir, "MemberInit.compute");
            File.WriteAllText(path,
                "#pragma kernel Main\nstruct Spring { float k = 2.0f; };\nRWStructuredBuffer<float> _Out;\n" +
                "[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID) { Spring s; s.k = 1.0f; _Out[0] = s.k; }\n");
            var error = Assert.Throws<ComputeException>(() => GpuTestDevice.Shared.LoadProgram(path));
            Assert.That(error.Message, Does.Contain(path + ":2:").And.Contain("struct-member initializers ignored"));
        }

        [Test]
        public void AKernelPragmaWithoutAValidNameIsReportedWithItsLine()
        {
            string path = Path.Combine(_dir, "BadPragma.compute");
            File.WriteAllText(path, "// kernels\n#pragma kernel Main\n#pragma kernel 3DFill\nRWStructuredBuffer<float> _Out;\n" +
                                    "[numthreads(1, 1, 1)]\nvoid Main(uint3 id : SV_DispatchThreadID) { _Out[0] = 1.0f; }\n");
            var error = Assert.Throws<ComputeException>(() => ComputeSource.Load(path, new string[0]));
            Assert.That(error.Message, Does.Contain(path + ":3:").And.Contain("'3DFill'"));
            File.WriteAllText(path, "#pragma kernel ;\n");
            Assert.That(() => ComputeSource.Load(path, new string[0]),
                Throws.TypeOf<ComputeException>().With.Message.Contains(path + ":1:").And.Message.Contains("needs a kernel name"));
        }

        [Test]
        public void KernelDefinesAreReadUpToTheSemicolon()
        {
            string path = Path.Combine(_dir, "Defines.compute");
            File.WriteAllText(path, "#pragma kernel A;\n#pragma kernel B WIDTH=4 FAST ; // note\n#pragma kernel C /* inline */ DEPTH=2\n");
            var source = ComputeSource.Load(path, new string[0]);
            Assert.That(source.Kernels.Select(k => k.Name + ":" + string.Join(",", k.Defines)),
                Is.EqualTo(new[] { "A:", "B:WIDTH=4,FAST", "C:DEPTH=2" }));
        }

        static float[] Run(IComputeDevice device, IComputeProgram program, string kernelName, float[] input)
        {
            int kernel = program.FindKernel(kernelName);
            using (var values = device.CreateBuffer("Values", input.Length, sizeof(float)))
            {
                values.SetData(input);
                device.SetBuffer(program, kernel, device.PropertyId("_Values"), values);
                device.SetInt(program, device.PropertyId("numItems"), input.Length);
                device.SetFloat(program, device.PropertyId("gain"), 3f);
                device.SetVector(program, device.PropertyId("_Offset"), new Vector4(1f, 2f, 4f, 0f));
                device.SetFloat(program, device.PropertyId("_OffsetWeight"), 0.5f);
                device.DispatchThreads(program, kernel, input.Length);
                var result = new float[input.Length];
                values.GetData(result);
                return result;
            }
        }
    }
}
