#ifndef SPHFLUID_SPH_NEIGHBOURHOOD_INCLUDED
#define SPHFLUID_SPH_NEIGHBOURHOOD_INCLUDED

#include "FluidConstants.hlsl" // first: the grid lives in the constant buffer
#include "Grid.hlsl"

// The 27-cell neighbour search over cell-sorted particles (uniform grid of cell size H, Green 2008; Ihmsen
// et al. 2011). Because the counting sort stores cells in linear order (x fastest), the three cells of one
// row (x-1, x, x+1 at fixed y, z) hold ONE contiguous range of sorted particles:
// [CellStart[x-1], CellStart[x+1] + CellCount[x+1]). So the 27 cells are visited as 9 ranges, with a third
// of the bookkeeping and longer, better-predicted inner loops. Fluid and boundary particles live in the
// same grid, each sorted into its own buffer with its own CellStart/CellCount.
// Usage: for (uint row = 0u; row < 9u; row++) { uint2 range = NeighbourRowRange(home, row); for (j in range) ... }

StructuredBuffer<uint> _CellStart;         // fluid: first sorted particle of each cell (exclusive prefix sum of the counts)
StructuredBuffer<uint> _CellCount;         // fluid: particles in each cell
StructuredBuffer<uint> _BoundaryCellStart; // boundary particles: the same per cell
StructuredBuffer<uint> _BoundaryCellCount;

// First and last cell of row `row` (0..8: dy, dz in -1..1) around cell `home`; false outside the grid.
bool NeighbourRowCells(int3 home, uint row, out uint firstCell, out uint lastCell)
{
    int3 c = home + int3(0, (int)(row % 3u) - 1, (int)(row / 3u) - 1);
    int top = (int)_GridDims.x - 1;
    int3 first = int3(max(c.x - 1, 0), c.y, c.z);
    int3 last = int3(min(c.x + 1, top), c.y, c.z);
    firstCell = 0u;
    lastCell = 0u;
    if (!GridCoordInside(first))
        return false;
    firstCell = CellIndexOf(first);
    lastCell = CellIndexOf(last);
    return true;
}

// Sorted fluid-particle range [x, y) of row `row` around cell `home`; empty outside the grid.
uint2 NeighbourRowRange(int3 home, uint row)
{
    uint firstCell, lastCell;
    if (!NeighbourRowCells(home, row, firstCell, lastCell))
        return uint2(0u, 0u);
    return uint2(_CellStart[firstCell], _CellStart[lastCell] + _CellCount[lastCell]);
}

// Sorted boundary-particle range [x, y) of row `row` around cell `home`; empty outside the grid.
uint2 BoundaryRowRange(int3 home, uint row)
{
    uint firstCell, lastCell;
    if (!NeighbourRowCells(home, row, firstCell, lastCell))
        return uint2(0u, 0u);
    return uint2(_BoundaryCellStart[firstCell], _BoundaryCellStart[lastCell] + _BoundaryCellCount[lastCell]);
}

#endif
