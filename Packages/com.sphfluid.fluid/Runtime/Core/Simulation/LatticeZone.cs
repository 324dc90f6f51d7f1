using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The wave vectors of the spawn lattice's analyses (<see cref="LatticeStability"/>, <see cref="SolverRelaxation"/>,
    /// <see cref="ViscousStepLimit"/>), sampled over the part of the simple cubic lattice's zone that its symmetries leave:
    /// k = (a, b, c) pi / (s n) with n &gt;= a &gt;= b &gt;= c &gt;= 0. A lattice sum whose weights depend on the offset's length
    /// alone takes the same value at any k with its components permuted or their signs flipped, so the extremes over
    /// this wedge are the zone's.
    /// </summary>
    internal static class LatticeZone
    {
        /// <summary>The largest of <paramref name="mode"/>(a, b, c) over the wedge sampled <paramref name="samples"/> steps
        /// per axis, and at least <paramref name="floor"/>.</summary>
        public static double Largest(int samples, double floor, Func<int, int, int, double> mode)
        {
            double largest = floor;
            for (int a = 0; a <= samples; a++)
            for (int b = 0; b <= a; b++)
            for (int c = 0; c <= b; c++)
                largest = Math.Max(largest, mode(a, b, c));
            return largest;
        }

        /// <summary>The smallest of <paramref name="mode"/>(a, b, c) over the wedge, and at most <paramref name="ceiling"/>.</summary>
        public static double Smallest(int samples, double ceiling, Func<int, int, int, double> mode) =>
            -Largest(samples, -ceiling, (a, b, c) => -mode(a, b, c));
    }
}
