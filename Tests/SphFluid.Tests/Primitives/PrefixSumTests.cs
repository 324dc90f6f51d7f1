using System;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Sorting;

namespace SphFluid.Tests.Primitives
{
    /// <summary>The GPU exclusive scan against a CPU scan, across one, two and three block levels.</summary>
    public sealed class PrefixSumTests
    {
        // 2048^2 + 1: the first length whose block totals need a third level.
        private const int ThreeLevelLength = PrefixSum.ElementsPerGroup * PrefixSum.ElementsPerGroup + 1;

        private IComputeDevice device;
        private PrefixSum scan;
        private IComputeBuffer input, output;

        [OneTimeSetUp]
        public void CreateScan()
        {
            device = GpuTestDevice.Shared;
            scan = new PrefixSum(device, ThreeLevelLength);
            input = device.CreateBuffer("PrefixSumTests.Input", ThreeLevelLength, sizeof(uint));
            output = device.CreateBuffer("PrefixSumTests.Output", ThreeLevelLength, sizeof(uint));
        }

        [OneTimeTearDown]
        public void ReleaseScan()
        {
            scan?.Dispose();
            input?.Dispose();
            output?.Dispose();
        }

        [TestCase(1)]
        [TestCase(255)]
        [TestCase(256)]
        [TestCase(257)]
        [TestCase(2048)]
        [TestCase(2049)]
        [TestCase(PrefixSum.SmallLength - 1)]
        [TestCase(PrefixSum.SmallLength)]
        [TestCase(PrefixSum.SmallLength + 1)]
        [TestCase(100000)]
        [TestCase(600000)]
        [TestCase(ThreeLevelLength)]
        public void ExclusiveScanEqualsCpuScan(int length)
        {
            uint[] values = RandomValues(length, 1000, length);

            uint[] gpu = RunScan(values, out uint total);

            uint[] expected = CpuExclusiveScan(values, out uint expectedTotal);
            Assert.That(FirstMismatch(gpu, expected), Is.EqualTo(-1), "first index where GPU and CPU scans differ");
            Assert.That(total, Is.EqualTo(expectedTotal));
        }

        [Test]
        public void LevelsGrowWithTheLength()
        {
            Assert.That(PrefixSum.LevelsFor(2048), Is.EqualTo(1));
            Assert.That(PrefixSum.LevelsFor(2049), Is.EqualTo(2));
            Assert.That(PrefixSum.LevelsFor(ThreeLevelLength), Is.EqualTo(3));
        }

        sealed class DispatchCounter : ForwardingDevice
        {
            public DispatchCounter(IComputeDevice inner) : base(inner) { }

            public int Dispatches { get; private set; }

            public override void Dispatch(IComputeProgram program, int kernel, int groupsX, int groupsY, int groupsZ)
            {
                Dispatches++;
                Inner.Dispatch(program, kernel, groupsX, groupsY, groupsZ);
            }
        }

        /// <summary>A scene's cell grid of up to <see cref="PrefixSum.SmallLength"/> cells is scanned in one dispatch: on an
        /// H200 the sort of the three demo scenes whose grids took three went from 0.037 to 0.053 ms a sub-step.</summary>
        [TestCase(1, 1)]
        [TestCase(7590, 1)] // OilAndWater's grid, cells of half the support
        [TestCase(PrefixSum.SmallLength, 1)]
        [TestCase(PrefixSum.SmallLength + 1, 3)]
        [TestCase(600000, 3)]
        [TestCase(ThreeLevelLength, 5)]
        public void AScanTakesOneDispatchUpToTheSmallLength(int length, int dispatches)
        {
            var counter = new DispatchCounter(device);
            using var counted = new PrefixSum(counter, ThreeLevelLength);
            counted.Scan(input, output, length);
            counter.Submit();
            Assert.That(counter.Dispatches, Is.EqualTo(dispatches));
        }

        [Test]
        public void SumsWrapAroundLikeUint()
        {
            uint[] values = { uint.MaxValue, 2u, 3u, uint.MaxValue - 1u, 7u };

            uint[] gpu = RunScan(values, out uint total);

            Assert.That(gpu, Is.EqualTo(CpuExclusiveScan(values, out uint expectedTotal)));
            Assert.That(total, Is.EqualTo(expectedTotal));
        }

        [Test]
        public void ScanOnlyWritesTheRequestedLength()
        {
            uint[] sentinel = new uint[300];
            for (int i = 0; i < sentinel.Length; i++) sentinel[i] = 0xDEADBEEFu;
            output.SetData(sentinel);
            uint[] values = RandomValues(257, 50, 7);
            input.SetData(values);

            scan.Scan(input, output, values.Length);
            uint[] gpu = new uint[300];
            output.GetData(gpu);

            Assert.That(gpu[256], Is.EqualTo(CpuExclusiveScan(values, out _)[256]));
            Assert.That(gpu[257], Is.EqualTo(0xDEADBEEFu));
            Assert.That(gpu[299], Is.EqualTo(0xDEADBEEFu));
        }

        [Test]
        public void MisuseIsRefusedWithAClearMessage()
        {
            Assert.That(() => scan.Scan(input, input, 10), Throws.ArgumentException.With.Message.Contains("different buffers"));
            Assert.That(() => scan.Scan(input, output, ThreeLevelLength + 1),
                Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("length must be in [0, " + ThreeLevelLength + "]"));
            Assert.That(() => new PrefixSum(device, 0), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("maxLength"));
        }

        private uint[] RunScan(uint[] values, out uint total)
        {
            input.SetData(values, 0, 0, values.Length);
            scan.Scan(input, output, values.Length);
            device.Submit();
            var result = new uint[values.Length];
            output.GetData(result);
            var totalData = new uint[1];
            scan.Total.GetData(totalData);
            total = totalData[0];
            return result;
        }

        internal static uint[] RandomValues(int length, int maxExclusive, int seed)
        {
            var random = new Random(seed);
            var values = new uint[length];
            for (int i = 0; i < length; i++) values[i] = (uint)random.Next(maxExclusive);
            return values;
        }

        internal static uint[] CpuExclusiveScan(uint[] values, out uint total)
        {
            var result = new uint[values.Length];
            uint sum = 0u;
            for (int i = 0; i < values.Length; i++)
            {
                result[i] = sum;
                sum = unchecked(sum + values[i]);
            }
            total = sum;
            return result;
        }

        internal static int FirstMismatch(uint[] actual, uint[] expected)
        {
            if (actual.Length != expected.Length) return Math.Min(actual.Length, expected.Length);
            for (int i = 0; i < actual.Length; i++)
                if (actual[i] != expected[i]) return i;
            return -1;
        }
    }
}
