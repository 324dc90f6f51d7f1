using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The eigenvalue interval [Low, High] that DFSPH's Chebyshev-accelerated solve is tuned for (DivergenceFreeSolver.hlsl):
    /// the eigenvalues of the relaxed Jacobi step's operator, omega lambda(k), over the pressure waves the fluid carries.
    /// <para>
    /// High is the lattice's stiffest wave (<see cref="SolverRelaxation.StiffestMode"/>) with a margin of
    /// <see cref="Margin"/>, and never below <see cref="JacobiLimit"/>: a wave above the interval grows with every round,
    /// one below it is only damped more slowly.
    /// </para>
    /// <para>
    /// Low is the longest wave a fluid of depth D holds: pressure zero at its free surface and no flux through its floor
    /// give a quarter wavelength over the column, k = pi / (2 D), and lambda(k) = <see cref="SolverRelaxation.Mode"/> there
    /// (about 8 (k s)^2 for Wendland C2 at 2.85 spacings, 6 / n^2 relaxed to 0.3 for a column of n spacings). D is the
    /// spawned fluid's extent along gravity, a particle spacing included for the half spacing above and below the outer
    /// particles; without gravity, its largest extent. A fluid deeper than <see cref="TunedDepth"/> spacings is taken as
    /// that deep: its longer waves fall below the interval, where the polynomial still damps them, only more slowly.
    /// </para>
    /// </summary>
    public static class ChebyshevBounds
    {
        /// <summary>High over the lattice's omega lambda_max: a disordered neighbourhood may have stiffer waves than the lattice's.
        /// At 1.05 (1.70 for Wendland C2 at 2.85 spacings relaxed to 0.3) OilAndWater ran 6 s at 4 160 particles and 0.3 s at
        /// 25 900 with no clamp hit.</summary>
        public const double Margin = 1.05;

        /// <summary>The least High: every wave the relaxed Jacobi step damps (omega lambda below 2, the bound FluidSettings
        /// holds omega to above 2 spacings) the accelerated solve damps too. The lattice's waves are an ordered fluid's; a fluid held only
        /// loosely incompressible is disordered, and its stiffest neighbourhoods carry waves above the lattice's margin.
        /// With High at the margin (1.70 for OilAndWater's solve) a 1 % tolerance took OilAndWater to unhealthy within
        /// 0.037 s at 100k and 250k particles on an H200 (b653f9f; 62 and 69 m/s) and within 0.033 s at 25 900 on lavapipe
        /// (42 % largest compression), while the Jacobi solve at 1 % ran clean; at 2 it ran 0.5 s at 25 900 and 0.1 s at
        /// 100k with no clamp hit (<c>LooseToleranceTests</c>). At the 0.1 % default it costs nothing measurable:
        /// OilAndWater at 25 900 particles, 0.3 s, 7.7 + 2.5 iterations a sub-step against 7.1 + 3.2. A solve at the papers'
        /// full step is above it already (the cubic spline at 2 spacings: 1.05 x 2.82) and unchanged.</summary>
        public const double JacobiLimit = 2.0;

        /// <summary>The deepest column, in spacings, whose quarter wave Low reaches down to. A column's quarter wave is its
        /// hydrostatic mode, which the warm start carries from one sub-step to the next, so tuning the solve for it pays
        /// in every round for a wave that is mostly solved already. Water columns of 80 spacings on 12 by 12 (the 1M
        /// case's depth; DeepColumnProbe) take 10.1 iterations a sub-step at 40 (12.0 at 60) against 17.7 tuned to the
        /// whole depth, at 0.100 and 0.095 % compression; OilAndWater in motion at 250k and 1M particles' spacing
        /// (LockExchangeSliceProbe) 12.7 and 14.0 against 18.8 and 31.2. A moving fluid tuned below its depth pays in the
        /// constant-density solve (OilAndWater at 25 900 particles: 6.9 iterations tuned to its 24 spacings, 11.2 to 12),
        /// so the cap sits above every shipped scene's depth.</summary>
        public const int TunedDepth = 40;

        /// <summary>The loosest density tolerance, in % per spacing of the fluid's depth, at which the constant-density solve
        /// still takes accelerated steps; at this tolerance or looser it takes the Jacobi solve's steps and only the
        /// divergence-free solve is accelerated (<see cref="AcceleratesDensitySolve"/>).
        /// <para>A loose solve stops after a few rounds, partway through the polynomial, whose few-round residual swings
        /// through zero to nearly its starting size on the waves between the interval's ends. Those overshoots stay in the
        /// velocities, hidden from a compression-only error, and the divergence-free solve must remove them: with both
        /// solves accelerated OilAndWater at 25 900 particles (24.4 spacings deep, 0.2 s) took 7.8 + 2.1, 3.8 + 9, 3 + 12.5
        /// and 2 + 25 iterations a sub-step at 0.1, 0.3, 0.5 and 1 %, a looser tolerance costing more; at its own 4 160
        /// (13.4 spacings) 1 % took 2 + 10 against 0.1 %'s 4 + 2, and at 0.5 and 1 % the fluid bounced, its potential
        /// energy rising 0.06 J above the spawn's within 0.1 s. With the Jacobi constant-density solve the same runs
        /// took 16 + 2, 9 + 2.7 and 4.8 + 2.7 iterations at 0.3, 0.5 and 1 % at 24.4 spacings (38.9 + 2.0 at 0.1 % in
        /// the slice of that depth, both solves Jacobi) and 6.9 and 5 at 13.4 spacings (0.3 and 0.5 %), with no bounce.
        /// The Jacobi solve's rounds grow with the square of the depth and fall with the tolerance, so the crossover
        /// moves with the depth: between 0.3 and 0.5 % at 24.4 spacings, 0.1 and 0.3 % at 13.4, and at 1 080 particles
        /// (8.5 spacings) a tie at 0.2 % (4.5 iterations each) where 0.1 % is the accelerated solve's (4.5 against 6.5).
        /// A sixtieth of a per cent per spacing (0.41, 0.22 and 0.14 %) lies within each bracket (hand edits of
        /// DivergenceFreeSolver.hlsl in temporary copies, lavapipe). Near the crossover neither step is cheap: at 24.4
        /// spacings 0.3 and 0.5 % cost more than 0.1 % whichever the solve takes.</para>
        /// <para>Measured again at 87177d8 with the Jacobi steps at every tolerance (<c>Headless/tools/experiment.sh --baseline
        /// jacobi-density-steps-at-every-tolerance</c>, the tolerance study of Headless/docs/accuracy-for-time.md):
        /// 18.3 and 44.5 iterations a sub-step, both solves together, at 0.3 and 0.1 % at 24.4 spacings against the
        /// accelerated steps' 13.4 and 10.8, and 14.9 against 6.4 at 0.1 % at 13.4 spacings: the rule puts each of
        /// those tolerances on its cheaper side.</para></summary>
        public const double DensityCrossover = 1.0 / 60.0;

        /// <summary>Whether DFSPH's constant-density solve takes accelerated steps at <paramref name="densityTolerance"/> (%)
        /// for a fluid <paramref name="depth"/> deep (m, as <see cref="For"/> takes it): below
        /// <see cref="DensityCrossover"/> times the depth in spacings.</summary>
        public static bool AcceleratesDensitySolve(double densityTolerance, double depth, double spacing) =>
            densityTolerance < DensityCrossover * depth / spacing;

        /// <summary>(Low, High) for a fluid of the given depth, m.</summary>
        public static (double Low, double High) For(KernelFamily kind, double spacing, double support, double relaxation, double depth)
        {
            double high = Math.Max(Margin * relaxation * SolverRelaxation.StiffestMode(kind, spacing, support), JacobiLimit);
            double longest = Math.PI / (2.0 * Math.Clamp(depth, spacing, TunedDepth * spacing));
            double low = Math.Min(relaxation * SolverRelaxation.Mode(kind, spacing, support, 0.0, longest, 0.0), 0.5 * high);
            return (low, high);
        }
    }
}
