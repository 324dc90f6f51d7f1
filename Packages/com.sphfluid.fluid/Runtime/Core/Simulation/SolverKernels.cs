using SphFluid.Compute;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The kernels of FluidSolver.compute, each found once by its <c>#pragma kernel</c> name (the field's own name), in
    /// the order the compute file declares them. <see cref="All"/> is every one of them, for the buffers bound to each.
    /// </summary>
    internal sealed class SolverKernels
    {
        // WCSPH's Velocity Verlet sub-step (HalfStep, or HalfKick and HalfDrift around an implicit viscosity solve), the
        // walls and delta-SPH (SphDensityDiffusion.hlsl).
        public readonly int HalfStep, HalfKick, HalfDrift, PlaceBoundary, DensityPressure, DensityRate, ContinuityDensity, WallPressure, Normals, Rotations, Forces,
            FullStep, ParticleShift, ApplyShift;

        // DFSPH's sub-step and its two solves (Passes/DivergenceFree*.hlsl).
        public readonly int DensityFactor, WallMovedDensityFactor, BoundaryDensityFactor, BoundarySolveError,
            NonPressureForces, PredictVelocity, BeginDensitySolve, BeginDivergenceSolve, DensitySolveError, DivergenceSolveError,
            ApplyStiffness, Drift, DivergenceRate, FindNeighbours, WallNumberDensity;

        // The implicit viscosity solve (ViscositySolve.hlsl).
        public readonly int ViscosityStep, ViscosityApply, ViscosityStage;

        public readonly int[] All;

        public SolverKernels(IComputeProgram solver)
        {
            HalfStep = solver.FindKernel(nameof(HalfStep));
            HalfKick = solver.FindKernel(nameof(HalfKick));
            HalfDrift = solver.FindKernel(nameof(HalfDrift));
            PlaceBoundary = solver.FindKernel(nameof(PlaceBoundary));
            DensityPressure = solver.FindKernel(nameof(DensityPressure));
            DensityRate = solver.FindKernel(nameof(DensityRate));
            ContinuityDensity = solver.FindKernel(nameof(ContinuityDensity));
            WallPressure = solver.FindKernel(nameof(WallPressure));
            Normals = solver.FindKernel(nameof(Normals));
            Rotations = solver.FindKernel(nameof(Rotations));
            Forces = solver.FindKernel(nameof(Forces));
            FullStep = solver.FindKernel(nameof(FullStep));
            ParticleShift = solver.FindKernel(nameof(ParticleShift));
            ApplyShift = solver.FindKernel(nameof(ApplyShift));
            DensityFactor = solver.FindKernel(nameof(DensityFactor));
            WallMovedDensityFactor = solver.FindKernel(nameof(WallMovedDensityFactor));
            BoundaryDensityFactor = solver.FindKernel(nameof(BoundaryDensityFactor));
            BoundarySolveError = solver.FindKernel(nameof(BoundarySolveError));
            NonPressureForces = solver.FindKernel(nameof(NonPressureForces));
            PredictVelocity = solver.FindKernel(nameof(PredictVelocity));
            BeginDensitySolve = solver.FindKernel(nameof(BeginDensitySolve));
            BeginDivergenceSolve = solver.FindKernel(nameof(BeginDivergenceSolve));
            DensitySolveError = solver.FindKernel(nameof(DensitySolveError));
            DivergenceSolveError = solver.FindKernel(nameof(DivergenceSolveError));
            ApplyStiffness = solver.FindKernel(nameof(ApplyStiffness));
            Drift = solver.FindKernel(nameof(Drift));
            DivergenceRate = solver.FindKernel(nameof(DivergenceRate));
            FindNeighbours = solver.FindKernel(nameof(FindNeighbours));
            WallNumberDensity = solver.FindKernel(nameof(WallNumberDensity));
            ViscosityStep = solver.FindKernel(nameof(ViscosityStep));
            ViscosityApply = solver.FindKernel(nameof(ViscosityApply));
            ViscosityStage = solver.FindKernel(nameof(ViscosityStage));
            All = new[]
            {
                HalfStep, HalfKick, HalfDrift, PlaceBoundary, DensityPressure, DensityRate, ContinuityDensity, WallPressure, Normals, Rotations, Forces, FullStep,
                ParticleShift, ApplyShift, DensityFactor, WallMovedDensityFactor, BoundaryDensityFactor,
                BoundarySolveError, NonPressureForces, PredictVelocity, BeginDensitySolve, BeginDivergenceSolve, DensitySolveError,
                DivergenceSolveError, ApplyStiffness, Drift, DivergenceRate, FindNeighbours, WallNumberDensity,
                ViscosityStep, ViscosityApply, ViscosityStage,
            };
        }
    }
}
