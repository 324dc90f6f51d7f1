using System;
using SphFluid.Sorting;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The neighbour lists (SphNeighbourhood.hlsl): every particle's neighbours found once per sort and read from a list by
    /// the passes until the next drift. A grid walk visits the 125 cells of h/2 around a particle
    /// (<see cref="CellGrid.CellsPerSupport"/>), about 3.7 candidates per neighbour, so a pass that reads a list instead
    /// skips most of its work. DFSPH reads them in every iteration of its solves. WCSPH reads them in its four neighbour
    /// passes of a sub-step when each particle's loops run in one lane (a CPU device, or a GPU the particles fill); with
    /// more lanes the walks are already split over threads, and the search, which keeps the walk's order only in one lane
    /// (DFSPH's lists it finds in lanes, in another order), would add a whole walk to the sub-step (<see cref="InUse"/>).
    /// A particle inside the fluid at rest, or beside a wall whose particles fill its support at the fluid's number
    /// density, has about (4/3) pi (H / s)^3 neighbours: 33.5 for the cubic spline at 2 spacings, 97 for Wendland C2 at
    /// 2.85. Each list holds <see cref="Headroom"/> times that; a particle with more (a splash crushed against a wall)
    /// walks the grid instead, which costs that particle time, never a neighbour. WCSPH's lists keep the grid walk's
    /// order (<see cref="ListRows"/>), so that reading them changes no sum, not even by rounding.
    /// </summary>
    public static class NeighbourCapacity
    {
        /// <summary>Entries per list over the neighbours at rest.</summary>
        public const double Headroom = 1.5;

        /// <summary>The lists of one simulation live in one buffer of at most this many bytes (2 GiB, what a structured
        /// buffer can address), and no more than the device binds (<c>IComputeDevice.MaxBufferBytes</c>, 128 MiB on lavapipe);
        /// a larger simulation walks the grid in every pass.</summary>
        public const long MaxListBytes = 1L << 31;

        /// <summary>Words before the entries of a list in the grid walk's order: where each of the walk's rows ends, one row
        /// of cells along x for each y and z the walk reaches (NEIGHBOUR_ROW_WORDS in SphNeighbourhood.hlsl).</summary>
        public const int RowWords = (2 * CellGrid.CellsPerSupport + 1) * (2 * CellGrid.CellsPerSupport + 1);

        /// <summary>Entries per list for <paramref name="owners"/> list owners (fluid and wall particles), 0 for no lists:
        /// lists that would not fit in <see cref="MaxListBytes"/> or in the device's largest buffer,
        /// <paramref name="maxBufferBytes"/>.</summary>
        public static int For(FluidSettings settings, int owners, long maxBufferBytes)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            if (owners <= 0) return 0;
            double ratio = settings.SmoothingRadius / (double)settings.ParticleSpacing;
            int capacity = (int)Math.Ceiling(Headroom * 4.0 / 3.0 * Math.PI * ratio * ratio * ratio);
            if (ListRows(settings.PressureSolver) > 1) capacity += RowWords;
            // A list's counts share one word, 16 bits each.
            capacity = Math.Min(capacity, 0xFFFF);
            return (long)capacity * owners * sizeof(uint) <= Math.Min(MaxListBytes, maxBufferBytes) ? capacity : 0;
        }

        /// <summary>Whether the passes of <paramref name="solver"/> read the lists at <paramref name="lanes"/> threads per
        /// particle (NeighbourLanes): always under DFSPH, whose solves read them many times a sub-step; under WCSPH in one lane.</summary>
        public static bool InUse(PressureSolver solver, int lanes) => solver == PressureSolver.Dfsph || lanes == 1;

        /// <summary>The order of a list's entries (SphNeighbourhood.hlsl): <see cref="RowWords"/>, the grid walk's, row by row,
        /// each row's fluid neighbours and then its walls (WCSPH, whose results in one lane were measured with the grid walk and
        /// stay its to the bit); 1, all fluid neighbours and then all walls (DFSPH, which has always read its lists so).</summary>
        public static int ListRows(PressureSolver solver) => solver == PressureSolver.Dfsph ? 1 : RowWords;
    }
}
