using System;
using System.Collections.Generic;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The longest sub-step the explicit viscous force allows (SphViscosity.hlsl: Morris, Fox and Zhu 1997, "Modeling low
    /// Reynolds number incompressible flows using SPH"), from the force's own operator on the particle lattice.
    /// <para>
    /// On the spawn lattice (simple cubic, spacing s, each particle's volume V0 = 1 / delta0 and mass rho0 V0) put a wave
    /// of velocity on the particles, v_j = a exp(i k . r_j). The pair force turns it into the acceleration
    ///   a_i = -nu Lambda(k) v_i,   Lambda(k) = sum_j w_j (1 - cos k . r_j),   w_j = -2 V0 r_j W'(r_j) / (r_j^2 + 0.01 H^2),
    /// summed over the lattice points r_j != 0 within the support H (w_j is positive: W' is negative). Both integrators
    /// apply it as one explicit kick a sub-step, on the half-step velocity (WCSPH's Velocity Verlet) or the velocity
    /// (DFSPH's symplectic Euler), so each sub-step multiplies the wave by 1 - dt nu Lambda(k): it grows once dt nu
    /// Lambda exceeds 2. The step allowed is 1 / (nu Lambda_max), half that bound, at which every lattice wave decays
    /// without changing sign, leaving room for what the lattice does not have: disorder, walls, a free surface
    /// (summation density's thin surface particles carry larger volumes).
    /// </para>
    /// <para>
    /// Lambda_max s^2 is 5.82 for the cubic spline at 2 spacings and 3.16 for Wendland C2 at 2.85, at the zone's corner
    /// k = (1, 1, 1) pi / s, where neighbours an odd number of steps away move against each other. The rule it replaces,
    /// 0.125 H^2 / nu (Monaghan's, for the smoothing length h = H / 2 of the cubic spline, applied to H), allowed 0.5 and
    /// 1.02 s^2 / nu there, beyond the bounds 2 / Lambda_max of 0.34 and 0.63 s^2 / nu: OilAndWater's oil at 100 Pa s ran
    /// at the speed of sound's 1.85 ms steps, under that rule's 2.06 ms and above the bound's 1.28 ms, and blew up within
    /// 0.09 s (<c>ViscousStepTests</c>).
    /// </para>
    /// </summary>
    public static class ViscousStepLimit
    {
        /// <summary>Wave vectors sampled per axis over [0, pi / s] (<see cref="LatticeZone"/>).</summary>
        const int Samples = 16;

        /// <summary>The longest sub-step for kinematic viscosity <paramref name="nu"/> (m^2/s), s: 1 / (nu Lambda_max);
        /// infinite without viscosity.</summary>
        public static double For(KernelFamily kind, double spacing, double support, double nu) =>
            nu > 0.0 ? 1.0 / (nu * StiffestMode(kind, spacing, support)) : double.PositiveInfinity;

        /// <summary>Lambda_max, the largest Lambda(k) over the zone, 1/m^2.</summary>
        public static double StiffestMode(KernelFamily kind, double spacing, double support)
        {
            var neighbours = Neighbours(kind, spacing, support);
            double step = Math.PI / spacing / Samples;
            return LatticeZone.Largest(Samples, 0.0, (a, b, c) => Mode(neighbours, step * a, step * b, step * c));
        }

        /// <summary>Lambda(k) at wave vector (kx, ky, kz), 1/m^2: the acceleration per unit velocity and unit kinematic
        /// viscosity that the wave meets.</summary>
        public static double Mode(KernelFamily kind, double spacing, double support, double kx, double ky, double kz) =>
            Mode(Neighbours(kind, spacing, support), kx, ky, kz);

        /// <summary>2 sum_j w_j, 1/m^2: Gershgorin's bound on Lambda for any velocities on the lattice, walls that stand still
        /// in place of some neighbours included.</summary>
        public static double RowBound(KernelFamily kind, double spacing, double support)
        {
            double sum = 0.0;
            var neighbours = Neighbours(kind, spacing, support);
            for (int n = 3; n < neighbours.Length; n += 4) sum += neighbours[n];
            return 2.0 * sum;
        }

        static double Mode(double[] neighbours, double kx, double ky, double kz)
        {
            double sum = 0.0;
            for (int n = 0; n < neighbours.Length; n += 4)
                sum += neighbours[n + 3] * (1.0 - Math.Cos(kx * neighbours[n] + ky * neighbours[n + 1] + kz * neighbours[n + 2]));
            return sum;
        }

        /// <summary>Each lattice neighbour's offset (x, y, z) and weight w_j.</summary>
        static double[] Neighbours(KernelFamily kind, double spacing, double support)
        {
            double volume = 1.0 / SmoothingKernels.LatticeNumberDensity(kind, spacing, support);
            var neighbours = new List<double>();
            SmoothingKernels.ForEachLatticePoint(spacing, support, (x, y, z) =>
            {
                double r2 = x * x + y * y + z * z, r = Math.Sqrt(r2);
                if (r <= 0.0 || r >= support) return;
                double weight = -2.0 * volume * r * SmoothingKernels.Derivative(kind, r, support) / (r2 + 0.01 * support * support);
                neighbours.AddRange(new[] { x, y, z, weight });
            });
            return neighbours.ToArray();
        }
    }
}
