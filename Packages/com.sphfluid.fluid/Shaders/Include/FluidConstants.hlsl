#ifndef SPHFLUID_FLUID_CONSTANTS_INCLUDED
#define SPHFLUID_FLUID_CONSTANTS_INCLUDED

// Every constant the solver and its diagnostics read, in one constant buffer. The C# struct
// SphFluid.Simulation.FluidConstants mirrors it member for member; FluidSimulation keeps one copy, and
// records an upload of it before the next dispatch whenever a value changed (settings at start, the
// container and the time step once a frame), so a dispatch never pays for per-value parameter calls.
// FluidConstantsLayoutTests compares the struct's offsets with the SPIR-V reflection of both programs.
//
// Layout: HLSL packing (a vector never straddles a 16-byte row), written as whole 16-byte rows so that
// the C# struct needs no padding. Matrices are row_major: the C# System.Numerics.Matrix4x4's memory
// order (M11 M12 M13 M14 M21 ...), so M{r}{c} is what the kernel reads as m[r-1][c-1]; the transforms
// are written for column vectors, mul(m, float4(p, 1)), translation in the last column.
//
// Per row, the include whose equation reads the value.
cbuffer FluidConstants
{
    row_major float4x4 _WorldToContainer;   // SphBoundary: q = mul(_WorldToContainer, float4(x, 1)).xyz = R^T (x - c)
    row_major float4x4 _ContainerToWorld;   // SphBoundary: x = mul(_ContainerToWorld, float4(q, 1)).xyz = R q + c
    row_major float4x4 _WorldToGrid;        // Grid: world -> grid units

    float3 _ContainerCenter;                // SphBoundary: c, m
    uint _ParticleCount;                    // fluid particles
    float3 _ContainerHalfSize;              // SphBoundary: S/2, m, the walls' inner faces
    uint _BoundaryCount;                    // boundary particles (walls and obstacles)
    float3 _ContainerClampExtent;           // SphBoundary: Hc = S/2 - s/100, m, no particle centre beyond it
    uint _ObstacleCount;                    // SphBoundary: sphere obstacles in _Obstacles
    float3 _ContainerVelocity;              // SphBoundary: V, m/s
    float _TimeStep;                        // SphIntegration: dt of this sub-step, s
    float3 _ContainerAngularVelocity;       // SphBoundary: w, rad/s
    float _ParticleSpacing;                 // SphBoundary: s, m
    float3 _Gravity;                        // g, m/s^2
    float _VelocityDamping;                 // SphIntegration: 1/s, 0 = none
    uint3 _GridDims;                        // Grid: cells per local axis, margin included
    uint _GridCellCount;                    // Grid: _GridDims.x * _GridDims.y * _GridDims.z

    float _SmoothingRadius;                 // SphKernels: H, the support radius, m
    float _SmoothingRadius2;                // SphKernels: H^2, m^2
    float _KernelCoefficient;               // SphKernels: sigma (8 / (pi H^3) for the cubic spline), 1/m^3
    float _GradientCoefficient;             // SphKernels: sigma / H, 1/m^4
    float _Stiffness;                       // SphDensityPressure: Tait k, Pa
    float _Gamma;                           // SphDensityPressure: Tait exponent
    float _ArtificialViscosity;             // SphViscosity: alpha c h, m^2/s
    float _WallArtificialViscosity;         // SphViscosity: alpha_w c h against boundary particles, m^2/s
    float _WallContactNumberDensity;        // SphBoundary: the walls' share of delta beside a flat wall at rest, 1/m^3
    float _SurfaceForceScale;               // SphSurfaceTension: 1 / (H share), the normals' H and SurfaceLayerShare's share undone, 1/m
    float _XsphEpsilon;                     // SphXsph: epsilon in [0, 1]
    float _ShiftingCoefficient;             // ParticleShifting: A h, m
    float _WallFriction;                    // SphBoundary: 0 free slip, 1 no slip

    uint _PhaseCount;                       // rows of the phase table
    uint _ReductionGroupCount;              // SphTimeStep: groups of the diagnostics' partial reductions
    float _DensitySolveTolerance;           // DivergenceFreeSolver: average density error that ends the solve
    float _DivergenceSolveTolerance;        // DivergenceFreeSolver: average divergence error that ends the solve at this sub-step, 1/s (DivergenceSolveTolerance.cs)
    uint _DensitySolveRounds;               // DivergenceFreeSolver: rounds recorded for the constant-density solve
    uint _DivergenceSolveRounds;            // DivergenceFreeSolver: rounds recorded for the divergence-free solve

    float _DensityDiffusion;                // SphDensityDiffusion: xi h c0, m^2/s
    float _HydrostaticCompliance;           // SphDensityDiffusion: 1 / (gamma k), 1/Pa
    uint _SmoothingKernel;                  // SphKernels: 0 cubic spline, 1 Wendland C2
    uint _WallContactAtAnyDensity;          // SphBoundary: 1 (delta-SPH) wall contact by distance alone, 0 below rest density too
    float _SolverRelaxation;                // DivergenceFreeSolver: omega of the fluid particles' Jacobi step (SolverRelaxation.cs)

    uint _NeighbourCapacity;                // SphNeighbourhood: entries of each neighbour list, 0 for no lists (NeighbourCapacity.cs)
    uint _NeighbourLanes;                   // NeighbourLanes: threads per particle in the laned neighbour loops, 1, 2, 4 or 8
    uint _NeighbourListRows;                // SphNeighbourhood: order of a list's entries, 1 (DFSPH) or 25, the grid walk's rows (WCSPH)
    float _ChebyshevLow;                    // DivergenceFreeSolver: a, lowest eigenvalue the accelerated solve is tuned for

    float _ChebyshevHigh;                   // DivergenceFreeSolver: b, highest; 0 for the Jacobi solve (ChebyshevBounds.cs)
    uint _AcceleratedDensitySolve;          // DivergenceFreeSolver: 1 when the constant-density solve is accelerated too (ChebyshevBounds.cs)
    float _ViscositySolveLow;               // SphViscositySolve: a, lowest eigenvalue the implicit viscosity solve is tuned for
    float _ViscositySolveHigh;              // SphViscositySolve: b, highest; 0 while the viscosity is explicit (ImplicitViscosity.cs)

    float _ViscositySolveStep;              // SphViscositySolve: h = gamma s, the step each of its two stages solves for, s
    float _ViscositySolveSpan;              // SphViscositySolve: s, the step one solve covers (DFSPH's dt, a WCSPH half kick's dt/2)
    uint _StrainRateViscosity;              // SphViscosity: 1 when the viscous stress is the strain rate's (ViscousStress.cs), 0 Morris's Laplacian
};

// Grid.hlsl reads its three values from here instead of declaring its own.
#define SPHFLUID_GRID_DECLARED

#endif
