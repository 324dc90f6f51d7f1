#ifndef SPHFLUID_SPH_NEIGHBOURHOOD_INCLUDED
#define SPHFLUID_SPH_NEIGHBOURHOOD_INCLUDED

#include "Grid.hlsl"

// The 27-cell neighbour search over the cell-sorted particles (uniform grid of cell size h, Green
// 2008; Ihmsen et al. 2011). Because the counting sort stores cells in linear order (x fastest), the
// three cells of one row (x-1, x, x+1 at fixed y, z) hold ONE contiguous range of sorted particles:
// [CellStart[x-1], CellStart[x+1] + CellCount[x+1]). So the 27 cells are visited as 9 ranges, with a
// third of the bookkeeping and longer, better-predicted inner loops.
// Usage: for (uint row = 0u; row < 9u; row++) { uint2 range = NeighbourRowRange(home, row); for (j in range) ... }

StructuredBuffer<uint> _CellStart; // first sorted particle of each cell (exclusive prefix sum of the counts)
StructuredBuffer<uint> _CellCount; // particles in each cell

// Sorted-particle range [x, y) of row `row` (0..8: dy, dz in -1..1) around cell `home`; empty outside the grid.
uint2 NeighbourRowRange(int3 home, uint row)
{
    int3 c = home + int3(0, (int)(row % 3u) - 1, (int)(row / 3u) - 1);
    int top = (int)_GridDims.x - 1;
    int3 first = int3(max(c.x - 1, 0), c.y, c.z);
    int3 last = int3(min(c.x + 1, top), c.y, c.z);
    if (!GridCoordInside(first))
        return uint2(0u, 0u);
    uint firstCell = CellIndexOf(first);
    uint lastCell = CellIndexOf(last);
    return uint2(_CellStart[firstCell], _CellStart[lastCell] + _CellCount[lastCell]);
}

#endif
