using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// What the DFSPH probes (<see cref="DeepColumnProbe"/>, <see cref="LockExchangeSliceProbe"/>) print: each report's
    /// iterations, cut-offs, compression of the first phase and fastest particle, and the averages of the iterations a
    /// sub-step and of that compression over the reports after a start time, which leaves the spawn out.
    /// </summary>
    sealed class SolveAverages
    {
        readonly double _from;
        int _reports;
        double _density, _divergence, _compression;

        public SolveAverages(double from) => _from = from;

        /// <summary>Prints the report as a progress line under <paramref name="label"/>, and counts it once past the start.</summary>
        public void Add(string label, double time, DiagnosticsReport report)
        {
            if (time > _from + 1e-6)
            {
                _reports++;
                _density += report.DensitySolveIterations;
                _divergence += report.DivergenceSolveIterations;
                _compression += report.Phases[0].AverageDensityError;
            }
            TestContext.Progress.WriteLine($"{label} t = {time:F2} s: constant-density iterations {report.DensitySolveIterations:F1} a sub-step " +
                $"({100 * report.DensitySolvesCutOff:F0} % cut off), divergence {report.DivergenceSolveIterations:F1}, " +
                $"{report.Phases[0].Name} average compression {100 * report.Phases[0].AverageDensityError:F3} %, fastest {report.MaxSpeed:F3} m/s");
        }

        /// <summary>"; from <paramref name="span"/>, iterations a sub-step: ..." for the reports counted, or nothing if none was.</summary>
        public string Summary(string span, string phase) => _reports > 0
            ? $"; from {span}, iterations a sub-step: constant-density {_density / _reports:F1}, divergence-free " +
              $"{_divergence / _reports:F1}, together {(_density + _divergence) / _reports:F1}; {phase} average compression " +
              $"{100 * _compression / _reports:F3} %"
            : "";
    }
}
