#ifndef SPHFLUID_NEIGHBOUR_LANES_INCLUDED
#define SPHFLUID_NEIGHBOUR_LANES_INCLUDED

#include "FluidConstants.hlsl"

// One particle's neighbourhood walked by several threads ("lanes"), then summed across them in groupshared memory. A
// neighbour loop visits a few hundred candidates one after another, each a dependent memory read, so a pass over a few
// thousand particles takes as long as its slowest thread's walk however many cores stand idle: on an H100 and an H200
// alike a WCSPH sub-step of 1 080 particles cost 0.77 ms and one of 68 000 0.95 ms (Headless/docs/accuracy-for-time.md,
// "Real time where it counts"). With _NeighbourLanes threads per particle, lane l takes candidates l, l + lanes, ... of
// every range, which shortens the walk by the lane count while the GPU has threads to spare; a full GPU gains nothing,
// so the host picks the lanes from the particle count (NeighbourLanes.cs), and 1 on a CPU device, whose cores do not
// hide latency behind other threads. The sums are the same up to float rounding, in another order.
// Usage, in a kernel dispatched over owners * _NeighbourLanes threads of PARTICLE_THREADS (a multiple of the lanes):
//   uint owner = min(LaneOwner(id.x), count - 1u), lane = FirstCandidate(id.x, count);
//   for (uint k = range.x + lane; k < range.y; k += _NeighbourLanes) ...;
//   float4 sum = SumOverLanes(partial, groupThread);   // every thread of the group, no early return before it
//   if (lane == 0u) write.

#define MAX_NEIGHBOUR_LANES 8u

groupshared float4 s_LaneSums[PARTICLE_THREADS];

uint LaneOwner(uint thread)
{
    return thread / _NeighbourLanes;
}

uint LaneOf(uint thread)
{
    return thread & (_NeighbourLanes - 1u);
}

// A start past the end of every candidate range (which hold fewer than 2^31 entries, so the sum cannot wrap).
#define IDLE_LANE 0x7fffffffu

// The offset of this thread's first candidate in each range: its lane, or IDLE_LANE for a thread with nothing to walk
// (past the last of `owners`, in the last group, or an owner left out of the pass), which must still reach
// SumOverLanes's barriers but would otherwise walk the last owner's neighbourhood for nothing. Only a lane 0 of an owner
// with work gets 0, so `lane == 0u` alone picks the thread that writes.
uint FirstCandidate(uint thread, uint owners)
{
    return LaneOwner(thread) < owners ? LaneOf(thread) : IDLE_LANE;
}

// The sum of `partial` over the lanes of this thread's owner, returned to all of them. A tree over aligned runs of
// _NeighbourLanes slots; its barriers sit outside every branch that depends on the thread, behind only the uniform
// one-lane return, which spares a CPU device (one lane) the barriers: they cost lavapipe 9 % of an OilAndWater sub-step.
float4 SumOverLanes(float4 partial, uint groupThread)
{
    if (_NeighbourLanes == 1u)
        return partial;
    s_LaneSums[groupThread] = partial;
    GroupMemoryBarrierWithGroupSync();
    [unroll]
    for (uint stride = MAX_NEIGHBOUR_LANES / 2u; stride > 0u; stride >>= 1u)
    {
        if (stride < _NeighbourLanes && (groupThread & (_NeighbourLanes - 1u)) < stride)
            s_LaneSums[groupThread] += s_LaneSums[groupThread + stride];
        GroupMemoryBarrierWithGroupSync();
    }
    float4 total = s_LaneSums[groupThread & ~(_NeighbourLanes - 1u)];
    GroupMemoryBarrierWithGroupSync(); // a second sum in the same kernel overwrites the slots read here
    return total;
}

#endif
