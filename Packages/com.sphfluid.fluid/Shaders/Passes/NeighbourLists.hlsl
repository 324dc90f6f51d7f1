#ifndef SPHFLUID_PASSES_NEIGHBOUR_LISTS_INCLUDED
#define SPHFLUID_PASSES_NEIGHBOUR_LISTS_INCLUDED

// FluidSolver.compute's FindNeighbours: the neighbour lists of SphNeighbourhood.hlsl, built once after every sort.

// Where list owner `owner` stands: fluid particle i, or wall particle b as owner _ParticleCount + b.
float3 OwnerPosition(uint owner)
{
    if (owner < _ParticleCount) // a branch, not ?:, which would read both buffers, one of them out of bounds
        return _Particles[owner].position;
    return _BoundaryParticles[owner - _ParticleCount].position;
}

// Whether a candidate at y is a neighbour of x, as the passes that read the lists decide it.
bool InSupport(float3 x, float3 y)
{
    float3 r = x - y;
    return dot(r, r) < _SmoothingRadius2;
}

// SphNeighbourhood.hlsl's neighbour lists, after every sort of the fluid or the walls, for one thread an owner: the fluid
// particles first, then the wall particles (their fluid neighbours only: the walls around a wall particle move only with
// it, WallNumberDensity). The distances are computed as the passes that read the lists compute them,
// so a listed neighbour is exactly one the grid walk would have taken. In the grid walk's order (_NeighbourListRows 25)
// the entries follow the walk and each row's ends are written before them; in DFSPH's (1) fluid fills from the front
// and walls from the back. A wall particle with no fluid in its walk's five slabs (FluidWithinReach) lists nothing and
// writes no row words: in a container 60 spacings wide around a droplet of 1 000 particles the search then took 2.4 ms
// a sub-step on lavapipe instead of 6.2 to 8.1 (`sphfluid bench`, two runs each); DamBreak's, whose walls lie near its
// fluid, stayed at 4.1 to 4.5 ms.
void ListOneOwner(uint owner)
{
    if (owner >= _ParticleCount + _BoundaryCount)
        return;
    bool fluidOwner = owner < _ParticleCount;
    float3 x = OwnerPosition(owner);
    int3 home = GridCoordOf(x);
    if (!fluidOwner && !FluidWithinReach(home))
    {
        _FoundNeighbourCounts[owner] = 0u; // NeighbourRows walks no row of it, so its row words need not be written
        return;
    }
    bool walkOrder = _NeighbourListRows != 1u;
    uint fluid = 0u, walls = 0u;
    uint next = walkOrder ? NEIGHBOUR_ROW_WORDS : 0u; // the walk order's next entry
    for (uint row = 0u; row < NEIGHBOUR_WALK_ROWS; row++)
    {
        uint2 range = NeighbourRowRange(home, row);
        for (uint j = range.x; j < range.y; j++)
        {
            if (!InSupport(x, _Particles[j].position))
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
                if (!InSupport(x, _BoundaryParticles[b].position))
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

// The fluid (x) and wall (y) neighbours that lane `lane` finds in the walk around x: candidates lane, lane + lanes, ...
// of every row, as the laned passes visit them. With `store` it also writes them in DFSPH's order, from entries
// `firsts` on: the fluid from the front, the walls from the back.
uint2 WalkOneLane(uint owner, float3 x, bool fluidOwner, uint lane, bool store, uint2 firsts)
{
    int3 home = GridCoordOf(x);
    uint fluid = 0u, walls = 0u;
    for (uint row = 0u; row < NEIGHBOUR_WALK_ROWS; row++)
    {
        uint2 range = NeighbourRowRange(home, row);
        for (uint j = range.x + lane; j < range.y; j += _NeighbourLanes)
        {
            if (!InSupport(x, _Particles[j].position))
                continue;
            if (store)
                StoreNeighbour(owner, firsts.x + fluid, j);
            fluid++;
        }
        if (!fluidOwner)
            continue;
        uint2 wallRange = BoundaryRowRange(home, row);
        for (uint b = wallRange.x + lane; b < wallRange.y; b += _NeighbourLanes)
        {
            if (!InSupport(x, _BoundaryParticles[b].position))
                continue;
            if (store)
                StoreNeighbour(owner, _NeighbourCapacity - 1u - (firsts.y + walls), b);
            walls++;
        }
    }
    return uint2(fluid, walls);
}

groupshared uint2 s_LaneFinds[PARTICLE_THREADS];

// DFSPH's lists with several lanes an owner (NeighbourLanes.hlsl), so that a small scene's search does not wait on one
// thread's walk of 125 cells: each lane counts what it finds, learns from the group how many its owner's lower lanes
// found, and walks again to write its own from there. Twice the distance tests, each walk a lane's share of the
// candidates. The entries come lane by lane rather than in the walk's order, which only DFSPH's order allows: WCSPH
// reads lists in one lane only (NeighbourCapacity.InUse), so its order is never made here.
void ListOwnerInLanes(uint thread, uint groupThread)
{
    uint owners = _ParticleCount + _BoundaryCount;
    uint owner = min(LaneOwner(thread), owners - 1u);
    uint lane = FirstCandidate(thread, owners);
    bool fluidOwner = owner < _ParticleCount;
    float3 x = OwnerPosition(owner);
    bool inReach = fluidOwner;
    if (!inReach)
        inReach = FluidWithinReach(GridCoordOf(x));
    s_LaneFinds[groupThread] = uint2(0u, 0u);
    if (inReach)
        s_LaneFinds[groupThread] = WalkOneLane(owner, x, fluidOwner, lane, false, uint2(0u, 0u));
    GroupMemoryBarrierWithGroupSync();
    uint firstLane = groupThread & ~(_NeighbourLanes - 1u);
    uint2 lower = uint2(0u, 0u), found = uint2(0u, 0u);
    for (uint l = firstLane; l < firstLane + _NeighbourLanes; l++)
    {
        lower += l < groupThread ? s_LaneFinds[l] : uint2(0u, 0u);
        found += s_LaneFinds[l];
    }
    bool fits = found.x + found.y <= _NeighbourCapacity;
    if (fits && inReach)
        WalkOneLane(owner, x, fluidOwner, lane, true, lower);
    if (lane == 0u)
        _FoundNeighbourCounts[owner] = fits ? found.x | (found.y << 16) : NO_NEIGHBOUR_LIST;
}

// Dispatched over the owners times _NeighbourLanes threads.
[numthreads(PARTICLE_THREADS, 1, 1)]
void FindNeighbours(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    if (_NeighbourLanes == 1u)
        ListOneOwner(id.x);
    else
        ListOwnerInLanes(id.x, groupThread.x);
}

#endif
