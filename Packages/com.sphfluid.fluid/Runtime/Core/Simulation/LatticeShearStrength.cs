using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Why a fluid at rest on its spawn lattice can hold a small tilt: the lattice's ideal shear strength under a uniform
    /// pressure p, for the solver's symmetric pressure force F_i = -sum_j (q_i + q_j) gradW(r_ij), q = p / delta0^2
    /// (Shaders/Include/SphPressureForce.hlsl and DivergenceFreeSolver.hlsl).
    /// <para>
    /// Slide the half of the lattice above a horizontal lattice plane rigidly by u along x over the half below it, the
    /// calculation of Frenkel's ideal shear strength ("Zur Theorie der Elastizitätsgrenze und der Festigkeit
    /// kristallinischer Körper", 1926) with SPH's pair force in place of the atoms'. With q uniform the pair force is
    /// -grad of 2 q W, so the stress that resists the slip is the derivative of a slip energy per unit area:
    ///   tau(u) = (2 q / s^2) d/du sum_{n >= 1} n sum_{(a, b) in the plane} W(|(a s + u, n s, b s)|),
    /// where n counts the pairs of rows n spacings apart across the plane (n of them for each column). tau is periodic
    /// in u with period s and odd about 0 and s / 2, so its largest magnitude tau_y is the stress the slip must get past:
    /// below it the lattice can stand as a solid would. tau_y is proportional to p, and tau_y / p
    /// depends only on the kernel and the support in spacings, not on the resolution: a finer spacing at the same
    /// support ratio holds the same fraction of the pressure. It comes from the lattice sum of W at a shifted row, a
    /// Fourier coefficient of the kernel at the lattice's period, and so falls and rises with the support.
    /// </para>
    /// <para>
    /// It is an estimate: a perfect lattice and a rigid plane, where a real slip starts at a defect and spreads. It
    /// agrees with the tilted-layers fixtures of InternalSeicheProbe (Headless/docs/physics.md: "From a tilted start: a
    /// threshold, not a damping"): every measured start stopped at a tilt whose buoyancy the lattice can carry as
    /// shear, though a start within that bound may still creep some way before it stops (the cubic spline's, 7 mm in
    /// its first second).
    /// </para>
    /// </summary>
    public static class LatticeShearStrength
    {
        /// <summary>Slips sampled over half a period, [0, s / 2]; tau is odd about both ends.</summary>
        const int Samples = 64;

        /// <summary>tau(u) / p: the stress that resists a rigid slip u (m) of the lattice's upper half, per unit pressure;
        /// positive where it pushes the slip back towards u = 0.</summary>
        public static double SlipStressRatio(KernelFamily kind, double spacing, double support, double slip)
        {
            double delta0 = SmoothingKernels.LatticeNumberDensity(kind, spacing, support);
            double sum = 0.0;
            // One more lattice point each way: the slip moves a row up to a spacing into the support.
            SmoothingKernels.ForEachLatticePoint(spacing, support + spacing, (dx, dy, dz) =>
            {
                if (dy <= 0.0) return;
                double x = dx + slip, r = Math.Sqrt(x * x + dy * dy + dz * dz);
                if (r >= support) return;
                sum += Math.Round(dy / spacing) * SmoothingKernels.Derivative(kind, r, support) * x / r;
            });
            return 2.0 / (delta0 * delta0 * spacing * spacing) * sum;
        }

        /// <summary>tau_y / p: the largest |tau(u)| / p over a period, the stress per unit pressure a rigid slip of the
        /// lattice must get past.</summary>
        public static double YieldRatio(KernelFamily kind, double spacing, double support)
        {
            double largest = 0.0;
            for (int i = 1; i < Samples; i++)
                largest = Math.Max(largest, Math.Abs(SlipStressRatio(kind, spacing, support, 0.5 * spacing * i / Samples)));
            return largest;
        }
    }
}
