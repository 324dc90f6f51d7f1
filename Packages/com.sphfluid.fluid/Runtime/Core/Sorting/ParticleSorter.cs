using System;
using SphFluid.Compute;
using SphFluid.Simulation;

namespace SphFluid.Sorting
{
    /// <summary>
    /// Sorts particles by grid cell every step (Shaders/ParticleSort.compute): a stable counting sort with
    /// no per-cell capacity, so no particle is ever dropped however many share a cell. After
    /// <see cref="Sort"/>, the destination buffer holds the particles grouped by cell (memory-coherent
    /// neighbour loops over rows of cells, SphNeighbourhood.hlsl), and cell c's particles are
    /// <c>_SortedParticles[_CellStart[c] .. _CellStart[c] + _CellCount[c] - 1]</c>.
    /// </summary>
    /// <remarks>
    /// Stable: within a cell, particles keep their input order, so a step's output depends only on its
    /// input, never on GPU thread timing. Bind <see cref="CellStart"/> / <see cref="CellCount"/> to the
    /// solver's kernels as <see cref="CellStartProperty"/> / <see cref="CellCountProperty"/>, and upload the
    /// grid with <see cref="CellGrid.SetOn"/>. The buffers are valid for the grid of the last sort; the
    /// sorter owns them (and its scratch) and releases them on <see cref="Dispose"/>.
    /// </remarks>
    public sealed class ParticleSorter : IDisposable
    {
        public const string ProgramName = "ParticleSort";

        /// <summary>Per cell: index of its first particle in the sorted buffer (uint).</summary>
        public const string CellStartProperty = "_CellStart";

        /// <summary>Per cell: number of its particles (uint).</summary>
        public const string CellCountProperty = "_CellCount";

        /// <summary>Per sorted slot j: index in the input buffer of the particle now at j (uint). Lets the
        /// solver carry per-particle data that is not in <see cref="Particle"/> into the new order.</summary>
        public const string SortedSourceProperty = "_SortedSource";

        /// <summary>Threads per group of every ParticleSort kernel (SORT_THREADS).</summary>
        public const int ThreadsPerGroup = 256;

        /// <summary>Cells one ClearCells group clears (SORT_THREADS * CLEAR_PER_THREAD).</summary>
        private const int CellsPerClearGroup = 256 * 8;

        /// <summary>Most particles: one dispatch may have at most 65535 groups along x.</summary>
        public const int MaxSupportedParticles = 65535 * ThreadsPerGroup;

        private readonly IComputeDevice device;
        private readonly IComputeProgram program;
        private readonly PrefixSum prefixSum;
        private readonly int clearCells, rankInBlocks, sumEarlierBlocks, scatterParticles;
        private readonly int particleCountId, particlesId, sortedParticlesId, sortedSourceId;
        private readonly int cellCountId, cellStartId, sortKeysId, sortRecordsId;
        private IComputeBuffer cellCount, cellStart, sortKeys, sortRecords, sortedSource;
        private bool disposed;

        /// <param name="device">The device that runs the sort.</param>
        /// <param name="maxParticles">Most particles one sort handles, in [1, <see cref="MaxSupportedParticles"/>].</param>
        /// <param name="maxCellCount">Most grid cells (<see cref="CellGrid.CellCount"/>), in [1, <see cref="CellGrid.MaxCellCount"/>].</param>
        public ParticleSorter(IComputeDevice device, int maxParticles, int maxCellCount)
        {
            if (device == null) throw new ArgumentNullException(nameof(device));
            if (maxParticles < 1 || maxParticles > MaxSupportedParticles)
                throw new ArgumentOutOfRangeException(nameof(maxParticles), maxParticles,
                    "ParticleSorter: maxParticles must be in [1, " + MaxSupportedParticles + "] (was " + maxParticles + ")");
            if (maxCellCount < 1 || maxCellCount > CellGrid.MaxCellCount)
                throw new ArgumentOutOfRangeException(nameof(maxCellCount), maxCellCount,
                    "ParticleSorter: maxCellCount must be in [1, " + CellGrid.MaxCellCount + "] (was " + maxCellCount + ")");
            this.device = device;
            MaxParticles = maxParticles;
            MaxCellCount = maxCellCount;

            program = device.LoadProgram(ProgramName);
            clearCells = FindKernel("ClearCells");
            rankInBlocks = FindKernel("RankInBlocks");
            sumEarlierBlocks = FindKernel("SumEarlierBlocks");
            scatterParticles = FindKernel("ScatterParticles");
            particleCountId = device.PropertyId("_ParticleCount");
            particlesId = device.PropertyId("_Particles");
            sortedParticlesId = device.PropertyId("_SortedParticles");
            sortedSourceId = device.PropertyId(SortedSourceProperty);
            cellCountId = device.PropertyId(CellCountProperty);
            cellStartId = device.PropertyId(CellStartProperty);
            sortKeysId = device.PropertyId("_SortKeys");
            sortRecordsId = device.PropertyId("_SortRecords");

            try
            {
                prefixSum = new PrefixSum(device, maxCellCount);
                cellCount = device.CreateBuffer("ParticleSorter.CellCount", maxCellCount, sizeof(uint));
                cellStart = device.CreateBuffer("ParticleSorter.CellStart", maxCellCount, sizeof(uint));
                sortKeys = device.CreateBuffer("ParticleSorter.SortKeys", maxParticles, 4 * sizeof(uint));
                sortRecords = device.CreateBuffer("ParticleSorter.SortRecords", maxParticles, 2 * sizeof(uint));
                sortedSource = device.CreateBuffer("ParticleSorter.SortedSource", maxParticles, sizeof(uint));
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        public int MaxParticles { get; }
        public int MaxCellCount { get; }

        /// <summary>Per cell, the first sorted slot (<see cref="CellStartProperty"/>).</summary>
        public IComputeBuffer CellStart => cellStart;

        /// <summary>Per cell, the particle count (<see cref="CellCountProperty"/>).</summary>
        public IComputeBuffer CellCount => cellCount;

        /// <summary>Per sorted slot, the input index it came from (<see cref="SortedSourceProperty"/>).</summary>
        public IComputeBuffer SortedSource => sortedSource;

        /// <summary>
        /// Records the sort of the first <paramref name="particleCount"/> particles of <paramref name="particles"/>
        /// into <paramref name="sortedParticles"/> (a different buffer of <see cref="Particle"/>), grouped by
        /// the cell of <paramref name="grid"/> each falls in. Uploads the grid's globals to the sort program.
        /// Runs at the device's next submit; the solver usually swaps the two buffers afterwards.
        /// </summary>
        public void Sort(CellGrid grid, IComputeBuffer particles, IComputeBuffer sortedParticles, int particleCount)
        {
            if (disposed) throw new ObjectDisposedException(nameof(ParticleSorter));
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            CheckParticles(particles, nameof(particles), particleCount);
            CheckParticles(sortedParticles, nameof(sortedParticles), particleCount);
            if (ReferenceEquals(particles, sortedParticles))
                throw new ArgumentException("ParticleSorter: particles and sortedParticles must be different buffers (" + particles.Name + ")",
                    nameof(sortedParticles));
            if (particleCount < 0 || particleCount > MaxParticles)
                throw new ArgumentOutOfRangeException(nameof(particleCount), particleCount,
                    "ParticleSorter: particleCount must be in [0, " + MaxParticles + "] (was " + particleCount + ")");
            if (grid.CellCount > MaxCellCount)
                throw new ArgumentException("ParticleSorter: " + grid + " has " + grid.CellCount + " cells, more than the " +
                                            MaxCellCount + " this sorter was created for", nameof(grid));

            grid.SetOn(device, program);
            device.SetInt(program, particleCountId, particleCount);

            device.SetBuffer(program, clearCells, cellCountId, cellCount);
            device.SetBuffer(program, clearCells, cellStartId, cellStart);
            device.Dispatch(program, clearCells, (grid.CellCount + CellsPerClearGroup - 1) / CellsPerClearGroup, 1, 1);
            if (particleCount == 0)
            {
                // Every CellStart must still read as a valid (empty) range.
                prefixSum.Scan(cellCount, cellStart, grid.CellCount);
                return;
            }

            device.SetBuffer(program, rankInBlocks, particlesId, particles);
            device.SetBuffer(program, rankInBlocks, cellCountId, cellCount);
            device.SetBuffer(program, rankInBlocks, cellStartId, cellStart);
            device.SetBuffer(program, rankInBlocks, sortKeysId, sortKeys);
            device.SetBuffer(program, rankInBlocks, sortRecordsId, sortRecords);
            device.DispatchThreads(program, rankInBlocks, particleCount);

            device.SetBuffer(program, sumEarlierBlocks, cellStartId, cellStart);
            device.SetBuffer(program, sumEarlierBlocks, sortKeysId, sortKeys);
            device.SetBuffer(program, sumEarlierBlocks, sortRecordsId, sortRecords);
            device.DispatchThreads(program, sumEarlierBlocks, particleCount);

            prefixSum.Scan(cellCount, cellStart, grid.CellCount);

            device.SetBuffer(program, scatterParticles, particlesId, particles);
            device.SetBuffer(program, scatterParticles, sortedParticlesId, sortedParticles);
            device.SetBuffer(program, scatterParticles, sortedSourceId, sortedSource);
            device.SetBuffer(program, scatterParticles, cellStartId, cellStart);
            device.SetBuffer(program, scatterParticles, sortKeysId, sortKeys);
            device.SetBuffer(program, scatterParticles, sortRecordsId, sortRecords);
            device.DispatchThreads(program, scatterParticles, particleCount);
        }

        public void Dispose()
        {
            if (disposed) return;
            disposed = true;
            prefixSum?.Dispose();
            cellCount?.Dispose();
            cellStart?.Dispose();
            sortKeys?.Dispose();
            sortRecords?.Dispose();
            sortedSource?.Dispose();
            cellCount = cellStart = sortKeys = sortRecords = sortedSource = null;
        }

        private int FindKernel(string name)
        {
            int kernel = program.FindKernel(name);
            program.GetKernelThreadGroupSizes(kernel, out uint x, out _, out _);
            if (x != ThreadsPerGroup)
                throw new ComputeException("ParticleSorter: kernel " + name + " of " + program.Name + " has " + x +
                                           " threads per group; ParticleSorter.ThreadsPerGroup says " + ThreadsPerGroup);
            return kernel;
        }

        private static void CheckParticles(IComputeBuffer buffer, string name, int particleCount)
        {
            if (buffer == null) throw new ArgumentNullException(name);
            if (buffer.Stride != Particle.Stride)
                throw new ArgumentException("ParticleSorter: " + name + " '" + buffer.Name + "' must hold Particle (stride " +
                                            Particle.Stride + ", was " + buffer.Stride + ")", name);
            if (buffer.Count < particleCount)
                throw new ArgumentException("ParticleSorter: " + name + " '" + buffer.Name + "' holds " + buffer.Count +
                                            " particles, fewer than particleCount " + particleCount, name);
        }
    }
}
