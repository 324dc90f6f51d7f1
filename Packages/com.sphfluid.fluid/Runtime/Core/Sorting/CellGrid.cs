using System;
using System.Globalization;
using System.Numerics;
using SphFluid.Compute;

namespace SphFluid.Sorting
{
    /// <summary>
    /// The solver's uniform neighbour grid: cubic cells, <see cref="CellsPerSupport"/> to the support radius h
    /// (<see cref="ForSupport"/>), laid out in the container's LOCAL frame (so a rotating container never resizes it),
    /// with <see cref="MarginCells"/> margin cells on every side so that particles pushed slightly through a wall still
    /// map to a sensible cell. The C# twin of Shaders/Include/Grid.hlsl; <see cref="SetOn"/> uploads its globals.
    /// </summary>
    /// <remarks>
    /// Grid coordinate of world point x: g = WorldToGrid * (x, 1) with
    /// WorldToGrid = scale(1/cell) * translate(S/2 + margin cell) * R^T * translate(-c), cell = clamp(floor(g), 0, dims - 1),
    /// linear index = x + dims.x (y + dims.y z).
    /// </remarks>
    public sealed class CellGrid
    {
        /// <summary>Most cells a grid may have: 2^25 (32M). Each per-cell uint buffer is then 128 MiB, the
        /// largest storage buffer D3D11 and lavapipe guarantee to bind.</summary>
        public const int MaxCellCount = 1 << 25;

        /// <summary>Cells to the support radius h, and so the cells a neighbour walk reaches on each side of a particle's
        /// own: (2 * CellsPerSupport + 1)^3 cells, as (2 * CellsPerSupport + 1)^2 rows (CELLS_PER_SUPPORT in
        /// SphNeighbourhood.hlsl, which must match). Two, not one: the 125 cells of h/2 around a particle hold 58 % of the
        /// volume of the 27 cells of h, so every walk tests that much fewer candidates for the same neighbours. On an
        /// NVIDIA H200 at 1M particles (OilAndWater) that took WCSPH's sub-step from 6.27 to 4.65 ms (FindNeighbours 2.62 to
        /// 1.63, Forces 1.30 to 1.09) and DFSPH's from 37.2 to 34.6 ms; on lavapipe FindNeighbours costs about a fifth less
        /// at 4 160 particles and the whole sub-step about 5 % less, where the longer rows' bookkeeping takes back most of
        /// the gain (Headless/experiments/half-support-cells.patch, Headless/docs/accuracy-for-time.md). The price is 8
        /// times the cells for a container, against <see cref="MaxCellCount"/>.</summary>
        public const int CellsPerSupport = 2;

        /// <summary>Cells added on each side of every axis beyond the container: one support radius h, as many cells as the
        /// walk reaches, so that a particle a little outside its wall still finds its neighbours inside.</summary>
        public const int MarginCells = CellsPerSupport;

        /// <summary>The solver's grid for the support radius <paramref name="smoothingRadius"/> (h): cells of
        /// h / <see cref="CellsPerSupport"/>, which a neighbour walk of <see cref="CellsPerSupport"/> cells each side
        /// covers. Every grid the simulation walks is made here, so the cell size is derived from h in this one place.</summary>
        public static CellGrid ForSupport(Vector3 containerCentre, Quaternion containerRotation, Vector3 containerSize, float smoothingRadius)
        {
            if (!(smoothingRadius > 0f) || !float.IsFinite(smoothingRadius))
                throw new ArgumentOutOfRangeException(nameof(smoothingRadius), smoothingRadius,
                    Format("CellGrid: the smoothing radius h must be a finite number > 0 m (was {0})", smoothingRadius));
            return new CellGrid(containerCentre, containerRotation, containerSize, smoothingRadius / CellsPerSupport, smoothingRadius);
        }

        /// <summary>A grid of cells of <paramref name="cellSize"/> m; the solver's grid is <see cref="ForSupport"/>.</summary>
        public CellGrid(Vector3 containerCentre, Quaternion containerRotation, Vector3 containerSize, float cellSize)
            : this(containerCentre, containerRotation, containerSize, cellSize, float.NaN)
        {
        }

        /// <param name="support">The smoothing radius the cells were made from (<see cref="ForSupport"/>), which a refusal
        /// names, or NaN for a grid of a given cell size.</param>
        private CellGrid(Vector3 containerCentre, Quaternion containerRotation, Vector3 containerSize, float cellSize, float support)
        {
            if (!(cellSize > 0f) || !float.IsFinite(cellSize))
                throw new ArgumentOutOfRangeException(nameof(cellSize), cellSize,
                    Format("CellGrid: cell size must be a finite number > 0 m (was {0})", cellSize));
            if (!(containerSize.X > 0f && containerSize.Y > 0f && containerSize.Z > 0f) || !IsFinite(containerSize))
                throw new ArgumentOutOfRangeException(nameof(containerSize), containerSize,
                    Format("CellGrid: container size must be finite and > 0 m on every axis (was {0})", containerSize));

            double dx = CellsAlong(containerSize.X, cellSize);
            double dy = CellsAlong(containerSize.Y, cellSize);
            double dz = CellsAlong(containerSize.Z, cellSize);
            double cells = dx * dy * dz;
            if (cells > MaxCellCount)
            {
                string need = Format("needs {0} x {1} x {2} = {3:E2} cells ({4} margin cells per side included), more than the {5} allowed",
                    dx, dy, dz, cells, MarginCells, MaxCellCount);
                if (float.IsNaN(support))
                    throw new ArgumentOutOfRangeException(nameof(cellSize), cellSize,
                        Format("CellGrid: container size {0} m in cells of {1} m {2}; raise the cell size or shrink the container",
                            containerSize, cellSize, need));
                throw new ArgumentOutOfRangeException("smoothingRadius", support,
                    Format("CellGrid: container size {0} m with smoothing radius h = {1} m (cells of h/{2}) {3}; " +
                           "raise the smoothing radius to at least {4:G4} m or shrink the container",
                        containerSize, support, CellsPerSupport, need, SmallestSupport(containerSize)));
            }

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

        /// <summary>Edge of a cell, m: h / <see cref="CellsPerSupport"/> for the solver's grid (<see cref="ForSupport"/>).</summary>
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

        /// <summary>Grid coordinates (units of <see cref="CellSize"/>, before flooring) of a world point.</summary>
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
            return Format("CellGrid {0} x {1} x {2} cells of {3} m", DimX, DimY, DimZ, CellSize);
        }

        /// <summary>The smallest smoothing radius whose grid for <paramref name="containerSize"/> stays within
        /// <see cref="MaxCellCount"/>, rounded up to four significant digits (for a refusal to name the range).</summary>
        private static double SmallestSupport(Vector3 containerSize)
        {
            double low = 0, high = Math.Max(containerSize.X, Math.Max(containerSize.Y, containerSize.Z));
            for (int i = 0; i < 100; i++)
            {
                double h = 0.5 * (low + high), cell = h / CellsPerSupport;
                bool fits = CellsAlong(containerSize.X, cell) * CellsAlong(containerSize.Y, cell) * CellsAlong(containerSize.Z, cell) <= MaxCellCount;
                if (fits) high = h;
                else low = h;
            }
            double digit = Math.Pow(10, Math.Floor(Math.Log10(high)) - 3);
            return Math.Ceiling(high / digit) * digit;
        }

        private static double CellsAlong(float size, double cellSize)
        {
            return Math.Ceiling(size / cellSize) + 2 * MarginCells;
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

        /// <summary>A message with its vectors written as the validation writes them, (x, y, z), not as Vector3's &lt;x, y, z&gt;:
        /// the scene reader prints this beside the validation's messages.</summary>
        private static string Format(string format, params object[] args)
        {
            for (int i = 0; i < args.Length; i++)
                if (args[i] is Vector3 v) args[i] = Simulation.ValidationRules.Format(v);
            return string.Format(CultureInfo.InvariantCulture, format, args);
        }
    }
}
