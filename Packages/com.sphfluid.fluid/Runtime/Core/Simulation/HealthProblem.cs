using System.Globalization;

namespace SphFluid.Simulation
{
    /// <summary>The first thing found wrong with a simulated state: when, in which phase, which figure, its value
    /// and the bound it broke. <see cref="Message"/> is the one line the runner prints and Unity logs.</summary>
    public sealed class HealthProblem
    {
        /// <summary>Simulated time of the state, s.</summary>
        public double Time { get; }

        /// <summary>Phase name, or "all phases" for a figure of the whole fluid.</summary>
        public string Phase { get; }

        /// <summary>What was measured, e.g. "speed", "max compression", "mechanical energy".</summary>
        public string Figure { get; }

        public double Value { get; }

        public double Bound { get; }

        public string Message { get; }

        public HealthProblem(double time, string phase, string figure, double value, double bound, string unit, string why)
        {
            Time = time;
            Phase = phase;
            Figure = figure;
            Value = value;
            Bound = bound;
            Message = string.Format(CultureInfo.InvariantCulture,
                "unhealthy at t = {0:F3} s, phase '{1}': {2} {3:G4}{4} exceeds the bound {5:G4}{4} ({6})",
                time, phase, figure, value, string.IsNullOrEmpty(unit) ? "" : " " + unit, bound, why);
        }

        public override string ToString() => Message;
    }
}
