using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The CPU side of the solver's one smoothing kernel, the cubic B-spline (Monaghan &amp; Lattanzio 1985)
    /// with support radius H (Shaders/Include/SphKernels.hlsl holds the GPU version and the equations).
    /// The solver needs it before the GPU runs: the number density of a particle inside the spawn lattice,
    /// from which each phase's particle mass is derived (m_k = rho0_k / delta0) so that a lattice at rest,
    /// next to a wall of boundary particles too, sits exactly at rest density.
    /// </summary>
    public static class SmoothingKernels
    {
        /// <summary>W(r) = 8 / (pi H^3) w(r / H): the cubic spline of support H.</summary>
        public static double CubicSpline(double r, double support)
        {
            double q = r / support;
            double w;
            if (q <= 0.5) w = 6.0 * (q * q * q - q * q) + 1.0;
            else if (q < 1.0) w = 2.0 * (1.0 - q) * (1.0 - q) * (1.0 - q);
            else return 0.0;
            return 8.0 / (Math.PI * support * support * support) * w;
        }

        /// <summary>dW/dr of the cubic spline (negative inside the support): gradW = dW/dr r_ij / r.</summary>
        public static double CubicSplineDerivative(double r, double support)
        {
            double q = r / support;
            double w;
            if (q <= 0.5) w = 6.0 * (3.0 * q * q - 2.0 * q);
            else if (q < 1.0) w = -6.0 * (1.0 - q) * (1.0 - q);
            else return 0.0;
            return 8.0 / (Math.PI * Math.Pow(support, 4)) * w;
        }

        /// <summary>delta0 = sum over the cubic lattice of spacing s of W(|r|), self included.</summary>
        public static double LatticeNumberDensity(double spacing, double support)
        {
            double sum = 0.0;
            ForEachLatticePoint(spacing, support, (dx, dy, dz) => sum += CubicSpline(Math.Sqrt(dx * dx + dy * dy + dz * dz), support));
            return sum;
        }

        /// <summary>The walls' part of the number density of a lattice particle at rest beside a flat wall sampled on the
        /// same lattice: the lattice sum over the half-space of points below it (dy &lt; 0).</summary>
        public static double FlatWallNumberDensity(double spacing, double support)
        {
            double sum = 0.0;
            ForEachLatticePoint(spacing, support, (dx, dy, dz) =>
            {
                if (dy < 0) sum += CubicSpline(Math.Sqrt(dx * dx + dy * dy + dz * dz), support);
            });
            return sum;
        }

        /// <summary>
        /// How much of a linear pressure field's gradient the kernel recovers on the rest lattice:
        /// -sum_j V0 y_ij (dW/dy)(r_ij) with V0 = 1 / delta0 (1 is exact). The hydrostatic pressure gradient
        /// a tank at rest settles to is off by about this factor's distance from 1.
        /// </summary>
        public static double LatticeGradientReproduction(double spacing, double support)
        {
            double volume = 1.0 / LatticeNumberDensity(spacing, support);
            double sum = 0.0;
            ForEachLatticePoint(spacing, support, (dx, dy, dz) =>
            {
                double r = Math.Sqrt(dx * dx + dy * dy + dz * dz);
                if (r > 0) sum += volume * dy * CubicSplineDerivative(r, support) * dy / r;
            });
            return -sum;
        }

        static void ForEachLatticePoint(double spacing, double support, Action<double, double, double> visit)
        {
            int reach = (int)Math.Ceiling(support / spacing);
            for (int i = -reach; i <= reach; i++)
            for (int j = -reach; j <= reach; j++)
            for (int k = -reach; k <= reach; k++)
                visit(i * spacing, j * spacing, k * spacing);
        }
    }
}
