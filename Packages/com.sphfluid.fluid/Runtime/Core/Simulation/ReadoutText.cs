using System.Globalization;
using System.Text;

namespace SphFluid.Simulation
{
    /// <summary>
    /// What a running fluid's frame cost, worded once for every Unity readout (the <c>Fluid</c> inspector in play mode,
    /// the demo's on-screen readout): the pressure solve's iterations and the GPU's time in the accuracy-for-time
    /// study's currency, seconds per simulated second and the real-time factor they allow.
    /// </summary>
    public static class ReadoutText
    {
        static readonly CultureInfo C = CultureInfo.InvariantCulture;

        /// <summary>Said in place of <see cref="AppendGpuCost"/> where the platform has no GPU timer queries.</summary>
        public const string GpuTimeUnavailable = "GPU time: not measurable on this platform";

        /// <summary>How the running DFSPH solves iterate. The Chebyshev setting accelerates the constant-density solve
        /// only at tolerances tight for the fluid's depth (<see cref="ChebyshevBounds.AcceleratesDensitySolve"/>), so the
        /// name says when that solve takes the Jacobi steps.</summary>
        public static string IterationName(SolverIteration iteration, bool acceleratesDensitySolve) =>
            iteration == SolverIteration.Jacobi ? "Jacobi"
            : acceleratesDensitySolve ? "Chebyshev" : "Chebyshev (divergence-free; density Jacobi)";

        /// <summary>The frame's GPU time, a sub-step's share and, where the frame advanced the fluid, the GPU seconds a
        /// simulated second takes and the real-time factor they allow: a bound, since the frame adds the CPU's and the
        /// rendering's time.</summary>
        public static StringBuilder AppendGpuCost(StringBuilder text, double gpuMilliseconds, StepReport step)
        {
            text.AppendFormat(C, "GPU {0:F2} ms per frame, {1:F3} ms per sub-step", gpuMilliseconds,
                step.Substeps > 0 ? gpuMilliseconds / step.Substeps : 0.0);
            if (step.SimulatedSeconds > 0f && gpuMilliseconds > 0.0)
            {
                double perSimulatedSecond = gpuMilliseconds * 0.001 / step.SimulatedSeconds;
                text.AppendFormat(C, ", {0:F3} s per simulated s (at most {1:F2}x real time)", perSimulatedSecond, 1.0 / perSimulatedSecond);
            }
            return text;
        }

        /// <summary>The pressure solve as the last read-back saw it: DFSPH's iterations per sub-step and the share of
        /// solves cut off at their cap (above 0 the error may exceed its tolerance), or WCSPH's divergence error alone.
        /// The iteration scheme is the running simulation's: an edit of the inspector's settings waits for a reset.</summary>
        public static StringBuilder AppendSolves(StringBuilder text, DiagnosticsReport diagnostics, FluidSimulation simulation)
        {
            string iterationName = IterationName(simulation.Scene.Settings.SolverIteration, simulation.AcceleratesDensitySolve);
            return diagnostics.PressureSolver == PressureSolver.Dfsph
                ? text.AppendFormat(C, "DFSPH {5} iterations per sub-step: density {0:F1} ({1:P0} cut off), divergence {2:F1} ({3:P0} cut off)   divergence error {4:F2} %/s",
                    diagnostics.DensitySolveIterations, diagnostics.DensitySolvesCutOff, diagnostics.DivergenceSolveIterations,
                    diagnostics.DivergenceSolvesCutOff, diagnostics.DivergenceError, iterationName)
                : text.AppendFormat(C, "Divergence error {0:F2} %/s", diagnostics.DivergenceError);
        }

        /// <summary>The implicit viscosity solve's rounds a sub-step, where the last frame's step was longer than the
        /// explicit viscous limit (<see cref="ImplicitViscosity"/>); nothing while the viscosity was explicit.</summary>
        public static StringBuilder AppendViscositySolve(StringBuilder text, int rounds) =>
            rounds > 0 ? text.AppendFormat(C, "Viscosity solved implicitly: {0} rounds per sub-step", rounds) : text;
    }
}
