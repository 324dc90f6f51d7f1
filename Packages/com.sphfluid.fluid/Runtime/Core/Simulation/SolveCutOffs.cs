using System;
using System.Globalization;

namespace SphFluid.Simulation
{
    /// <summary>
    /// How much of a run's simulated time DFSPH's solves ran out of iterations before their tolerance, summed over its
    /// diagnostics reports (each report's share of the solves since the report before, weighted by the time it covers),
    /// and what a run above <see cref="WarningShare"/> should be told. Such a run is healthy, but it holds its error above
    /// the tolerance it asked for and pays the whole iteration budget in those sub-steps, while the pressure each solve
    /// starts from climbs. A fluid that fills its closed container exactly is one cause: it reads compressed at the
    /// tolerance itself and has no free volume to give (Headless/docs/known-limits.md).
    /// </summary>
    public sealed class SolveCutOffs
    {
        /// <summary>Above this share of the time cut off, <see cref="Warning"/> speaks.</summary>
        public const double WarningShare = 0.1;

        double _lastTime = double.NaN, _observed, _density, _divergence;

        /// <summary>Simulated seconds the reports so far cover.</summary>
        public double ObservedSeconds => _observed;

        /// <summary>Share of <see cref="ObservedSeconds"/> whose constant-density solves were cut off.</summary>
        public double DensityShare => _observed > 0 ? _density / _observed : 0;

        /// <summary>Share of <see cref="ObservedSeconds"/> whose divergence-free solves were cut off.</summary>
        public double DivergenceShare => _observed > 0 ? _divergence / _observed : 0;

        /// <summary>Adds a report's shares of solves cut off since the report before (a report at the same time or
        /// earlier, as after a reset, starts the count again).</summary>
        public void Observe(double simulatedTime, double densityCutOff, double divergenceCutOff)
        {
            if (!(simulatedTime > _lastTime))
            {
                if (simulatedTime < _lastTime) _observed = _density = _divergence = 0;
                _lastTime = simulatedTime;
                return;
            }
            double covered = simulatedTime - _lastTime;
            _lastTime = simulatedTime;
            _observed += covered;
            _density += covered * densityCutOff;
            _divergence += covered * divergenceCutOff;
        }

        public void Observe(DiagnosticsReport report)
        {
            if (report == null) throw new ArgumentNullException(nameof(report));
            Observe(report.SimulatedTime, report.DensitySolvesCutOff, report.DivergenceSolvesCutOff);
        }

        /// <summary>What to tell a DFSPH run whose solves ran out in more than <see cref="WarningShare"/> of its time, or
        /// null.</summary>
        public string Warning(FluidSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            if (settings.PressureSolver != PressureSolver.Dfsph || !(Math.Max(DensityShare, DivergenceShare) > WarningShare)) return null;
            // The Jacobi solve's rounds grow with the square of the fluid's depth in spacings: at 100k and 250k particles
            // OilAndWater's took 58.8 and 64.2 a sub-step at 0.1 % on an H200 and ran at their cap of 100 at 0.01 %, where
            // the accelerated solve's took 17 to 20 at every size to 2M (Headless/docs/accuracy-for-time.md), so a larger
            // budget is the dearer cure there.
            string accelerate = settings.SolverIteration == SolverIteration.Jacobi
                ? "Set SolverIteration to Chebyshev (the Jacobi solve's iterations grow with the square of the fluid's depth in " +
                  "spacings, the accelerated solve's with the depth), raise"
                : "Raise";
            return string.Format(CultureInfo.InvariantCulture,
                "DFSPH's solves ran out of their {0} iterations (MaxSolverIterations) in {1:P0} of the simulated time's " +
                "constant-density solves and {2:P0} of its divergence-free ones: the errors exceeded the tolerances of {3} % " +
                "and {4} %/s there, and each such sub-step cost the whole budget. {5} MaxSolverIterations, loosen the " +
                "density or divergence tolerance, or leave the fluid free volume: a fluid that fills its closed container " +
                "exactly cannot get below the tolerance.",
                settings.MaxSolverIterations, DensityShare, DivergenceShare, settings.DensityTolerance, settings.DivergenceTolerance,
                accelerate);
        }
    }
}
