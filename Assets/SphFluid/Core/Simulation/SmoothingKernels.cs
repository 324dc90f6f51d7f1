using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The CPU side of the SPH kernels (Mueller et al. 2003) that the solver needs before the GPU runs:
    /// the number density of a particle inside the spawn lattice, from which each phase's particle mass
    /// is derived (m_k = rho0_k / delta0) so that a lattice at rest has zero density error. The number
    /// density uses the Spiky kernel, as the GPU does (SphKernels.hlsl explains the deviation from Poly6).
    /// The GPU versions live in Shaders/Include/SphKernels.hlsl.
    /// </summary>
    public static class SmoothingKernels
    {
        /// <summary>Poly6: W(r) = 315 / (64 pi h^9) (h^2 - r^2)^3 for r &lt; h, else 0.</summary>
        public static double Poly6(double r2, double h)
        {
            double h2 = h * h;
            if (r2 >= h2) return 0.0;
            double d = h2 - r2;
            return 315.0 / (64.0 * Math.PI * Math.Pow(h, 9)) * d * d * d;
        }

        /// <summary>Spiky: Ws(r) = 15 / (pi h^6) (h - r)^3 for r &lt; h, else 0 (the density kernel).</summary>
        public static double Spiky(double r, double h)
        {
            if (r >= h) return 0.0;
            double d = h - r;
            return 15.0 / (Math.PI * Math.Pow(h, 6)) * d * d * d;
        }

        /// <summary>delta0 = sum over the cubic lattice of spacing s of Ws(|r|), self included.</summary>
        public static double LatticeNumberDensity(double spacing, double h)
        {
            int reach = (int)Math.Ceiling(h / spacing);
            double sum = 0.0;
            for (int i = -reach; i <= reach; i++)
            for (int j = -reach; j <= reach; j++)
            for (int k = -reach; k <= reach; k++)
            {
                double r2 = (i * i + j * j + k * k) * spacing * spacing;
                sum += Spiky(Math.Sqrt(r2), h);
            }
            return sum;
        }
    }
}
