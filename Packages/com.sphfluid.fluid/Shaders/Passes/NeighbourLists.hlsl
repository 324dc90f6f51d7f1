#ifndef SPHFLUID_PASSES_NEIGHBOUR_LISTS_INCLUDED
#define SPHFLUID_PASSES_NEIGHBOUR_LISTS_INCLUDED

// FluidSolver.compute's FindNeighbours: the neighbour lists of SphNeighbourhood.hlsl, built once after every sort.

// SphNeighbourhood.hlsl's neighbour lists, after every sort of the fluid or the walls: one thread per owner, the fluid
// particles first, then the wall particles (their fluid neighbours only: the walls around a wall particle move only with
// it, WallNumberDensity). The distances are computed as the passes that read the lists compute them,
// so a listed neighbour is exactly one the grid walk would have taken. In the grid walk's order (_NeighbourListRows 25)
// the entries follow the walk and each row's ends are written before them; in DFSPH's (1) fluid fills from the front
// and walls from the back.
[numthreads(PARTICLE_THREADS, 1, 1)]
void FindNeighbours(uint3 id : SV_DispatchThreadID)
{
    uint owner = id.x;
    if (owner >= _ParticleCount + _BoundaryCount)
        return;
    bool fluidOwner = owner < _ParticleCount;
    float3 x;
    if (fluidOwner) // a branch, not ?:, which would read both buffers, one of them out of bounds
        x = _Particles[owner].position;
    else
        x = _BoundaryParticles[owner - _ParticleCount].position;
    int3 home = GridCoordOf(x);
    bool walkOrder = _NeighbourListRows != 1u;
    uint fluid = 0u, walls = 0u;
    uint next = walkOrder ? NEIGHBOUR_ROW_WORDS : 0u; // the walk order's next entry
    for (uint row = 0u; row < NEIGHBOUR_WALK_ROWS; row++)
    {
        uint2 range = NeighbourRowRange(home, row);
        for (uint j = range.x; j < range.y; j++)
        {
            float3 r = x - _Particles[j].position;
            if (dot(r, r) >= _SmoothingRadius2)
                continue;
            if (walkOrder)
            {
                if (next < _NeighbourCapacity)
                    StoreNeighbour(owner, next, j);
                next++;
            }
            else if (fluid + walls < _NeighbourCapacity)
                StoreNeighbour(owner, fluid, j);
            fluid++;
        }
        uint fluidEnd = next;
        if (fluidOwner)
        {
            uint2 wallRange = BoundaryRowRange(home, row);
            for (uint b = wallRange.x; b < wallRange.y; b++)
            {
                float3 r = x - _BoundaryParticles[b].position;
                if (dot(r, r) >= _SmoothingRadius2)
                    continue;
                if (walkOrder)
                {
                    if (next < _NeighbourCapacity)
                        StoreNeighbour(owner, next, b);
                    next++;
                }
                else if (fluid + walls < _NeighbourCapacity)
                    StoreNeighbour(owner, _NeighbourCapacity - 1u - walls, b);
                walls++;
            }
        }
        if (walkOrder && next <= _NeighbourCapacity)
            StoreNeighbour(owner, row, fluidEnd | (next << 16));
    }
    bool fits = walkOrder ? next <= _NeighbourCapacity : fluid + walls <= _NeighbourCapacity;
    _FoundNeighbourCounts[owner] = fits ? fluid | (walls << 16) : NO_NEIGHBOUR_LIST;
}

#endif
