using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace SphFluid.Simulation
{
    /// <summary>Per-phase part of a <see cref="DiagnosticsReport"/>.</summary>
    public sealed class PhaseDiagnostics
    {
        public string Name { get; }
        public int Count { get; private set; }

        /// <summary>Mean compression max(0, rho / rho0 - 1) over the phase's particles (Ihmsen et al. 2014's measure:
        /// free-surface particles are under-dense by construction and would hide compression in a signed mean).</summary>
        public float AverageDensityError { get; private set; }

        /// <summary>Largest compression max(0, rho / rho0 - 1) over the phase's particles.</summary>
        public float MaxDensityError { get; private set; }

        public PhaseDiagnostics(string name, int count, float averageDensityError, float maxDensityError)
        {
            Name = name;
            Count = count;
            AverageDensityError = averageDensityError;
            MaxDensityError = maxDensityError;
        }

        /// <summary>New figures for the same phase (FluidSimulation.LatestDiagnostics reuses its report).</summary>
        internal void Refill(int count, float averageDensityError, float maxDensityError)
        {
            Count = count;
            AverageDensityError = averageDensityError;
            MaxDensityError = maxDensityError;
        }

        public override string ToString() => string.Format(CultureInfo.InvariantCulture,
            "{0}: {1} particles, density error avg {2:P2} max {3:P2}", Name, Count, AverageDensityError, MaxDensityError);
    }

    /// <summary>Whole-fluid health figures, from GPU reductions.</summary>
    public sealed class DiagnosticsReport
    {
        /// <summary>Sum of particle masses, kg (from per-phase counts times the phase mass: exact).</summary>
        public double TotalMass { get; private set; }

        /// <summary>Sum of m v^2 / 2, J.</summary>
        public double KineticEnergy { get; private set; }

        public float MaxSpeed { get; private set; }

        /// <summary>Particles with a NaN or infinite position or velocity component.</summary>
        public int NanCount { get; private set; }

        /// <summary>Particles outside the container box.</summary>
        public int OutsideCount { get; private set; }

        public IReadOnlyList<PhaseDiagnostics> Phases { get; }

        /// <summary>Particles the last-resort clamp behind the boundary particles has caught since spawn
        /// (each catch once per integration half-step); zero in a healthy run.</summary>
        public int ClampHits { get; private set; }

        /// <summary>DFSPH: mean iterations per constant-density solve since the previous report (the shader counts per solve;
        /// a sub-step runs one solve of each kind, so this is also per sub-step); 0 with WCSPH.</summary>
        public float DensitySolveIterations { get; internal set; }

        /// <summary>DFSPH: mean iterations per divergence-free solve since the previous report (the shader counts per solve;
        /// a sub-step runs one solve of each kind, so this is also per sub-step); 0 with WCSPH.</summary>
        public float DivergenceSolveIterations { get; internal set; }

        /// <summary>DFSPH: share (0 to 1) of the constant-density solves since the previous report that ran out of their
        /// recorded rounds (MaxSolverIterations, or fewer by FluidSimulation.SolveBudget) before reaching DensityTolerance;
        /// 0 with WCSPH. Above 0 the density error may exceed the tolerance, and a tighter tolerance buys nothing but the
        /// same capped cost, which the iteration means alone do not tell.</summary>
        public float DensitySolvesCutOff { get; internal set; }

        /// <summary>DFSPH: the same share for the divergence-free solves and DivergenceTolerance.</summary>
        public float DivergenceSolvesCutOff { get; internal set; }

        /// <summary>Average |D rho / Dt| / rho0 over the fluid, %/s: how far the velocity field is from
        /// divergence-free (the divergence error of the accuracy study).</summary>
        public float DivergenceError { get; internal set; }

        /// <summary>The pressure solver of the simulation the figures come from.</summary>
        public PressureSolver PressureSolver { get; internal set; }

        /// <summary>Simulated time of the state the figures describe, s.</summary>
        public double SimulatedTime { get; private set; }

        public int ParticleCount
        {
            get
            {
                int n = 0;
                for (int k = 0; k < Phases.Count; k++) n += Phases[k].Count; // not foreach: an interface's enumerator is garbage
                return n;
            }
        }

        public DiagnosticsReport(double totalMass, double kineticEnergy, float maxSpeed, int nanCount, int outsideCount,
            IReadOnlyList<PhaseDiagnostics> phases, double simulatedTime, int clampHits = 0)
        {
            ClampHits = clampHits;
            TotalMass = totalMass;
            KineticEnergy = kineticEnergy;
            MaxSpeed = maxSpeed;
            NanCount = nanCount;
            OutsideCount = outsideCount;
            Phases = phases;
            SimulatedTime = simulatedTime;
        }

        /// <summary>New whole-fluid figures in the same report, so that a running simulation's read-backs make no
        /// garbage (FluidSimulation.LatestDiagnostics); the phases are refilled by their owner.</summary>
        internal void Refill(double totalMass, double kineticEnergy, float maxSpeed, int nanCount, int outsideCount,
            double simulatedTime, int clampHits)
        {
            TotalMass = totalMass;
            KineticEnergy = kineticEnergy;
            MaxSpeed = maxSpeed;
            NanCount = nanCount;
            OutsideCount = outsideCount;
            SimulatedTime = simulatedTime;
            ClampHits = clampHits;
        }

        public override string ToString()
        {
            var b = new StringBuilder();
            b.AppendFormat(CultureInfo.InvariantCulture, "t={0:F3} s mass={1:G6} kg KE={2:G4} J vmax={3:G4} m/s nan={4} outside={5} clamped={6}",
                SimulatedTime, TotalMass, KineticEnergy, MaxSpeed, NanCount, OutsideCount, ClampHits);
            b.AppendFormat(CultureInfo.InvariantCulture, " div={0:G3} %/s", DivergenceError);
            if (PressureSolver == PressureSolver.Dfsph)
                b.AppendFormat(CultureInfo.InvariantCulture, " DFSPH iterations density {0:F1} ({1:P0} cut off) divergence {2:F1} ({3:P0} cut off)",
                    DensitySolveIterations, DensitySolvesCutOff, DivergenceSolveIterations, DivergenceSolvesCutOff);
            foreach (var p in Phases) b.Append(" | ").Append(p);
            return b.ToString();
        }
    }
}
