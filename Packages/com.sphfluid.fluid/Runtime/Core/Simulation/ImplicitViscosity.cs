using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The implicit viscosity solve of a sub-step longer than the explicit force's limit (SphViscositySolve.hlsl), once in
    /// a DFSPH sub-step and on each half kick of a WCSPH one (<see cref="SolvesPerStep"/>):
    /// the step h each of its two stages solves for, the eigenvalue interval [a, b] their Chebyshev rounds are tuned for
    /// and the number of rounds, all from the spawn lattice, so that the host records the rounds without reading anything
    /// back.
    /// <para>
    /// The two stages are Alexander's L-stable, second-order diagonally implicit Runge-Kutta method, each a backward
    /// Euler solve of step h = <see cref="StageFraction"/> s, s the step the solve covers (<see cref="Span"/>). Backward Euler alone took a wave of decay rate lambda down
    /// by 1 / (1 + lambda dt) a step, so a slow flow lagged: a cellular flow at 9.8 explicit limits kept 4 % more than the
    /// viscous operator's exact decay leaves, the two stages 0.1 % less. Two stages of h cost about what one of dt did,
    /// since the rounds grow as sqrt(h).
    /// </para>
    /// <para>
    /// Scaled by its diagonal, a stage's operator has its eigenvalues in [1 / (1 + beta), 2), beta = h nu sum_j w_j for a
    /// particle with the lattice's neighbours (w_j of <see cref="ViscousStepLimit"/>, summed: half its row bound). b = 2 is
    /// Gershgorin's bound for any particle; a is the lattice's long-wave eigenvalue for a beta <see cref="RowMargin"/>
    /// times the lattice's, since a particle at a free surface, thin under summation density, carries a larger volume and
    /// so a larger beta. A wave below a is still taken down, only more slowly, and none grows.
    /// </para>
    /// <para>
    /// K rounds take every wave's error in [a, b] down by 1 / T_K((b + a) / (b - a)) at least (T_K the Chebyshev
    /// polynomial), so a stage's rounds are the least K with T_K at or above 1 / <see cref="Tolerance"/>: each wave gets
    /// its stage's change to within that fraction. They grow as sqrt(beta): 10 rounds a stage, a neighbour pass each, at
    /// the 6.5 times the explicit limit that a liquid of 100 Pa s meets in OilAndWater, against 6.5 explicit sub-steps,
    /// each with both pressure solves, a sort and four neighbour passes besides; 28 a stage at 65 times.
    /// </para>
    /// </summary>
    public readonly struct ImplicitViscosity
    {
        /// <summary>The largest fraction of any wave's backward Euler change that the rounds may leave undone.</summary>
        public const double Tolerance = 1e-3;

        /// <summary>The largest row sum of couplings a particle may carry, in lattice row sums, that the interval's bottom
        /// is set for.</summary>
        public const double RowMargin = 1.5;

        /// <summary>gamma = 1 - 1 / sqrt 2: each stage's step over the sub-step's (Alexander 1977, "Diagonally implicit
        /// Runge-Kutta methods for stiff O.D.E.'s"), the value that makes the two stages second order and L-stable.</summary>
        public const double StageFraction = 0.29289321881345248;

        /// <summary>Backward Euler solves a sub-step makes, each of <see cref="StageStep"/>.</summary>
        public const int Stages = 2;

        /// <summary>b: Gershgorin's bound on the diagonally scaled operator for any particle.</summary>
        public const float High = 2f;

        /// <summary>a, the lowest eigenvalue the rounds are tuned for.</summary>
        public float Low { get; }

        /// <summary>Rounds of ViscosityStep and ViscosityApply each stage records; 0 while the viscosity is explicit.</summary>
        public int Rounds { get; }

        /// <summary>h, the step each stage solves for, s.</summary>
        public float StageStep { get; }

        ImplicitViscosity(float low, int rounds, float stageStep)
        {
            Low = low;
            Rounds = rounds;
            StageStep = stageStep;
        }

        /// <summary>The solve covering <paramref name="timeStep"/> s at kinematic viscosity <paramref name="nu"/>
        /// (m^2/s, the largest a pair of phases meets) on a lattice of <paramref name="spacing"/> m with support
        /// <paramref name="support"/> m.</summary>
        public static ImplicitViscosity For(KernelFamily kind, double spacing, double support, double nu, double timeStep) =>
            For(LatticeRowSum(kind, spacing, support), nu, timeStep);

        /// <summary>sum_j w_j over the lattice's neighbours, 1/m^2 (half <see cref="ViscousStepLimit.RowBound"/>): what a
        /// simulation keeps, so that a frame's new step allocates nothing.</summary>
        public static double LatticeRowSum(KernelFamily kind, double spacing, double support) =>
            0.5 * ViscousStepLimit.RowBound(kind, spacing, support);

        /// <summary>The solve covering <paramref name="timeStep"/> s (<see cref="Span"/>) at kinematic viscosity
        /// <paramref name="nu"/> (m^2/s) on a lattice whose <see cref="LatticeRowSum"/> is <paramref name="rowSum"/>.</summary>
        public static ImplicitViscosity For(double rowSum, double nu, double timeStep)
        {
            double stageStep = StageFraction * timeStep;
            double beta = RowMargin * stageStep * nu * rowSum;
            double low = 1.0 / (1.0 + beta);
            double ratio = (High + low) / (High - low);
            int rounds = (int)Math.Ceiling(Acosh(1.0 / Tolerance) / Acosh(ratio) - 1e-9);
            return new ImplicitViscosity((float)low, Math.Max(1, rounds), (float)stageStep);
        }

        /// <summary>Whether sub-steps of <paramref name="timeStep"/> s need the implicit solve: beyond the explicit force's
        /// limit <paramref name="explicitLimit"/> s (<see cref="TimeStepController.ViscousTimeStep"/>), by more than the
        /// rounding of a step held at the limit and stored in single precision.</summary>
        public static bool Needed(double timeStep, double explicitLimit) => timeStep > explicitLimit * (1.0 + 1e-6);

        /// <summary>What a WCSPH sub-step costs in rounds of the solve: on lavapipe, OilAndWater's 4 160 particles took
        /// 39 ms a sub-step and 7.3 ms a round (0.5 s with its oil at 100 Pa s: 810 explicit sub-steps in 31.9 s, 270
        /// implicit ones of 24 rounds in 57.9 s). A DFSPH sub-step, with its two pressure solves, costs many times more.</summary>
        public const double WcsphSubstepRounds = 5.3;

        /// <summary>Whether a sub-step of <paramref name="timeStep"/> s beyond the explicit limit <paramref name="explicitLimit"/>
        /// s costs less with the implicit solve than the explicit sub-steps it stands for: always under DFSPH; under
        /// WCSPH when its rounds (<see cref="SolvesPerStep"/> times <see cref="Stages"/> times a stage's) cost less than
        /// the ceil(timeStep / explicitLimit) - 1 further sub-steps (<see cref="WcsphSubstepRounds"/> each). OilAndWater's
        /// oil at 100 Pa s meets WCSPH's 1.85 ms step at 2.9 limits, where 24 rounds cost more than 2 sub-steps (the
        /// implicit run took 1.8 times the explicit one's wall time); a pool at 1000 Pa s at 7.6 limits.</summary>
        public static bool PaysOff(PressureSolver solver, double timeStep, double explicitLimit, double rowSum, double nu)
        {
            if (!Needed(timeStep, explicitLimit)) return false;
            if (solver == PressureSolver.Dfsph) return true;
            int rounds = SolvesPerStep(solver) * Stages * For(rowSum, nu, Span(solver, timeStep)).Rounds;
            return rounds < (Math.Ceiling(timeStep / explicitLimit) - 1.0) * WcsphSubstepRounds;
        }

        /// <summary>Solves a sub-step of <paramref name="solver"/> makes: DFSPH's one, between its constant-density solve and
        /// its drift; WCSPH's two, one on each half kick of Velocity Verlet, so that the particles drift with a velocity
        /// the viscosity has damped (SphIntegration.hlsl).</summary>
        public static int SolvesPerStep(PressureSolver solver) => solver == PressureSolver.Dfsph ? 1 : 2;

        /// <summary>The step one solve covers, s: a DFSPH sub-step's <paramref name="timeStep"/>, a WCSPH half kick's half.</summary>
        public static double Span(PressureSolver solver, double timeStep) => timeStep / SolvesPerStep(solver);

        static double Acosh(double x) => Math.Log(x + Math.Sqrt(x * x - 1.0));
    }
}
