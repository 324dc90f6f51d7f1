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

// The walls' part of a wall particle's number density, sum_b' omega_b' W_bb' (weights at the lattice's rest number
// density; BoundaryDensityFactor scales it to the fluid's): it changes only when the walls are placed again. A sphere's own
// shells are not summed but taken at rest from the sampling (BoundarySampling.OwnNumberDensities: weighed up for the fluid
// outside the sphere, they read up to 22 % above rest at its own outer particles), and only the container's lattice is
// summed (CountsInWallSum, SphBoundary.hlsl).
[numthreads(PARTICLE_THREADS, 1, 1)]
void WallNumberDensity(uint3 id : SV_DispatchThreadID)
{
    uint b = id.x;
    if (b >= _BoundaryCount)
        return;
    BoundaryParticle wall = _BoundaryParticles[b];
    int3 home = GridCoordOf(wall.position);
    float sum = _BoundaryOwnNumberDensities[_BoundarySortedSource[b]];
    for (uint row = 0u; row < NEIGHBOUR_WALK_ROWS; row++)
    {
        uint2 walls = BoundaryRowRange(home, row);
        for (uint c = walls.x; c < walls.y; c++)
        {
            BoundaryParticle other = _BoundaryParticles[c];
            if (!CountsInWallSum(wall, other))
                continue;
            float3 r = wall.position - other.position;
            sum += other.weight * Kernel(dot(r, r));
        }
    }
    _WallNumberDensities[b] = sum;
}

#endif
