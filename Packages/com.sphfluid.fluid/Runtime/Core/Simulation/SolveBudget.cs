using System;
using System.Collections.Generic;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The rounds (the fluid's and the walls' error passes, correction) a DFSPH sub-step records for each of its solves
    /// without reading anything back (FluidSimulation's Solve), and which of the recorded dispatches then run groups: each
    /// is an indirect dispatch whose group count the fold at the end of the walls' error pass sets to zero once the solve
    /// has converged.
    /// </summary>
    public static class SolveBudget
    {
        /// <summary>
        /// The rounds a solve needs to converge after <paramref name="mostIterations"/> corrections (the most any solve of
        /// its kind made since the last motion read-back) are that many plus one, the round whose fold sees the
        /// error within tolerance. Twice that plus a margin is recorded, so that a flow that turns harder from one frame
        /// to the next still converges within the rounds of the frame planned before it was known; a solve that ran out
        /// of rounds anyway (<paramref name="cutOff"/> &gt; 0) at least doubles the budget. Never more than
        /// <paramref name="maxIterations"/> (the setting's hard limit), never fewer than the three rounds the first
        /// possible convergence takes; no solve since (0 and 0) keeps <paramref name="rounds"/>.
        /// </summary>
        public static int Next(int rounds, int mostIterations, int cutOff, int maxIterations)
        {
            if (mostIterations <= 0 && cutOff <= 0) return rounds;
            int next = 2 * mostIterations + 4;
            if (cutOff > 0) next = Math.Max(next, 2 * rounds);
            return Math.Min(maxIterations, Math.Max(3, next));
        }

        /// <summary>
        /// Of the indirect dispatches a DFSPH sub-step records for its two solves, how many run groups, by kernel.
        /// Per-dispatch timings count the empty rounds that the budget keeps in reserve beside those that ran, so a
        /// kernel's milliseconds over its dispatches understate what a running one costs wherever the solve converges
        /// well within its rounds. A solve of k corrections runs its error passes k + 1 times (the last finds it converged)
        /// or k times when its rounds run out first, and its correction k + 1 times, the warm start's first. Takes each
        /// solve's mean corrections and share cut off (<see cref="DiagnosticsReport"/>); the solves' set-up kernels are plain
        /// dispatches that always run.
        /// </summary>
        public static IReadOnlyList<(string Kernel, double Dispatches)> DispatchesThatRun(float densityIterations, float densityCutOff,
            float divergenceIterations, float divergenceCutOff)
        {
            double densityErrors = densityIterations + 1.0 - densityCutOff, divergenceErrors = divergenceIterations + 1.0 - divergenceCutOff;
            return new[]
            {
                (nameof(SolverKernels.DensitySolveError), densityErrors),
                (nameof(SolverKernels.DivergenceSolveError), divergenceErrors),
                (nameof(SolverKernels.BoundarySolveError), densityErrors + divergenceErrors),
                (nameof(SolverKernels.ApplyStiffness), densityIterations + divergenceIterations + 2.0),
            };
        }
    }
}
