using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The CPU side of the solver's smoothing kernels (KernelFamily, FluidSettings.SmoothingKernel; Shaders/Include/SphKernels.hlsl holds the GPU
    /// version and the equations), with support radius H. The solver needs them before the GPU runs: the number density of
    /// a particle inside the spawn lattice, from which each phase's particle mass is derived (m_k = rho0_k / delta0) so that
    /// a lattice at rest, next to a wall of boundary particles too, sits exactly at rest density.
    /// </summary>
    public static class SmoothingKernels
    {
        /// <summary>sigma of W(r) = sigma w(r / H): 8 / (pi H^3) for the cubic spline, 21 / (2 pi H^3) for Wendland C2.</summary>
        public static double Normalisation(KernelFamily kind, double support) =>
            (kind == KernelFamily.WendlandC2 ? 21.0 / (2.0 * Math.PI) : 8.0 / Math.PI) / (support * support * support);

        /// <summary>w(q), the kernel's shape at q = r / H (0 beyond 1).</summary>
        public static double Shape(KernelFamily kind, double q)
        {
            if (q >= 1.0) return 0.0;
            double t = 1.0 - q;
            if (kind == KernelFamily.WendlandC2) return t * t * t * t * (1.0 + 4.0 * q);
            return q <= 0.5 ? 6.0 * (q * q * q - q * q) + 1.0 : 2.0 * t * t * t;
        }

        /// <summary>dw/dq (negative inside the support).</summary>
        public static double ShapeDerivative(KernelFamily kind, double q)
        {
            if (q >= 1.0) return 0.0;
            double t = 1.0 - q;
            if (kind == KernelFamily.WendlandC2) return -20.0 * q * t * t * t;
            return q <= 0.5 ? 6.0 * (3.0 * q * q - 2.0 * q) : -6.0 * t * t;
        }

        /// <summary>d2w/dq2: what the lattice's stiffness under pressure is built from (<see cref="LatticeStability"/>).</summary>
        public static double ShapeSecondDerivative(KernelFamily kind, double q)
        {
            if (q >= 1.0) return 0.0;
            double t = 1.0 - q;
            if (kind == KernelFamily.WendlandC2) return 20.0 * t * t * (4.0 * q - 1.0);
            return q <= 0.5 ? 36.0 * q - 12.0 : 12.0 * t;
        }

        /// <summary>W(r) of support H.</summary>
        public static double Value(KernelFamily kind, double r, double support) =>
            Normalisation(kind, support) * Shape(kind, r / support);

        /// <summary>dW/dr (negative inside the support): gradW = dW/dr r_ij / r.</summary>
        public static double Derivative(KernelFamily kind, double r, double support) =>
            Normalisation(kind, support) / support * ShapeDerivative(kind, r / support);

        /// <summary>d2W/dr2.</summary>
        public static double SecondDerivative(KernelFamily kind, double r, double support) =>
            Normalisation(kind, support) / (support * support) * ShapeSecondDerivative(kind, r / support);

        /// <summary>delta0 = sum over the cubic lattice of spacing s of W(|r|), self included.</summary>
        public static double LatticeNumberDensity(KernelFamily kind, double spacing, double support)
        {
            double sum = 0.0;
            ForEachLatticePoint(spacing, support, (dx, dy, dz) => sum += Value(kind, Math.Sqrt(dx * dx + dy * dy + dz * dz), support));
            return sum;
        }

        /// <summary>The walls' part of the number density of a lattice particle at rest beside a flat wall sampled on the
        /// same lattice: the lattice sum over the half-space of points below it (dy &lt; 0).</summary>
        public static double FlatWallNumberDensity(KernelFamily kind, double spacing, double support)
        {
            double sum = 0.0;
            ForEachLatticePoint(spacing, support, (dx, dy, dz) =>
            {
                if (dy < 0) sum += Value(kind, Math.Sqrt(dx * dx + dy * dy + dz * dz), support);
            });
            return sum;
        }

        /// <summary>
        /// How much of a linear pressure field's gradient the kernel recovers on the rest lattice:
        /// -sum_j V0 y_ij (dW/dy)(r_ij) with V0 = 1 / delta0 (1 is exact). The hydrostatic pressure gradient
        /// a tank at rest settles to is off by about this factor's distance from 1.
        /// </summary>
        public static double LatticeGradientReproduction(KernelFamily kind, double spacing, double support)
        {
            double volume = 1.0 / LatticeNumberDensity(kind, spacing, support);
            double sum = 0.0;
            ForEachLatticePoint(spacing, support, (dx, dy, dz) =>
            {
                double r = Math.Sqrt(dx * dx + dy * dy + dz * dz);
                if (r > 0) sum += volume * dy * Derivative(kind, r, support) * dy / r;
            });
            return -sum;
        }

        internal static void ForEachLatticePoint(double spacing, double support, Action<double, double, double> visit)
        {
            int reach = (int)Math.Ceiling(support / spacing);
            for (int i = -reach; i <= reach; i++)
            for (int j = -reach; j <= reach; j++)
            for (int k = -reach; k <= reach; k++)
                visit(i * spacing, j * spacing, k * spacing);
        }
    }
}
