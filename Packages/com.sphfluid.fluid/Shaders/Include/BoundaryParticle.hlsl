#ifndef SPHFLUID_BOUNDARY_PARTICLE_INCLUDED
#define SPHFLUID_BOUNDARY_PARTICLE_INCLUDED

// One boundary particle (SphFluid.Simulation.BoundaryParticle in C#): the container's walls and every
// obstacle are sampled with these by the engine-free core (BoundarySampling.cs). Same 32-byte layout as
// Particle (position first), so the particle sort orders them unchanged.
//   rest buffer:   position = in the owner's frame (container-local, or relative to the sphere's centre)
//   placed/sorted: position and velocity in world space
struct BoundaryParticle
{
    float3 position; // m
    float weight;    // omega = V_b / s^3: how many fluid particles on the rest lattice it stands for
    float3 velocity; // m/s (the wall's velocity at that point)
    uint owner;      // BOUNDARY_OWNER_CONTAINER, or the obstacle index
};

#define BOUNDARY_OWNER_CONTAINER 0xFFFFFFFFu

#endif
