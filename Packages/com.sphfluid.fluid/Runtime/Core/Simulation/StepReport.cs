using System.Globalization;

namespace SphFluid.Simulation
{
    /// <summary>How one frame was covered: sub-step count and length, and whether the cap made it slower than real time.</summary>
    /// <remarks>A value, not an object: the solver plans one every frame, and a class would be garbage each time.</remarks>
    public readonly struct StepReport
    {
        public static readonly StepReport None = new StepReport(0, 0f, 0f, false, 0f, "none");

        /// <summary>Sub-steps run for the frame.</summary>
        public int Substeps { get; }

        /// <summary>Length of each sub-step, s.</summary>
        public float TimeStep { get; }

        /// <summary>Simulated time the frame advanced, s (= Substeps * TimeStep).</summary>
        public float SimulatedSeconds { get; }

        /// <summary>MaxSubsteps was reached: the frame's simulated time is shorter than its real time.</summary>
        public bool Capped { get; }

        /// <summary>The largest stable sub-step found from the conditions, s.</summary>
        public float StableTimeStep { get; }

        /// <summary>Which condition set <see cref="StableTimeStep"/>: "cfl", "gravity wave" (DFSPH), "acceleration", "viscous", "capillary" or "max".</summary>
        public string Limit => _limit ?? "none";

        /// <summary>The pressure solver the sub-steps ran.</summary>
        public PressureSolver PressureSolver { get; }

        readonly string _limit; // null only in default(StepReport), which reads as None

        public StepReport(int substeps, float timeStep, float simulatedSeconds, bool capped, float stableTimeStep, string limit,
            PressureSolver pressureSolver = PressureSolver.Wcsph)
        {
            PressureSolver = pressureSolver;
            Substeps = substeps;
            TimeStep = timeStep;
            SimulatedSeconds = simulatedSeconds;
            Capped = capped;
            StableTimeStep = stableTimeStep;
            _limit = limit;
        }

        public override string ToString() => string.Format(CultureInfo.InvariantCulture,
            "{0} sub-steps x {1:G4} ms = {2:G4} ms simulated (stable dt {3:G4} ms, limited by {4}){5}{6}",
            Substeps, TimeStep * 1000f, SimulatedSeconds * 1000f, StableTimeStep * 1000f, Limit,
            Capped ? ", capped: slower than real time" : "", PressureSolver == PressureSolver.Dfsph ? ", DFSPH" : "");
    }
}
