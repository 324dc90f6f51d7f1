namespace SphFluid.Simulation
{
    /// <summary>
    /// Threads per particle in the neighbour loops of density, wall pressure, forces (with the tension's normals and the strain
    /// rate's rotations), particle shifting, and DFSPH's neighbour search and solve (NeighbourLanes.hlsl). A pass
    /// over few particles leaves a GPU idle but for the longest thread's walk through its neighbourhood, so splitting
    /// each walk over several threads shortens the pass; once the particles alone fill the GPU, more threads only add
    /// the sum across them. The count of threads that fills a GPU is taken as <see cref="FillingThreads"/>: an H100's and
    /// an H200's WCSPH sub-step cost the same from 1 080 to 68 000 particles and grew from there
    /// (Headless/docs/accuracy-for-time.md), and a mid-range card fills with fewer. A CPU device (lavapipe) runs each
    /// thread's walk on a core that hides no latency behind other threads: one lane.
    /// </summary>
    public static class NeighbourLanes
    {
        /// <summary>The most lanes a particle gets; a power of two that divides the kernels' thread groups.</summary>
        public const int Max = 8;

        /// <summary>Threads (particles times lanes) taken to fill a GPU.</summary>
        public const int FillingThreads = 65536;

        /// <summary>The largest power of two up to <see cref="Max"/> whose lanes for <paramref name="particles"/> stay
        /// within <see cref="FillingThreads"/>, at least 1; 1 on a CPU device.</summary>
        public static int For(int particles, bool cpuDevice)
        {
            if (cpuDevice || particles <= 0) return 1;
            int lanes = 1;
            while (lanes < Max && (long)particles * lanes * 2 <= FillingThreads) lanes *= 2;
            return lanes;
        }

        /// <summary>Whether <paramref name="lanes"/> is a lane count the kernels take: 1, 2, 4 or 8.</summary>
        public static bool IsValid(int lanes) => lanes >= 1 && lanes <= Max && (lanes & (lanes - 1)) == 0;
    }
}
