using System;
using System.Numerics;
using SphFluid.Compute;
using SphFluid.Sorting;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The GPU buffers of one <see cref="FluidSimulation"/> and, in one static table, the shader property each one is
    /// bound to and which program reads it. The simulation only says when a group of bindings changed (the particle
    /// buffers swap after every sort, the boundary and the cell lists are made again when the container is resized or an
    /// obstacle is reshaped); binding walks the table and allocates nothing.
    /// </summary>
    /// <remarks>
    /// Two particle buffers: the sort writes the other one and they swap, so <see cref="Particles"/> is always the
    /// cell-sorted current state. Per particle (indexed like the current particles): density and pressure, normals,
    /// accelerations, XSPH corrections and shifts; the DFSPH factor, stiffness and (by particle id) warm start. Then the
    /// phase table, the obstacles, the fluid's and the boundary's CellStart/CellCount, the boundary particles (rest frame,
    /// placed, cell-sorted) and their pressures, the neighbour lists of fluid and boundary particles (DFSPH), the
    /// clamp-hit counter, the reductions' partials and totals, the solver state and its indirect arguments, and the
    /// constant buffer (Include/FluidConstants.hlsl).
    /// </remarks>
    sealed class SolverBuffers : IDisposable
    {
        /// <summary>Words of the solver state: two solve slots of 8 words, the open solve's slot, the Chebyshev and viscosity
        /// weights and the fold's count of finished groups (FluidSolver.compute).</summary>
        public const int SolverStateWords = 20;

        /// <summary>When a binding must be made again.</summary>
        public enum Group
        {
            /// <summary>Once, when the buffers are made.</summary>
            Fixed,
            /// <summary>After every sort (the particle buffers swap).</summary>
            Particles,
            /// <summary>When the boundary is sampled again (container resized, obstacle reshaped).</summary>
            Boundary,
            /// <summary>When the fluid's sorter is made again for a larger grid.</summary>
            Cells,
        }

        [Flags]
        enum Readers
        {
            Solver = 1,
            Diagnostics = 2,
            Both = Solver | Diagnostics,
        }

        readonly struct Binding
        {
            public readonly string Property;
            public readonly Func<SolverBuffers, IComputeBuffer> Buffer;
            public readonly Readers Readers;
            public readonly Group Group;

            public Binding(string property, Func<SolverBuffers, IComputeBuffer> buffer, Readers readers, Group group)
            {
                Property = property;
                Buffer = buffer;
                Readers = readers;
                Group = group;
            }
        }

        static readonly Binding[] Table =
        {
            new Binding("_Particles", b => b.Particles, Readers.Both, Group.Particles),
            new Binding("_Phases", b => b.Phases, Readers.Both, Group.Fixed),
            new Binding("_Densities", b => b.Densities, Readers.Both, Group.Fixed),
            new Binding("_Normals", b => b.Normals, Readers.Solver, Group.Fixed),
            new Binding("_Rotations", b => b.Rotations, Readers.Solver, Group.Fixed),
            new Binding("_Accelerations", b => b.Accelerations, Readers.Both, Group.Fixed),
            new Binding("_VelocityCorrections", b => b.VelocityCorrections, Readers.Solver, Group.Fixed),
            new Binding("_Shifts", b => b.Shifts, Readers.Solver, Group.Fixed),
            new Binding("_Obstacles", b => b.Obstacles, Readers.Both, Group.Fixed),
            new Binding("_ClampHits", b => b.ClampHits, Readers.Both, Group.Fixed),
            new Binding("_DivergenceFreeFactors", b => b.Factors, Readers.Solver, Group.Fixed),
            new Binding("_SolverParticles", b => b.SolverParticles, Readers.Solver, Group.Fixed),
            new Binding("_WarmStart", b => b.WarmStart, Readers.Solver, Group.Fixed),
            new Binding("_SolverPartials", b => b.SolverPartials, Readers.Solver, Group.Fixed),
            new Binding("_SolverState", b => b.SolverState, Readers.Both, Group.Fixed),
            new Binding("_SolverArguments", b => b.SolverArguments, Readers.Solver, Group.Fixed),
            new Binding("_DivergenceRates", b => b.DivergenceRates, Readers.Both, Group.Fixed),
            new Binding("_ViscosityStart", b => b.ViscosityStart, Readers.Solver, Group.Fixed),
            new Binding("_ViscosityTargets", b => b.ViscosityTargets, Readers.Solver, Group.Fixed),
            new Binding("_ViscositySteps", b => b.ViscositySteps, Readers.Solver, Group.Fixed),
            new Binding("_NumberDensities", b => b.NumberDensities, Readers.Solver, Group.Fixed),
            new Binding("_NumberDensitiesHalf", b => b.NumberDensitiesHalf, Readers.Solver, Group.Fixed),
            new Binding("_DensityRates", b => b.DensityRates, Readers.Solver, Group.Fixed),
            new Binding("_MotionPartials", b => b.MotionPartials, Readers.Diagnostics, Group.Fixed),
            new Binding("_MotionTotals", b => b.MotionTotals, Readers.Diagnostics, Group.Fixed),
            new Binding("_DiagnosticsPartials", b => b.DiagnosticsPartials, Readers.Diagnostics, Group.Fixed),
            new Binding("_DiagnosticsTotals", b => b.DiagnosticsTotals, Readers.Diagnostics, Group.Fixed),
            new Binding("_BoundaryRest", b => b.BoundaryRest, Readers.Solver, Group.Boundary),
            new Binding("_BoundaryPlaced", b => b.BoundaryPlaced, Readers.Solver, Group.Boundary),
            new Binding("_BoundaryParticles", b => b.BoundarySorted, Readers.Solver, Group.Boundary),
            new Binding("_BoundarySortedSource", b => b.BoundarySorter.SortedSource, Readers.Solver, Group.Boundary),
            new Binding("_BoundaryPressures", b => b.BoundaryPressures, Readers.Solver, Group.Boundary),
            new Binding("_BoundarySolve", b => b.BoundarySolve, Readers.Solver, Group.Boundary),
            new Binding("_BoundaryWarmStart", b => b.BoundaryWarmStart, Readers.Solver, Group.Boundary),
            new Binding("_BoundaryCellStart", b => b.BoundarySorter.CellStart, Readers.Solver, Group.Boundary),
            new Binding("_BoundaryCellCount", b => b.BoundarySorter.CellCount, Readers.Solver, Group.Boundary),
            new Binding("_WallNumberDensities", b => b.WallNumberDensities, Readers.Solver, Group.Boundary),
            new Binding("_BoundaryOwnNumberDensities", b => b.BoundaryOwnNumberDensities, Readers.Solver, Group.Boundary),
            new Binding("_NeighbourCounts", b => b.NeighbourCounts, Readers.Solver, Group.Boundary),
            new Binding("_NeighbourLists", b => b.NeighbourLists, Readers.Solver, Group.Boundary),
            new Binding("_FoundNeighbourCounts", b => b.NeighbourCounts, Readers.Solver, Group.Boundary), // FindNeighbours writes them
            new Binding("_FoundNeighbourLists", b => b.NeighbourLists, Readers.Solver, Group.Boundary),
            new Binding(ParticleSorter.CellStartProperty, b => b.Sorter.CellStart, Readers.Solver, Group.Cells),
            new Binding(ParticleSorter.CellCountProperty, b => b.Sorter.CellCount, Readers.Solver, Group.Cells),
        };

        readonly IComputeDevice _device;
        readonly IComputeProgram _solver, _diagnostics;
        readonly int[] _solverKernels, _diagnosticsKernels;
        readonly int[] _ids = new int[Table.Length];
        readonly int _particleCount;

        public IComputeBuffer Particles, ParticlesOther;
        public IComputeBuffer Phases, Densities, Normals, Rotations, Accelerations, VelocityCorrections, Shifts, Obstacles, ClampHits;
        public IComputeBuffer Factors, SolverParticles, WarmStart, SolverPartials, SolverState, SolverArguments, DivergenceRates;
        public IComputeBuffer NumberDensities, NumberDensitiesHalf, DensityRates; // delta-SPH (SphDensityDiffusion.hlsl)
        public IComputeBuffer ViscosityStart, ViscosityTargets, ViscositySteps; // the implicit viscosity (ViscositySolve.hlsl)
        public IComputeBuffer MotionPartials, MotionTotals, DiagnosticsPartials, DiagnosticsTotals;
        public IComputeBuffer BoundaryRest, BoundaryPlaced, BoundarySorted, BoundaryPressures, BoundarySolve, BoundaryWarmStart, WallNumberDensities;
        public IComputeBuffer BoundaryOwnNumberDensities; // DFSPH by boundary id: its own body's number density at rest (BoundarySampling)
        public IComputeBuffer NeighbourCounts, NeighbourLists; // per fluid and boundary particle (SphNeighbourhood.hlsl)
        public IComputeBuffer Constants;
        public ParticleSorter Sorter, BoundarySorter;

        /// <summary>Makes every per-particle, solver and reduction buffer (zeroed), the phase table and the constant
        /// buffer, and binds them; the boundary and the sorters come with <see cref="MakeBoundary"/> and
        /// <see cref="MakeSorter"/>.</summary>
        public SolverBuffers(IComputeDevice device, IComputeProgram solver, int[] solverKernels, IComputeProgram diagnostics,
            int[] diagnosticsKernels, int particleCount, PhaseProperties[] phaseTable, int reductionGroups, int fluidConstantsId,
            float[] spawnNumberDensities)
        {
            _device = device;
            _solver = solver;
            _diagnostics = diagnostics;
            _solverKernels = solverKernels;
            _diagnosticsKernels = diagnosticsKernels;
            _particleCount = particleCount;
            for (int i = 0; i < Table.Length; i++) _ids[i] = device.PropertyId(Table[i].Property);
            try
            {
                Make(phaseTable, reductionGroups, fluidConstantsId, spawnNumberDensities);
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        void Make(PhaseProperties[] phaseTable, int reductionGroups, int fluidConstantsId, float[] spawnNumberDensities)
        {
            var device = _device;
            int n = _particleCount;
            Particles = device.CreateBuffer("FluidSimulation.Particles", n, Particle.Stride);
            ParticlesOther = device.CreateBuffer("FluidSimulation.ParticlesSorted", n, Particle.Stride);
            Phases = device.CreateBuffer("FluidSimulation.Phases", phaseTable.Length, PhaseProperties.Stride);
            Phases.SetData(phaseTable);
            Densities = Zeroed("FluidSimulation.Densities", n, 16);
            Normals = Zeroed("FluidSimulation.Normals", n, 16);
            Rotations = Zeroed("FluidSimulation.Rotations", n, 16);
            Accelerations = Zeroed("FluidSimulation.Accelerations", n, 16);
            VelocityCorrections = Zeroed("FluidSimulation.VelocityCorrections", n, 16);
            Shifts = Zeroed("FluidSimulation.Shifts", n, 16);
            Obstacles = device.CreateBuffer("FluidSimulation.Obstacles", FluidSceneDescription.MaxObstacles, Obstacle.Stride);
            ClampHits = Zeroed("FluidSimulation.ClampHits", 1, 4);
            Factors = Zeroed("FluidSimulation.DivergenceFreeFactors", n, 4);
            SolverParticles = Zeroed("FluidSimulation.SolverParticles", n, 16);
            WarmStart = Zeroed("FluidSimulation.WarmStart", n, 8);
            // One error sum per phase and group of the laned error pass, at the most lanes a particle can be given.
            SolverPartials = Zeroed("FluidSimulation.SolverPartials", phaseTable.Length * ComputeDispatch.GroupsFor(n * NeighbourLanes.Max, FluidSimulation.ParticleThreads), 4);
            SolverState = Zeroed("FluidSimulation.SolverState", SolverStateWords, 4);
            SolverArguments = device.CreateArgumentsBuffer("FluidSimulation.SolverArguments", 6);
            // The solve's laned group counts come from BeginSolve on the GPU before any dispatch reads them; until
            // then they dispatch nothing.
            SolverArguments.SetData(new uint[] { 0u, 1u, 1u, 0u, 1u, 1u });
            DivergenceRates = Zeroed("FluidSimulation.DivergenceRates", n, 4);
            ViscosityStart = Zeroed("FluidSimulation.ViscosityStart", n, 16);
            ViscosityTargets = Zeroed("FluidSimulation.ViscosityTargets", n, 16);
            ViscositySteps = Zeroed("FluidSimulation.ViscositySteps", n, 16);
            NumberDensities = device.CreateBuffer("FluidSimulation.NumberDensities", n, 4);
            NumberDensities.SetData(spawnNumberDensities);
            NumberDensitiesHalf = device.CreateBuffer("FluidSimulation.NumberDensitiesHalf", n, 4);
            NumberDensitiesHalf.SetData(spawnNumberDensities);
            DensityRates = Zeroed("FluidSimulation.DensityRates", n, 8);
            int phases = phaseTable.Length;
            MotionPartials = device.CreateBuffer("FluidSimulation.MotionPartials", reductionGroups, 16);
            MotionTotals = device.CreateBuffer("FluidSimulation.MotionTotals", 2, 16);
            DiagnosticsPartials = device.CreateBuffer("FluidSimulation.DiagnosticsPartials", reductionGroups * (2 + phases), 16);
            DiagnosticsTotals = device.CreateBuffer("FluidSimulation.DiagnosticsTotals", 3 + phases, 16);
            Constants = device.CreateConstantBuffer("FluidSimulation.Constants", FluidConstants.Bytes);
            device.SetConstantBuffer(_solver, fluidConstantsId, Constants);
            device.SetConstantBuffer(_diagnostics, fluidConstantsId, Constants);
            Bind(Group.Fixed);
            Bind(Group.Particles);
        }

        IComputeBuffer Zeroed(string name, int count, int stride)
        {
            var buffer = _device.CreateBuffer(name, count, stride);
            buffer.SetData(new byte[count * stride]);
            return buffer;
        }

        /// <summary>Binds every buffer of the group to every kernel of the programs that read it.</summary>
        public void Bind(Group group)
        {
            for (int i = 0; i < Table.Length; i++)
            {
                if (Table[i].Group != group) continue;
                var buffer = Table[i].Buffer(this);
                if ((Table[i].Readers & Readers.Solver) != 0)
                    foreach (int k in _solverKernels) _device.SetBuffer(_solver, k, _ids[i], buffer);
                if ((Table[i].Readers & Readers.Diagnostics) != 0)
                    foreach (int k in _diagnosticsKernels) _device.SetBuffer(_diagnostics, k, _ids[i], buffer);
            }
        }

        /// <summary>After a sort wrote <see cref="ParticlesOther"/>: it becomes the current state.</summary>
        public void SwapParticles()
        {
            var t = Particles;
            Particles = ParticlesOther;
            ParticlesOther = t;
            Bind(Group.Particles);
        }

        /// <summary>New boundary buffers for these boundary particles (in their owners' frames) and their own bodies' number
        /// densities at rest (<see cref="BoundarySampling.OwnNumberDensities"/>), a sorter for them, and neighbour
        /// lists of <paramref name="neighbourCapacity"/> entries for every fluid and boundary particle (one word each for 0:
        /// no lists, the kernels walk the grid).</summary>
        public void MakeBoundary(BoundaryParticle[] rest, float[] ownNumberDensities, int cellCount, int neighbourCapacity)
        {
            ReleaseBoundary();
            int count = rest.Length;
            BoundaryRest = _device.CreateBuffer("FluidSimulation.BoundaryRest", count, BoundaryParticle.Stride);
            BoundaryRest.SetData(rest);
            BoundaryPlaced = _device.CreateBuffer("FluidSimulation.BoundaryPlaced", count, BoundaryParticle.Stride);
            BoundarySorted = _device.CreateBuffer("FluidSimulation.BoundarySorted", count, BoundaryParticle.Stride);
            BoundaryPressures = Zeroed("FluidSimulation.BoundaryPressures", count, 4);
            BoundarySolve = Zeroed("FluidSimulation.BoundarySolve", count, 16);
            BoundaryWarmStart = Zeroed("FluidSimulation.BoundaryWarmStart", count, 8);
            WallNumberDensities = Zeroed("FluidSimulation.WallNumberDensities", count, 4);
            BoundaryOwnNumberDensities = _device.CreateBuffer("FluidSimulation.BoundaryOwnNumberDensities", count, 4);
            BoundaryOwnNumberDensities.SetData(ownNumberDensities);
            BoundarySorter = new ParticleSorter(_device, count, cellCount);
            int owners = neighbourCapacity > 0 ? _particleCount + count : 1;
            NeighbourCounts = _device.CreateBuffer("FluidSimulation.NeighbourCounts", owners, 4);
            NeighbourLists = _device.CreateBuffer("FluidSimulation.NeighbourLists", owners * Math.Max(neighbourCapacity, 1), 4);
            Bind(Group.Boundary);
        }

        /// <summary>A fluid sorter for a grid of <paramref name="cellCount"/> cells, unless the current one holds it.</summary>
        public void MakeSorter(int cellCount)
        {
            if (Sorter != null && cellCount <= Sorter.MaxCellCount) return;
            Sorter?.Dispose();
            Sorter = null;
            Sorter = new ParticleSorter(_device, _particleCount, cellCount);
            Bind(Group.Cells);
        }

        /// <summary>Zeroes what a respawn must not inherit: the clamp hits, the warm start and the solver state.</summary>
        public void ClearForRespawn()
        {
            ClampHits.SetData(new uint[1]);
            WarmStart.SetData(new Vector2[_particleCount]);
            BoundaryWarmStart?.SetData(new Vector2[BoundaryWarmStart.Count]);
            SolverState.SetData(new uint[SolverStateWords]);
        }

        void ReleaseBoundary()
        {
            BoundaryRest?.Dispose();
            BoundaryPlaced?.Dispose();
            BoundarySorted?.Dispose();
            BoundaryPressures?.Dispose();
            BoundarySolve?.Dispose();
            BoundaryWarmStart?.Dispose();
            WallNumberDensities?.Dispose();
            BoundaryOwnNumberDensities?.Dispose();
            BoundarySorter?.Dispose();
            NeighbourCounts?.Dispose();
            NeighbourLists?.Dispose();
            BoundaryRest = BoundaryPlaced = BoundarySorted = BoundaryPressures = BoundarySolve = BoundaryWarmStart = WallNumberDensities = BoundaryOwnNumberDensities = null;
            NeighbourCounts = NeighbourLists = null;
            BoundarySorter = null;
        }

        public void Dispose()
        {
            foreach (var buffer in new[] { Particles, ParticlesOther, Phases, Densities, Normals, Rotations, Accelerations, VelocityCorrections, Shifts,
                         Obstacles, ClampHits, Factors, SolverParticles, WarmStart, SolverPartials, SolverState, SolverArguments,
                         DivergenceRates, NumberDensities, NumberDensitiesHalf, DensityRates, ViscosityStart, ViscosityTargets, ViscositySteps, MotionPartials,
                         MotionTotals, DiagnosticsPartials, DiagnosticsTotals, Constants })
                buffer?.Dispose();
            Particles = ParticlesOther = Phases = Densities = Normals = Rotations = Accelerations = VelocityCorrections = Shifts = null;
            Obstacles = ClampHits = Factors = SolverParticles = WarmStart = SolverPartials = SolverState = SolverArguments = null;
            NumberDensities = NumberDensitiesHalf = DensityRates = ViscosityStart = ViscosityTargets = ViscositySteps = null;
            DivergenceRates = MotionPartials = MotionTotals = DiagnosticsPartials = DiagnosticsTotals = Constants = null;
            ReleaseBoundary();
            Sorter?.Dispose();
            Sorter = null;
        }
    }
}
