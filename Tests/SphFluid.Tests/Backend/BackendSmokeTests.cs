using NUnit.Framework;
using SphFluid.Compute;

namespace SphFluid.Tests.Backend
{
    public sealed class BackendSmokeTests
    {
        [Test]
        public void DispatchWritesWhatTheKernelComputes()
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("BackendSmoke");
            int kernel = program.FindKernel("Fill");
            const int count = 1000;
            using (var output = device.CreateBuffer("Output", count, sizeof(float)))
            {
                device.SetBuffer(program, kernel, device.PropertyId("_Output"), output);
                device.SetFloat(program, device.PropertyId("_Scale"), 0.5f);
                device.SetInt(program, device.PropertyId("_Count"), count);
                device.DispatchThreads(program, kernel, count);
                device.Submit();
                var result = new float[count];
                output.GetData(result);
                for (int i = 0; i < count; i++) Assert.That(result[i], Is.EqualTo(0.5f * i + 1f), "element " + i);
            }
        }
    }
}
