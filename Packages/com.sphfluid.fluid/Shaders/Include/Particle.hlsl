#ifndef SPHFLUID_PARTICLE_INCLUDED
#define SPHFLUID_PARTICLE_INCLUDED

// One SPH particle (SphFluid.Simulation.Particle in C#): two 16-byte groups so that the
// structured-buffer stride is 32 bytes under D3D11/12 and Vulkan std430 alike.
struct Particle
{
    float3 position; // world space, m
    uint phase;      // index into the phase table
    float3 velocity; // world space, m/s
    uint id;         // identity from spawn; particles are re-sorted by cell every step
};

#endif
