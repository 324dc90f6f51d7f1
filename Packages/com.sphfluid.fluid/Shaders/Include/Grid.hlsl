#ifndef SPHFLUID_GRID_INCLUDED
#define SPHFLUID_GRID_INCLUDED

// The uniform neighbour grid of the SPH solver (cell size = h / CELLS_PER_SUPPORT, half the support radius h;
// SphNeighbourhood.hlsl says why), built in CONTAINER-LOCAL space so that rotating the container never resizes it.
// Uniform-grid neighbour search after Green 2008 ("Particle Simulation using CUDA", NVIDIA) and Ihmsen et al. 2011
// ("A parallel SPH implementation on multi-core CPUs"): with cells of size h/2, every neighbour j of particle i
// (r_ij < h) lies in the 5x5x5 block of cells around i's cell.
//
//   g    = mul(_WorldToGrid, float4(x, 1)).xyz        (grid units: one unit = one cell, h/2)
//   cell = clamp(floor(g), 0, _GridDims - 1)
//   linear index = cell.x + _GridDims.x * (cell.y + _GridDims.y * cell.z)
//   _WorldToGrid = scale(1/cell) * translate(S/2 + margin*cell) * R^T * translate(-c)
// (container centre c, rotation R, size S; two margin cells, one h, on every side). Positions outside the
// grid clamp into its border cells, so every particle, even a NaN one, has a valid cell.
//
// The solver reads the grid from its constant buffer (FluidConstants.hlsl, included first); the cell sort sets
// its own copy (SphFluid.Sorting.CellGrid.SetOn), declared here. The cell sort (ParticleSort.compute) provides _CellStart /
// _CellCount per linear cell; the neighbour loops themselves are in SphNeighbourhood.hlsl, which visits
// the 125 cells around a particle as 25 contiguous x-rows of the sorted buffer.

#ifndef SPHFLUID_GRID_DECLARED
float4x4 _WorldToGrid; // world -> grid units (column vectors, translation in the last column)
uint3 _GridDims;       // cells per local axis, margin included
uint _GridCellCount;   // _GridDims.x * _GridDims.y * _GridDims.z
#endif

// The cell holding world position worldPos. Clamps in float first (so huge coordinates cannot
// overflow the int conversion) and again in int (so a NaN, whose conversion is undefined, still lands
// in the grid).
int3 GridCoordOf(float3 worldPos)
{
    float3 g = mul(_WorldToGrid, float4(worldPos, 1.0)).xyz;
    int3 top = (int3)_GridDims - int3(1, 1, 1);
    int3 coord = (int3)clamp(floor(g), float3(0.0, 0.0, 0.0), (float3)top);
    return clamp(coord, int3(0, 0, 0), top);
}

bool GridCoordInside(int3 coord)
{
    return all(coord >= int3(0, 0, 0)) && all(coord < (int3)_GridDims);
}

// Linear index of an in-grid coordinate: x fastest, then y, then z.
uint CellIndexOf(int3 coord)
{
    uint3 c = (uint3)coord;
    return c.x + _GridDims.x * (c.y + _GridDims.y * c.z);
}

#endif
