#ifndef SPHFLUID_PASSES_WALLS_INCLUDED
#define SPHFLUID_PASSES_WALLS_INCLUDED

// FluidSolver.compute's passes for walls that moved (SphBoundary.hlsl): PlaceBoundary carries each boundary particle
// from its owner's frame to the world; WallNumberDensity sums the walls' own part of a wall particle's number density
// (DFSPH) once they are sorted.

[numthreads(PARTICLE_THREADS, 1, 1)]
void PlaceBoundary(uint3 id : SV_DispatchThreadID)
{
    uint b = id.x;
    if (b >= _BoundaryCount)
        return;
    _BoundaryPlaced[b] = PlaceBoundaryParticle(_BoundaryRest[b]);
}

// The walls' own part of a wall particle's number density, sum_b' omega_b' W_bb' (weights at the lattice's rest number
// density; BoundaryDensityFactor scales it to the fluid's): it changes only when the walls are placed again.
[numthreads(PARTICLE_THREADS, 1, 1)]
void WallNumberDensity(uint3 id : SV_DispatchThreadID)
{
    uint b = id.x;
    if (b >= _BoundaryCount)
        return;
    float3 xb = _BoundaryParticles[b].position;
    int3 home = GridCoordOf(xb);
    float sum = 0.0;
    for (uint row = 0u; row < 9u; row++)
    {
        uint2 walls = BoundaryRowRange(home, row);
        for (uint c = walls.x; c < walls.y; c++)
        {
            BoundaryParticle other = _BoundaryParticles[c];
            float3 r = xb - other.position;
            sum += other.weight * Kernel(dot(r, r));
        }
    }
    _WallNumberDensities[b] = sum;
}

#endif
