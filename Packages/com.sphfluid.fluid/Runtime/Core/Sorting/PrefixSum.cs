using System;
using System.Collections.Generic;
using SphFluid.Compute;

namespace SphFluid.Sorting
{
    /// <summary>
    /// Exclusive prefix sum of uint buffers of any length up to <see cref="MaxLength"/> on the GPU
    /// (Shaders/PrefixSum.compute): output[i] = input[0] + ... + input[i-1], and <see cref="Total"/> = the sum
    /// of all. Blocks of <see cref="ElementsPerGroup"/> are scanned in groupshared memory, their totals
    /// scanned by the same kernel one level up (as many levels as the length needs), and the scanned
    /// totals added back: 1 dispatch up to 2048 elements, 3 up to 4M, 5 beyond. From 2049 to <see cref="SmallLength"/>
    /// one group scans them all in one dispatch instead (ScanSmall), since a GPU spends a few microseconds a dispatch,
    /// more than the work of a scene's cell grid.
    /// Owns its per-level scratch buffers; create it once for the largest length and keep it.
    /// </summary>
    public sealed class PrefixSum : IDisposable
    {
        /// <summary>Threads per group of both kernels (SCAN_THREADS in Include/PrefixSumBlock.hlsl).</summary>
        public const int ThreadsPerGroup = 256;

        /// <summary>Elements one group scans (SCAN_BLOCK in Include/PrefixSumBlock.hlsl).</summary>
        public const int ElementsPerGroup = 2048;

        /// <summary>Longest scan of one dispatch, one group (SCAN_SMALL_LENGTH in Include/PrefixSumBlock.hlsl).</summary>
        public const int SmallLength = 16384;

        /// <summary>Longest scan: one dispatch may have at most 65535 groups along x.</summary>
        public const int MaxSupportedLength = 65535 * ElementsPerGroup;

        public const string ProgramName = "PrefixSum";

        private readonly IComputeDevice device;
        private readonly IComputeProgram program;
        private readonly int scanBlocksKernel;
        private readonly int addBlockOffsetsKernel;
        private readonly int scanSmallKernel;
        private readonly int inputId, outputId, blockSumsId, blockOffsetsId, lengthId;

        // Level L >= 1 holds the block totals of level L-1 (blockSums[L-1]) and their scan (blockOffsets[L-1]).
        private readonly List<IComputeBuffer> blockSums = new List<IComputeBuffer>();
        private readonly List<IComputeBuffer> blockOffsets = new List<IComputeBuffer>();
        private readonly IComputeBuffer total;
        private bool disposed;

        /// <param name="device">The device that runs the scans.</param>
        /// <param name="maxLength">Longest input this instance will scan, in [1, <see cref="MaxSupportedLength"/>].</param>
        public PrefixSum(IComputeDevice device, int maxLength)
        {
            if (device == null) throw new ArgumentNullException(nameof(device));
            if (maxLength < 1 || maxLength > MaxSupportedLength)
                throw new ArgumentOutOfRangeException(nameof(maxLength), maxLength,
                    "PrefixSum: maxLength must be in [1, " + MaxSupportedLength + "] (was " + maxLength + ")");
            this.device = device;
            MaxLength = maxLength;
            program = device.LoadProgram(ProgramName);
            scanBlocksKernel = program.FindKernel("ScanBlocks");
            addBlockOffsetsKernel = program.FindKernel("AddBlockOffsets");
            scanSmallKernel = program.FindKernel("ScanSmall");
            CheckGroupSize(scanBlocksKernel, "ScanBlocks");
            CheckGroupSize(addBlockOffsetsKernel, "AddBlockOffsets");
            CheckGroupSize(scanSmallKernel, "ScanSmall");
            inputId = device.PropertyId("_ScanInput");
            outputId = device.PropertyId("_ScanOutput");
            blockSumsId = device.PropertyId("_ScanBlockSums");
            blockOffsetsId = device.PropertyId("_ScanBlockOffsets");
            lengthId = device.PropertyId("_ScanLength");

            try
            {
                for (int length = BlocksFor(maxLength); length > 1; length = BlocksFor(length))
                {
                    blockSums.Add(device.CreateBuffer("PrefixSum.BlockSums" + (blockSums.Count + 1), length, sizeof(uint)));
                    blockOffsets.Add(device.CreateBuffer("PrefixSum.BlockOffsets" + (blockOffsets.Count + 1), length, sizeof(uint)));
                }
                total = device.CreateBuffer("PrefixSum.Total", 1, sizeof(uint));
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        public int MaxLength { get; }

        /// <summary>One element: the sum of all inputs of the last <see cref="Scan"/> (the inclusive end).</summary>
        public IComputeBuffer Total => total;

        /// <summary>Levels of block totals a scan of <paramref name="length"/> elements goes through.</summary>
        public static int LevelsFor(int length)
        {
            int levels = 1;
            for (int n = BlocksFor(length); n > 1; n = BlocksFor(n)) levels++;
            return levels;
        }

        /// <summary>Records the exclusive scan of the first <paramref name="length"/> elements of
        /// <paramref name="input"/> into <paramref name="output"/> (different buffers, stride 4). Nothing is
        /// dispatched for length 0. Runs at the device's next submit, like every recorded dispatch.</summary>
        public void Scan(IComputeBuffer input, IComputeBuffer output, int length)
        {
            if (disposed) throw new ObjectDisposedException(nameof(PrefixSum));
            if (input == null) throw new ArgumentNullException(nameof(input));
            if (output == null) throw new ArgumentNullException(nameof(output));
            if (ReferenceEquals(input, output))
                throw new ArgumentException("PrefixSum: input and output must be different buffers (" + input.Name + ")", nameof(output));
            if (length < 0 || length > MaxLength)
                throw new ArgumentOutOfRangeException(nameof(length), length,
                    "PrefixSum: length must be in [0, " + MaxLength + "] (was " + length + ")");
            CheckBuffer(input, length, nameof(input));
            CheckBuffer(output, length, nameof(output));
            if (length == 0) return;
            // Up to one block, ScanBlocks' coalesced loads through groupshared memory do it in one dispatch already.
            if (length > ElementsPerGroup && length <= SmallLength)
            {
                device.SetBuffer(program, scanSmallKernel, inputId, input);
                device.SetBuffer(program, scanSmallKernel, outputId, output);
                device.SetBuffer(program, scanSmallKernel, blockSumsId, total);
                device.SetInt(program, lengthId, length);
                device.Dispatch(program, scanSmallKernel, 1, 1, 1);
                return;
            }
            ScanLevel(input, output, length, 0);
        }

        private void ScanLevel(IComputeBuffer input, IComputeBuffer output, int length, int level)
        {
            int blocks = BlocksFor(length);
            IComputeBuffer sums = blocks > 1 ? blockSums[level] : total;
            device.SetBuffer(program, scanBlocksKernel, inputId, input);
            device.SetBuffer(program, scanBlocksKernel, outputId, output);
            device.SetBuffer(program, scanBlocksKernel, blockSumsId, sums);
            device.SetInt(program, lengthId, length);
            device.Dispatch(program, scanBlocksKernel, blocks, 1, 1);
            if (blocks == 1) return;

            ScanLevel(blockSums[level], blockOffsets[level], blocks, level + 1);

            device.SetBuffer(program, addBlockOffsetsKernel, outputId, output);
            device.SetBuffer(program, addBlockOffsetsKernel, blockOffsetsId, blockOffsets[level]);
            device.SetInt(program, lengthId, length);
            device.Dispatch(program, addBlockOffsetsKernel, blocks - 1, 1, 1);
        }

        public void Dispose()
        {
            if (disposed) return;
            disposed = true;
            foreach (IComputeBuffer buffer in blockSums) buffer.Dispose();
            foreach (IComputeBuffer buffer in blockOffsets) buffer.Dispose();
            blockSums.Clear();
            blockOffsets.Clear();
            total?.Dispose();
        }

        private static int BlocksFor(int length)
        {
            return (int)(((long)length + ElementsPerGroup - 1) / ElementsPerGroup);
        }

        private static void CheckBuffer(IComputeBuffer buffer, int length, string name)
        {
            if (buffer.Stride != sizeof(uint))
                throw new ArgumentException("PrefixSum: " + name + " '" + buffer.Name + "' must hold uint (stride 4, was " + buffer.Stride + ")", name);
            if (buffer.Count < length)
                throw new ArgumentException("PrefixSum: " + name + " '" + buffer.Name + "' holds " + buffer.Count +
                                            " elements, fewer than the length " + length, name);
        }

        private void CheckGroupSize(int kernel, string kernelName)
        {
            program.GetKernelThreadGroupSizes(kernel, out uint x, out _, out _);
            if (x != ThreadsPerGroup)
                throw new ComputeException("PrefixSum: kernel " + kernelName + " of " + program.Name + " has " + x +
                                           " threads per group; PrefixSum.ThreadsPerGroup says " + ThreadsPerGroup);
        }
    }
}
