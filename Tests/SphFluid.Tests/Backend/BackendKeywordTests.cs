using NUnit.Framework;
using SphFluid.Compute;

namespace SphFluid.Tests.Backend
{
    /// <summary>multi_compile keywords are read from the file and select the variant that runs.</summary>
    public sealed class BackendKeywordTests
    {
        [Test]
        public void KeywordsAreListedFromThePragmas()
        {
            var program = GpuTestDevice.Shared.LoadProgram("BackendKeywords");
            Assert.That(program.Keywords, Is.EqualTo(new[] { "MODE_A", "MODE_B", "DOUBLE_IT" }));
        }

        [Test]
        public void KeywordVariantsSelectTheirCode()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendKeywords");
            int kernel = program.FindKernel("WriteVariant");
            using (var code = device.CreateBuffer("VariantCode", 1, sizeof(uint)))
            {
                device.SetBuffer(program, kernel, device.PropertyId("_VariantCode"), code);
                Assert.That(Run(device, program, kernel, code), Is.EqualTo(1u), "no keyword");
                device.SetKeyword(program, "MODE_A", true);
                Assert.That(Run(device, program, kernel, code), Is.EqualTo(2u), "MODE_A");
                device.SetKeyword(program, "DOUBLE_IT", true);
                Assert.That(Run(device, program, kernel, code), Is.EqualTo(20u), "MODE_A DOUBLE_IT");
                device.SetKeyword(program, "MODE_A", false);
                device.SetKeyword(program, "MODE_B", true);
                Assert.That(Run(device, program, kernel, code), Is.EqualTo(30u), "MODE_B DOUBLE_IT");
                device.SetKeyword(program, "DOUBLE_IT", false);
                device.SetKeyword(program, "MODE_B", false);
                Assert.That(Run(device, program, kernel, code), Is.EqualTo(1u), "back to no keyword");
            }
        }

        [Test]
        public void VariantsRecordedInOneSubmitEachRunTheirOwnCode()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendKeywords");
            int kernel = program.FindKernel("WriteVariant");
            using (var plain = device.CreateBuffer("PlainCode", 1, sizeof(uint)))
            using (var modeB = device.CreateBuffer("ModeBCode", 1, sizeof(uint)))
            {
                device.SetBuffer(program, kernel, device.PropertyId("_VariantCode"), plain);
                device.Dispatch(program, kernel, 1, 1, 1);
                device.SetKeyword(program, "MODE_B", true);
                device.SetBuffer(program, kernel, device.PropertyId("_VariantCode"), modeB);
                device.Dispatch(program, kernel, 1, 1, 1);
                device.Submit();
                var a = new uint[1];
                var b = new uint[1];
                plain.GetData(a);
                modeB.GetData(b);
                Assert.That(a[0], Is.EqualTo(1u));
                Assert.That(b[0], Is.EqualTo(3u));
            }
        }

        [Test]
        public void UndeclaredKeywordIsNamed()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendKeywords");
            Assert.That(() => device.SetKeyword(program, "NOT_A_KEYWORD", true),
                Throws.TypeOf<ComputeException>().With.Message.Contains("NOT_A_KEYWORD"));
        }

        static uint Run(IComputeDevice device, IComputeProgram program, int kernel, IComputeBuffer code)
        {
            device.Dispatch(program, kernel, 1, 1, 1);
            var result = new uint[1];
            code.GetData(result);
            return result[0];
        }
    }
}
