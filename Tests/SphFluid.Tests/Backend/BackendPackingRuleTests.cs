using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>What the SPIR-V repacking tells apart: Unity-packed buffers that need scalar block layout, and
    /// 16-byte-grouped ones that std430 lays out the same way.</summary>
    public sealed class BackendPackingRuleTests
    {
        [Test]
        public void PackedFloat3BuffersNeedScalarLayoutAndSixteenByteGroupsDoNot()
        {
            var device = GpuTestDevice.Shared;
            Assert.That(device.ScalarBlockLayout, Is.True, "lavapipe and current GPUs offer scalarBlockLayout");
            Assert.That(FollowsStd430(device, "BackendUnityPacking", "StepBodies"), Is.False, "44-byte Body with float3 at 12");
            Assert.That(FollowsStd430(device, "BackendUnityPacking", "ShiftPoints"), Is.False, "12-byte float3 elements");
            Assert.That(FollowsStd430(device, "BackendBuffers", "CopyItems"), Is.True, "float3 + uint, one 16-byte group");
        }

        [Test]
        public void RepackingTwiceChangesNothing()
        {
            var device = GpuTestDevice.Shared;
            var words = Compile(device, "BackendUnityPacking", "TransformPoints");
            Assert.That(StructuredBufferPacking.Apply(words), Is.EqualTo(words));
        }

        static bool FollowsStd430(VulkanComputeDevice device, string program, string kernel) =>
            StructuredBufferPacking.FollowsStd430(Compile(device, program, kernel));

        static uint[] Compile(VulkanComputeDevice device, string program, string kernel)
        {
            string path = GpuTestDevice.ShaderDirectories.Select(d => Path.Combine(d, program + ".compute")).First(File.Exists);
            var source = ComputeSource.Load(path, GpuTestDevice.ShaderDirectories);
            return device.Compiler.Compile(source, kernel, new string[0], GpuTestDevice.ShaderDirectories);
        }
    }
}
