using System.Numerics;
using System.Runtime.InteropServices;
using SphFluid.Compute;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The solver's constant buffer, member for member as <c>cbuffer FluidConstants</c> in
    /// Shaders/Include/FluidConstants.hlsl declares it (each HLSL name is this field's name with a leading
    /// underscore; the units and the include that reads each value are documented there). FluidSimulation keeps one
    /// and records an upload when a value changed; FluidConstantsLayoutTests compares the offsets with the compiled
    /// kernels' SPIR-V.
    /// </summary>
    /// <remarks>Matrices are HLSL <c>row_major</c>, which is <see cref="Matrix4x4"/>'s memory order: M{r}{c} is what the
    /// kernel reads as m[r-1][c-1].</remarks>
    [StructLayout(LayoutKind.Sequential, Size = Bytes)]
    public struct FluidConstants
    {
        /// <summary>The cbuffer's size in bytes, whole 16-byte rows (HLSL rounds a part row up).</summary>
        public const int Bytes = 448;

        public Matrix4x4 WorldToContainer;
        public Matrix4x4 ContainerToWorld;
        public Matrix4x4 WorldToGrid;

        public Vector3 ContainerCenter;
        public uint ParticleCount;
        public Vector3 ContainerHalfSize;
        public uint BoundaryCount;
        public Vector3 ContainerClampExtent;
        public uint ObstacleCount;
        public Vector3 ContainerVelocity;
        public float TimeStep;
        public Vector3 ContainerAngularVelocity;
        public float ParticleSpacing;
        public Vector3 Gravity;
        public float VelocityDamping;
        public UInt3 GridDims;
        public uint GridCellCount;

        public float SmoothingRadius;
        public float SmoothingRadius2;
        public float KernelCoefficient;
        public float GradientCoefficient;
        public float Stiffness;
        public float Gamma;
        public float ArtificialViscosity;
        public float WallArtificialViscosity;
        public float WallContactNumberDensity;
        public float SurfaceForceScale;
        public float XsphEpsilon;
        public float ShiftingCoefficient;
        public float WallFriction;

        public uint PhaseCount;
        public uint ReductionGroupCount;
        public float DensitySolveTolerance;
        public float DivergenceSolveTolerance;
        public uint DensitySolveRounds;
        public uint DivergenceSolveRounds;

        public float DensityDiffusion;
        public float HydrostaticCompliance;
        public uint SmoothingKernel;
        public uint WallContactAtAnyDensity;
        public float SolverRelaxation;

        public uint NeighbourCapacity;
        public uint NeighbourLanes;
        public uint NeighbourListRows;
        public float ChebyshevLow;

        public float ChebyshevHigh;
        public uint AcceleratedDensitySolve;
        public float ViscositySolveLow;
        public float ViscositySolveHigh;

        public float ViscositySolveStep;
        public float ViscositySolveSpan;
        public uint StrainRateViscosity;
    }
}
