using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The relaxation omega of the DFSPH solves' Jacobi step for the fluid particles (DivergenceFreeSolver.hlsl): each
    /// iteration applies omega times the q that would remove a particle's residual if its neighbours stood still.
    /// <para>
    /// On the spawn lattice (simple cubic, spacing s, one particle mass m, away from walls and surfaces) put a wave of q on
    /// the particles, q_j = a exp(i k . r_j). Through the pair force it changes every particle's predicted number density
    /// by -(dt^2 / m) |S(k)|^2 q_i, S(k) = sum_j sin(k . r_j) gradW(r_j), while the step divides the residual by
    /// (dt^2 / m) sum_j |gradW(r_j)|^2 (the DFSPH factor alpha_i, whose |sum_j gradW|^2 vanishes on the lattice). So one
    /// iteration multiplies the wave's residual by 1 - omega lambda(k), with
    ///   lambda(k) = |S(k)|^2 / sum_j |gradW(r_j)|^2,
    /// summed over the lattice points r_j != 0 within the support. Its average over the zone is 1 (the factor is the
    /// operator's diagonal), but its largest value is above 2 for both kernels at DFSPH's 2 spacings (the cubic spline
    /// 2.82, at k near (1/3, 1/3, 0.3) pi / s, a wavelength of about 3.6 spacings; Wendland C2 2.61). The papers' step, omega = 1 (Bender and Koschier 2017,
    /// "Divergence-Free SPH for Incompressible and Viscous Fluids"), overshoots those waves and makes them grow with
    /// every iteration. The solves correct compression only, so the expansion an overshoot leaves is never taken back:
    /// the tighter the tolerance, the more iterations, the more pressure noise. Under DFSPH with the cubic spline, before
    /// the walls counted at the fluid's rest number density, relaxing to 1 / lambda_max took the oil-and-water scene's
    /// floor oil from 22 % to 15 %. Above 2 spacings omega lambda_max must stay within 2 (<see cref="StableLimit"/>):
    /// Wendland C2 at 2.85 spacings (lambda_max 5.38) diverged with the full step and layers the oil and water at 0.3.
    /// </para>
    /// <para>
    /// omega = 1 / lambda_max brings every lattice wave's residual down without changing its sign. It costs
    /// iterations: the long waves, lambda much below 1, converge omega times as fast as with the papers' step.
    /// </para>
    /// </summary>
    public static class SolverRelaxation
    {
        /// <summary>Wave vectors sampled per axis over [0, pi / s]: the cubic lattice's zone, by symmetry.</summary>
        const int Samples = 24;

        /// <summary>omega = 1 / lambda_max, capped at the papers' 1.</summary>
        public static double For(KernelFamily kind, double spacing, double support) =>
            Math.Min(1.0, 1.0 / StiffestMode(kind, spacing, support));

        /// <summary>2 / lambda_max: the largest omega at which every lattice wave's residual shrinks, the Jacobi step's
        /// stability bound (FluidSettings requires it of DFSPH above 2 spacings).</summary>
        public static double StableLimit(KernelFamily kind, double spacing, double support) => 2.0 / StiffestMode(kind, spacing, support);

        /// <summary>lambda_max, the largest lambda(k) over the zone.</summary>
        public static double StiffestMode(KernelFamily kind, double spacing, double support)
        {
            var (offsets, gradients, diagonal) = Neighbours(kind, spacing, support);
            double step = Math.PI / spacing / Samples;
            return LatticeZone.Largest(Samples, 0.0, (a, b, c) => Mode(offsets, gradients, diagonal, step * a, step * b, step * c));
        }

        /// <summary>lambda(k) at wave vector (kx, ky, kz), 1/m.</summary>
        public static double Mode(KernelFamily kind, double spacing, double support, double kx, double ky, double kz)
        {
            var (offsets, gradients, diagonal) = Neighbours(kind, spacing, support);
            return Mode(offsets, gradients, diagonal, kx, ky, kz);
        }

        static double Mode(double[] offsets, double[] gradients, double diagonal, double kx, double ky, double kz)
        {
            double sx = 0, sy = 0, sz = 0;
            for (int n = 0; n < offsets.Length; n += 3)
            {
                double sin = Math.Sin(kx * offsets[n] + ky * offsets[n + 1] + kz * offsets[n + 2]);
                sx += sin * gradients[n];
                sy += sin * gradients[n + 1];
                sz += sin * gradients[n + 2];
            }
            return (sx * sx + sy * sy + sz * sz) / diagonal;
        }

        /// <summary>The lattice neighbours' offsets and kernel gradients (x, y, z per neighbour) and sum |gradW|^2.</summary>
        static (double[] Offsets, double[] Gradients, double Diagonal) Neighbours(KernelFamily kind, double spacing, double support)
        {
            var offsets = new System.Collections.Generic.List<double>();
            var gradients = new System.Collections.Generic.List<double>();
            double diagonal = 0.0;
            SmoothingKernels.ForEachLatticePoint(spacing, support, (x, y, z) =>
            {
                double r = Math.Sqrt(x * x + y * y + z * z);
                if (r <= 0.0 || r >= support) return;
                double radial = SmoothingKernels.Derivative(kind, r, support) / r;
                offsets.AddRange(new[] { x, y, z });
                gradients.AddRange(new[] { radial * x, radial * y, radial * z });
                diagonal += radial * radial * r * r;
            });
            return (offsets.ToArray(), gradients.ToArray(), diagonal);
        }
    }
}
