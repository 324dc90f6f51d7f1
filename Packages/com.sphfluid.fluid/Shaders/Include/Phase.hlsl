#ifndef SPHFLUID_PHASE_INCLUDED
#define SPHFLUID_PHASE_INCLUDED

// One row of the phase table (SphFluid.Simulation.PhaseProperties in C#), indexed by
// Particle.phase. Three 16-byte groups: stride 48 under D3D and Vulkan std430 alike.
struct PhaseProperties
{
    float restDensity;    // rho0, kg/m^3
    float viscosity;      // mu, Pa s
    float particleMass;   // kg
    float surfaceTension; // sigma, N/m (SphSurfaceTension)
    float4 color;         // linear RGB tint, opacity
    float fresnelF0;      // Schlick reflectance at normal incidence
    float absorption;     // Beer-Lambert coefficient, 1/m
    float wallWeightScale; // (rho0 / m) / the lattice's delta0: the walls' omega at this phase's rest (SphBoundary's WallWeight)
    float inverseParticleCount; // 1 / the phase's particle count: its average in the DFSPH solves' stop rule (FoldSolveErrors)
};

#endif
