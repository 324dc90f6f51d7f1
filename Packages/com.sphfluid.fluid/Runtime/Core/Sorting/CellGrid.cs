using System;
using System.Globalization;
using System.Numerics;
using SphFluid.Compute;

namespace SphFluid.Sorting
{
    /// <summary>
    /// The solver's uniform neighbour grid: cubic cells of the support radius h, laid out in the
    /// container's LOCAL frame (so a rotating container never resizes it), with one margin cell on
    /// every side so that particles pushed slightly through a wall still map to a sensible cell.
    /// The C# twin of Shaders/Include/Grid.hlsl; <see cref="SetOn"/> uploads its globals.
    /// </summary>
    /// <remarks>
    /// Grid coordinate of world point x: g = WorldToGrid * (x, 1) with
    /// WorldToGrid = scale(1/h) * translate(S/2 + margin h) * R^T * translate(-c), cell = clamp(floor(g), 0, dims - 1),
    /// linear index = x + dims.x (y + dims.y z).
    /// </remarks>
    public sealed class CellGrid
    {
        /// <summary>Most cells a grid may have: 2^25 (32M). Each per-cell uint buffer is then 128 MiB, the
        /// largest storage buffer D3D11 and lavapipe guarantee to bind.</summary>
        public const int MaxCellCount = 1 << 25;

        /// <summary>Cells added on each side of every axis beyond the container.</summary>
        public const int MarginCells = 1;

        public CellGrid(Vector3 containerCentre, Quaternion containerRotation, Vector3 containerSize, float cellSize)
        {
            if (!(cellSize > 0f) || !float.IsFinite(cellSize))
                throw new ArgumentOutOfRangeException(nameof(cellSize), cellSize,
                    Format("CellGrid: cell size (the smoothing radius h) must be a finite number > 0 m (was {0})", cellSize));
            if (!(containerSize.X > 0f && containerSize.Y > 0f && containerSize.Z > 0f) || !IsFinite(containerSize))
                throw new ArgumentOutOfRangeException(nameof(containerSize), containerSize,
                    Format("CellGrid: container size must be finite and > 0 m on every axis (was {0})", containerSize));

            double dx = CellsAlong(containerSize.X, cellSize);
            double dy = CellsAlong(containerSize.Y, cellSize);
            double dz = CellsAlong(containerSize.Z, cellSize);
            double cells = dx * dy * dz;
            if (cells > MaxCellCount)
                throw new ArgumentOutOfRangeException(nameof(cellSize), cellSize,
                    Format("CellGrid: container size {0} m with smoothing radius h = {1} m needs {2} x {3} x {4} = {5:E2} cells " +
                           "(one margin cell per side included), more than the {6} allowed; raise the smoothing radius or shrink the container",
                        containerSize, cellSize, dx, dy, dz, cells, MaxCellCount));

            Size = containerSize;
            CellSize = cellSize;
            DimX = (int)dx;
            DimY = (int)dy;
            DimZ = (int)dz;
            CellCount = DimX * DimY * DimZ;
            Place(containerCentre, containerRotation);
        }

        /// <summary>Moves the grid with its container (same size and cells): a container that moves or turns keeps its
        /// fluid inside the grid instead of clamped into the border cells. Particles sorted on the old placement must be
        /// sorted again before a neighbour loop reads them.</summary>
        public void Place(Vector3 containerCentre, Quaternion containerRotation)
        {
            if (!IsFinite(containerCentre))
                throw new ArgumentOutOfRangeException(nameof(containerCentre), containerCentre,
                    Format("CellGrid: container centre must be finite (was {0})", containerCentre));
            float rotationLength = containerRotation.Length();
            if (!(rotationLength > 1e-6f) || !float.IsFinite(rotationLength))
                throw new ArgumentOutOfRangeException(nameof(containerRotation), containerRotation,
                    Format("CellGrid: container rotation must be a non-zero finite quaternion (was {0})", containerRotation));
            Centre = containerCentre;
            Rotation = Quaternion.Normalize(containerRotation);

            // Composed in System.Numerics' row-vector order (applied left to right), then transposed into
            // the interface's column-vector convention (translation in M14/M24/M34).
            Vector3 originOffset = Size * 0.5f + new Vector3(MarginCells * CellSize);
            Matrix4x4 rowVector = Matrix4x4.CreateTranslation(-containerCentre)
                                  * Matrix4x4.CreateFromQuaternion(Quaternion.Conjugate(Rotation))
                                  * Matrix4x4.CreateTranslation(originOffset)
                                  * Matrix4x4.CreateScale(1f / CellSize);
            worldToGridRows = rowVector;
            WorldToGrid = Matrix4x4.Transpose(rowVector);
        }

        public Vector3 Centre { get; private set; }

        /// <summary>The container's rotation, normalised.</summary>
        public Quaternion Rotation { get; private set; }

        public Vector3 Size { get; }

        /// <summary>Edge of a cell, m: the support radius h.</summary>
        public float CellSize { get; }

        public int DimX { get; }
        public int DimY { get; }
        public int DimZ { get; }

        /// <summary>DimX * DimY * DimZ.</summary>
        public int CellCount { get; }

        /// <summary>World to grid units for column vectors (<c>mul(_WorldToGrid, float4(x, 1))</c>).</summary>
        public Matrix4x4 WorldToGrid { get; private set; }

        private Matrix4x4 worldToGridRows;
        private IComputeDevice idsDevice;
        private int worldToGridId, gridDimsId, gridCellCountId;
        // SetInts takes params int[]: one array for the grid's lifetime, not one per sub-step.
        private readonly int[] dims = new int[3];

        /// <summary>Grid coordinates (units of h, before flooring) of a world point.</summary>
        public Vector3 GridPositionOf(Vector3 world)
        {
            return Vector3.Transform(world, worldToGridRows);
        }

        /// <summary>The cell holding a world point, clamped into the grid as Grid.hlsl's GridCoordOf does.</summary>
        public void CellCoordOf(Vector3 world, out int x, out int y, out int z)
        {
            Vector3 g = GridPositionOf(world);
            x = ClampFloor(g.X, DimX);
            y = ClampFloor(g.Y, DimY);
            z = ClampFloor(g.Z, DimZ);
        }

        /// <summary>Linear cell index: x fastest, then y, then z (Grid.hlsl's CellIndexOf).</summary>
        public int CellIndexOf(int x, int y, int z)
        {
            if ((uint)x >= (uint)DimX || (uint)y >= (uint)DimY || (uint)z >= (uint)DimZ)
                throw new ArgumentOutOfRangeException(nameof(x),
                    Format("CellGrid: cell ({0}, {1}, {2}) is outside the grid {3} x {4} x {5}", x, y, z, DimX, DimY, DimZ));
            return x + DimX * (y + DimY * z);
        }

        /// <summary>Linear index of the cell holding a world point.</summary>
        public int CellIndexOf(Vector3 world)
        {
            CellCoordOf(world, out int x, out int y, out int z);
            return x + DimX * (y + DimY * z);
        }

        /// <summary>Uploads <c>_WorldToGrid</c>, <c>_GridDims</c> and <c>_GridCellCount</c> (Grid.hlsl) for
        /// later dispatches of <paramref name="program"/>.</summary>
        public void SetOn(IComputeDevice device, IComputeProgram program)
        {
            if (device == null) throw new ArgumentNullException(nameof(device));
            if (program == null) throw new ArgumentNullException(nameof(program));
            if (!ReferenceEquals(device, idsDevice))
            {
                worldToGridId = device.PropertyId("_WorldToGrid");
                gridDimsId = device.PropertyId("_GridDims");
                gridCellCountId = device.PropertyId("_GridCellCount");
                idsDevice = device;
            }
            device.SetMatrix(program, worldToGridId, WorldToGrid);
            dims[0] = DimX;
            dims[1] = DimY;
            dims[2] = DimZ;
            device.SetInts(program, gridDimsId, dims);
            device.SetInt(program, gridCellCountId, CellCount);
        }

        public override string ToString()
        {
            return Format("CellGrid {0} x {1} x {2} cells of h = {3} m", DimX, DimY, DimZ, CellSize);
        }

        private static double CellsAlong(float size, float cellSize)
        {
            return Math.Ceiling((double)size / cellSize) + 2 * MarginCells;
        }

        private static int ClampFloor(float g, int dim)
        {
            double f = Math.Floor((double)g);
            if (!(f >= 0)) return 0; // NaN too
            if (f > dim - 1) return dim - 1;
            return (int)f;
        }

        private static bool IsFinite(Vector3 v)
        {
            return float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
        }

        private static string Format(string format, params object[] args)
        {
            return string.Format(CultureInfo.InvariantCulture, format, args);
        }
    }
}
