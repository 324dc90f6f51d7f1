using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The entries of each neighbour list (SphNeighbourhood.hlsl): DFSPH finds every particle's neighbours once per sort
    /// and its solves read them from the list in every iteration; WCSPH, whose passes walk each neighbourhood once, keeps
    /// no lists. A particle inside the fluid at rest, or beside a wall whose particles fill its support at the fluid's
    /// number density, has about (4/3) pi (H / s)^3 neighbours: 33.5 for the cubic spline at 2 spacings, 97 for Wendland
    /// C2 at 2.85. Each list holds <see cref="Headroom"/> times that; a particle with more (a splash crushed against a wall)
    /// walks the grid instead, which costs that particle time, never a neighbour.
    /// </summary>
    public static class NeighbourCapacity
    {
        /// <summary>Entries per list over the neighbours at rest.</summary>
        public const double Headroom = 1.5;

        /// <summary>The lists of one simulation live in one buffer of at most this many bytes (2 GiB, what a structured
        /// buffer can address); a larger simulation walks the grid in every pass.</summary>
        public const long MaxListBytes = 1L << 31;

        /// <summary>Entries per list for <paramref name="owners"/> list owners (fluid and wall particles), 0 for no lists:
        /// WCSPH, or lists that would not fit in <see cref="MaxListBytes"/>.</summary>
        public static int For(FluidSettings settings, int owners)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            if (settings.PressureSolver != PressureSolver.Dfsph || owners <= 0) return 0;
            double ratio = settings.SmoothingRadius / (double)settings.ParticleSpacing;
            int capacity = (int)Math.Ceiling(Headroom * 4.0 / 3.0 * Math.PI * ratio * ratio * ratio);
            // A list's counts share one word, 16 bits each.
            capacity = Math.Min(capacity, 0xFFFF);
            return (long)capacity * owners * sizeof(uint) <= MaxListBytes ? capacity : 0;
        }
    }
}
