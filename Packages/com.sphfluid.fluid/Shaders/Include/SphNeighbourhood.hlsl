#ifndef SPHFLUID_SPH_NEIGHBOURHOOD_INCLUDED
#define SPHFLUID_SPH_NEIGHBOURHOOD_INCLUDED

#include "FluidConstants.hlsl" // first: the grid lives in the constant buffer
#include "Grid.hlsl"

// The neighbour search over cell-sorted particles (uniform grid, Green 2008; Ihmsen et al. 2011), in cells of
// H / CELLS_PER_SUPPORT: every neighbour within H lies within CELLS_PER_SUPPORT cells of a particle's own on each
// axis, so the walk covers a cube of NEIGHBOUR_ROW_CELLS^3 cells (5 x 5 x 5 of H/2). Because the counting sort stores
// cells in linear order (x fastest), the cells of one row (x-2 .. x+2 at fixed y, z) hold ONE contiguous range of
// sorted particles: [CellStart[x-2], CellStart[x+2] + CellCount[x+2]). So the cube is visited as NEIGHBOUR_WALK_ROWS
// (25) ranges, with a fifth of the bookkeeping and longer, better-predicted inner loops. Fluid and boundary particles
// live in the same grid, each sorted into its own buffer with its own CellStart/CellCount.
// Cells of H/2, not H: the 125 cells of H/2 hold 58 % of the volume of the 27 cells of H, so every walk tests about
// 3.7 candidates per neighbour instead of 6.4, the same for every particle (so the lanes of a loop stay in step). On an
// NVIDIA H200 at 1M particles (OilAndWater) WCSPH's sub-step took 4.65 ms instead of 6.27 (FindNeighbours 1.63 instead
// of 2.62, Forces 1.09 instead of 1.30, DensityRate 0.94 instead of 1.16) and DFSPH's 34.6 instead of 37.2. On lavapipe
// at 4 160 particles FindNeighbours costs about a fifth less and the whole sub-step about 5 % less: neighbouring
// particles no longer share one cell's ranges, and 25 rows cost more bookkeeping than 9 (Headless/experiments/
// half-support-cells.patch, Headless/docs/accuracy-for-time.md). The price is 8 times the cells for a container
// (CellGrid.MaxCellCount).
// Usage: for (uint row = 0u; row < NEIGHBOUR_WALK_ROWS; row++)
//            { uint2 range = NeighbourRowRange(home, row); for (j in range) ... }
//
// Neighbour lists. DFSPH's solves visit every particle's neighbourhood twice per iteration, at positions that do not
// change between the sort and the next drift, so (as Bender & Koschier 2017, "Divergence-Free SPH for Incompressible
// and Viscous Fluids", do with the result of their neighbour search) the neighbours are found once per sort
// (FindNeighbours, Passes/NeighbourLists.hlsl) and read from a list by every pass until the next drift. A wide support
// makes the difference: at 2.85 spacings the walk's cells hold about 3.7 candidates per neighbour. WCSPH's four
// neighbour passes of a sub-step (density, wall pressure, forces, and delta-SPH's rate before the next drift) read the
// same lists when each particle's loops run in one lane; with more lanes (NeighbourLanes.hlsl) the walk is already
// split, and FindNeighbours, which keeps the walk's order only in one lane per owner (DFSPH's lists it finds in lanes,
// lane by lane), would add a whole walk to the sub-step (NeighbourCapacity.cs). Each
// list owner (fluid particle i, or wall particle b as owner _ParticleCount + b) has _NeighbourCapacity entries; entry k
// of owner o is at k * (_ParticleCount + _BoundaryCount) + o, so that the threads of a group read neighbouring words.
// The entries come in one of two orders (_NeighbourListRows, NeighbourCapacity.cs):
//   1 (DFSPH)  fluid neighbours (the particle itself among them, as in the grid walk) fill the entries from the front,
//              wall neighbours from the back: one range each;
//   25 (WCSPH) the grid walk's own order, row by row, each row's fluid neighbours and then its walls, after
//              NEIGHBOUR_ROW_WORDS words that hold where each row's fluid and walls end. A pass then visits the
//              neighbours in the order the grid walk would, and sums them in that order, so reading a list changes no
//              result, not even by rounding: in one lane WCSPH gives the grid walk's results to the bit.
// An owner with more neighbours than entries is marked NO_NEIGHBOUR_LIST and walks the grid, so a crowded particle
// costs time, never a neighbour; so does every particle when _NeighbourCapacity is 0 (no lists in use).
// Usage: NeighbourList list = ListOf(i); for (uint row = 0u; row < NeighbourRows(list); row++)
//            { uint2 range = FluidNeighbours(list, home, row); for (k in range) { uint j = Neighbour(list, k); ... } }

StructuredBuffer<uint> _CellStart;         // fluid: first sorted particle of each cell (exclusive prefix sum of the counts)
StructuredBuffer<uint> _CellCount;         // fluid: particles in each cell
StructuredBuffer<uint> _BoundaryCellStart; // boundary particles: the same per cell
StructuredBuffer<uint> _BoundaryCellCount;

// Read-only where the lists are read, so that they take no UAV slot there (D3D11 gives a kernel 8); FindNeighbours
// writes the same two buffers under the names below.
StructuredBuffer<uint> _NeighbourCounts;       // per owner: fluid neighbours | wall neighbours << 16, or NO_NEIGHBOUR_LIST
StructuredBuffer<uint> _NeighbourLists;        // sorted indices of the owners' neighbours (layout above)
RWStructuredBuffer<uint> _FoundNeighbourCounts;
RWStructuredBuffer<uint> _FoundNeighbourLists;

#define NO_NEIGHBOUR_LIST 0xFFFFFFFFu

// Cells of the grid to the support radius H, so the cells the walk reaches on each side of a particle's own; the C#
// CellGrid.CellsPerSupport, which makes the cells, must match (checked by NeighbourListOrderTests).
#define CELLS_PER_SUPPORT 2u
// Cells in one row of the walk, along x.
#define NEIGHBOUR_ROW_CELLS (2u * CELLS_PER_SUPPORT + 1u)
// Rows of the walk, one for each y and z it reaches.
#define NEIGHBOUR_WALK_ROWS (NEIGHBOUR_ROW_CELLS * NEIGHBOUR_ROW_CELLS)

// The row order's first words: entry r holds the end of row r's fluid neighbours | the end of its walls << 16
// (NeighbourCapacity.RowWords).
#define NEIGHBOUR_ROW_WORDS NEIGHBOUR_WALK_ROWS

// First and last cell of row `row` (0 .. NEIGHBOUR_WALK_ROWS - 1: dy, dz in -CELLS_PER_SUPPORT .. CELLS_PER_SUPPORT)
// around cell `home`; false outside the grid.
bool NeighbourRowCells(int3 home, uint row, out uint firstCell, out uint lastCell)
{
    int reach = (int)CELLS_PER_SUPPORT;
    int3 c = home + int3(0, (int)(row % NEIGHBOUR_ROW_CELLS) - reach, (int)(row / NEIGHBOUR_ROW_CELLS) - reach);
    int top = (int)_GridDims.x - 1;
    int3 first = int3(max(c.x - reach, 0), c.y, c.z);
    int3 last = int3(min(c.x + reach, top), c.y, c.z);
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

// The walk's slabs: slab s holds rows s * NEIGHBOUR_ROW_CELLS .. + NEIGHBOUR_ROW_CELLS - 1 (one z, every y), whose cells
// all lie in one range of linear cells, from its first row's first cell to its last row's last. No particle in that range
// means none in any of the slab's rows, read from two cells. The range spans the grid's whole x-rows between, so a slab
// may read occupied and still hold no neighbour.
bool NeighbourSlabCells(int3 home, uint slab, out uint firstCell, out uint lastCell)
{
    int reach = (int)CELLS_PER_SUPPORT;
    int3 top = (int3)_GridDims - int3(1, 1, 1);
    int3 first = int3(max(home.x - reach, 0), max(home.y - reach, 0), home.z + (int)slab - reach);
    int3 last = int3(min(home.x + reach, top.x), min(home.y + reach, top.y), first.z);
    firstCell = 0u;
    lastCell = 0u;
    if (first.z < 0 || first.z > top.z)
        return false;
    firstCell = CellIndexOf(first);
    lastCell = CellIndexOf(last);
    return true;
}

// Whether any fluid particle may lie in the walk around cell `home`; false means none does. A container's wall particles
// away from the fluid (most of a tall or wide one's) learn from five slabs that they have no neighbour, instead of from 25
// rows.
bool FluidWithinReach(int3 home)
{
    for (uint slab = 0u; slab < NEIGHBOUR_ROW_CELLS; slab++)
    {
        uint firstCell, lastCell;
        if (NeighbourSlabCells(home, slab, firstCell, lastCell))
        {
            if (_CellStart[lastCell] + _CellCount[lastCell] > _CellStart[firstCell])
                return true;
        }
    }
    return false;
}

// The list of owner `owner` (fluid particle i, or _ParticleCount + wall particle b).
struct NeighbourList
{
    bool listed;  // false: walk the grid's NEIGHBOUR_WALK_ROWS rows
    uint fluid;   // fluid neighbours (DFSPH's order: in entries [0, fluid))
    uint walls;   // wall neighbours (DFSPH's order: in entries [_NeighbourCapacity - walls, _NeighbourCapacity))
    uint owner;
    uint ends;    // the grid walk's order: the row ends of row endsRow, read once per row
    uint endsRow;
};

// The buffer reads below sit in branches, not in ?: (whose operands HLSL evaluates both): without lists the buffers hold
// one word, and an index past it reads out of bounds, which Vulkan and Metal leave undefined; and a listed particle
// need not look up the grid's cells.
NeighbourList ListOf(uint owner)
{
    NeighbourList list;
    uint word = NO_NEIGHBOUR_LIST;
    if (_NeighbourCapacity > 0u)
        word = _NeighbourCounts[owner];
    list.listed = word != NO_NEIGHBOUR_LIST;
    list.fluid = word & 0xFFFFu;
    list.walls = word >> 16;
    list.owner = owner;
    list.ends = 0u;
    list.endsRow = 0xFFFFFFFFu;
    return list;
}

// The grid's rows, or a list's: one range (DFSPH's order) or the grid's (the grid walk's); none for an owner that found
// no neighbour at all. That is a wall particle with no fluid in reach (a fluid particle lists itself): most of a tall or
// wide container's walls, which read a row word for each of 25 empty rows in every pass over the walls while they were
// walked. On lavapipe that halved WallPressure in DamBreak (0.94 and 0.77 ms a sub-step against 0.38 and 0.45 in two
// runs each of `sphfluid bench Assets/FluidDemo/Scenes/DamBreak.unity --particles 1440 --steps 40 --skip-savings`).
uint NeighbourRows(NeighbourList list)
{
    if (!list.listed)
        return NEIGHBOUR_WALK_ROWS;
    return list.fluid + list.walls == 0u ? 0u : _NeighbourListRows;
}

// Row `row`'s ends in a list of the grid walk's order, kept in the list: a pass that visits the rows in order, each
// row's fluid and then its walls, reads each row's word once.
void ReadRowEnds(inout NeighbourList list, uint row)
{
    if (list.endsRow != row)
        list.ends = _NeighbourLists[row * (_ParticleCount + _BoundaryCount) + list.owner];
    list.endsRow = row;
}

// Entries (listed) or sorted fluid particles (grid) of row `row`: Neighbour(list, k) for k in [x, y).
uint2 FluidNeighbours(inout NeighbourList list, int3 home, uint row)
{
    if (!list.listed)
        return NeighbourRowRange(home, row);
    if (_NeighbourListRows == 1u)
        return uint2(0u, list.fluid);
    uint start = NEIGHBOUR_ROW_WORDS;
    if (row > 0u)
    {
        ReadRowEnds(list, row - 1u); // kept from the last row's walls when the rows come in order
        start = list.ends >> 16;
    }
    ReadRowEnds(list, row);
    return uint2(start, list.ends & 0xFFFFu);
}

// The same for the wall particles.
uint2 WallNeighbours(inout NeighbourList list, int3 home, uint row)
{
    if (!list.listed)
        return BoundaryRowRange(home, row);
    if (_NeighbourListRows == 1u)
        return uint2(_NeighbourCapacity - list.walls, _NeighbourCapacity);
    ReadRowEnds(list, row);
    return uint2(list.ends & 0xFFFFu, list.ends >> 16);
}

// The sorted index of entry k: read from the list, or k itself on the grid.
uint Neighbour(NeighbourList list, uint k)
{
    if (list.listed)
        return _NeighbourLists[k * (_ParticleCount + _BoundaryCount) + list.owner];
    return k;
}

// Writes entry k of owner `owner` (FindNeighbours).
void StoreNeighbour(uint owner, uint k, uint index)
{
    _FoundNeighbourLists[k * (_ParticleCount + _BoundaryCount) + owner] = index;
}

#endif
