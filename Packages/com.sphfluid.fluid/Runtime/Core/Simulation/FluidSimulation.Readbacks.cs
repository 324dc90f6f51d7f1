using System;
using System.Numerics;
using SphFluid.Compute;

namespace SphFluid.Simulation
{
    /// <summary>The read-backs: the motion reduction that feeds the time step (and the DFSPH solve budget) and the
    /// diagnostics, each asynchronous in a frame and blocking for tools and tests.</summary>
    public sealed partial class FluidSimulation
    {
        /// <summary>Latest diagnostics read back asynchronously (after <see cref="RequestDiagnostics"/>);
        /// null until one arrives, possibly a frame stale (see <see cref="DiagnosticsReport.SimulatedTime"/>).
        /// The simulation refills this one report in place when a newer read-back arrives (a report a frame would
        /// be garbage a frame): read its figures now, or use <see cref="ReadDiagnostics"/> for a report to keep.</summary>
        public DiagnosticsReport LatestDiagnostics
        {
            get
            {
                PollDiagnostics();
                return _latestDiagnostics;
            }
            private set => _latestDiagnostics = value;
        }

        /// <summary>Records the diagnostics reductions and starts their asynchronous read-back
        /// (ignored while the previous one is still in flight).</summary>
        public void RequestDiagnostics()
        {
            ThrowIfDisposed();
            PollDiagnostics();
            if (_diagnosticsReadback != null) return;
            DispatchDiagnostics();
            _diagnosticsReadback = _device.RequestReadback(_buffers.DiagnosticsTotals);
            _diagnosticsRequestTime = SimulatedTime;
            _device.Submit();
        }

        /// <summary>Blocking diagnostics of the current state (tools and tests).</summary>
        public DiagnosticsReport ReadDiagnostics()
        {
            ThrowIfDisposed();
            DispatchDiagnostics();
            var rows = new Vector4[3 + _phases.Count];
            _buffers.DiagnosticsTotals.GetData(rows);
            return ToReport(rows, SimulatedTime);
        }

        void DispatchDiagnostics()
        {
            PushConstants();
            FindNeighbours(); // DivergenceRate reads them; after a shift they are found again
            _device.BeginSample(PassNames.Diagnostics);
            _device.DispatchThreads(_solver, _kernels.DivergenceRate, ParticleCount);
            _device.Dispatch(_diagnostics, _diagnosticsPartial, _reductionGroups, 1, 1);
            _device.Dispatch(_diagnostics, _diagnosticsFinal, 1, 1, 1);
            _device.EndSample(PassNames.Diagnostics);
        }

        void PollDiagnostics()
        {
            if (_diagnosticsReadback == null || !_diagnosticsReadback.IsDone) return;
            var request = _diagnosticsReadback;
            _diagnosticsReadback = null;
            if (request.HasError) return;
            request.GetData(_diagnosticsRows);
            if (_diagnosticsReport == null)
            {
                _diagnosticsPhases = NewPhaseRows();
                _diagnosticsReport = new DiagnosticsReport(0, 0, 0f, 0, 0, _diagnosticsPhases, 0);
            }
            Refill(_diagnosticsReport, _diagnosticsPhases, _diagnosticsRows, _diagnosticsRequestTime);
            _latestDiagnostics = _diagnosticsReport;
        }

        PhaseDiagnostics[] NewPhaseRows()
        {
            var phases = new PhaseDiagnostics[_phases.Count];
            for (int k = 0; k < phases.Length; k++)
                phases[k] = new PhaseDiagnostics(_phases[k].Name, 0, 0f, 0f);
            return phases;
        }

        DiagnosticsReport ToReport(Vector4[] rows, double time)
        {
            var phases = NewPhaseRows();
            var report = new DiagnosticsReport(0, 0, 0f, 0, 0, phases, time);
            Refill(report, phases, rows, time);
            return report;
        }

        /// <summary>Rows of DiagnosticsFinal: [0] KE, vmax, NaN count, outside count; [1 + k] phase k's count,
        /// mean and max compression; [1 + phases] clamp hits and the shares of the DFSPH solves cut off; [2 + phases]
        /// mean |D delta / Dt| / delta0 (1/s) and the DFSPH solves' mean corrections per solve.</summary>
        void Refill(DiagnosticsReport report, PhaseDiagnostics[] phases, Vector4[] rows, double time)
        {
            double mass = 0;
            for (int k = 0; k < phases.Length; k++)
            {
                Vector4 row = rows[1 + k];
                int count = (int)Math.Round(row.X);
                mass += (double)count * _phaseTable[k].ParticleMass;
                phases[k].Refill(count, row.Y, row.Z);
            }
            report.Refill(mass, rows[0].X, rows[0].Y, (int)Math.Round(rows[0].Z), (int)Math.Round(rows[0].W), time,
                (int)Math.Round(rows[1 + _phases.Count].X));
            Vector4 solves = rows[2 + _phases.Count];
            report.DivergenceError = 100f * solves.X;
            report.DensitySolveIterations = solves.Y;
            report.DivergenceSolveIterations = solves.Z;
            report.DensitySolvesCutOff = rows[1 + _phases.Count].Y;
            report.DivergenceSolvesCutOff = rows[1 + _phases.Count].Z;
            report.PressureSolver = _scene.Settings.PressureSolver;
        }

        void RequestMotion()
        {
            if (_motionReadback != null) return; // one in flight: the controller plans with the older figures meanwhile
            _device.BeginSample(PassNames.MotionReduction);
            _device.Dispatch(_diagnostics, _motionPartial, _reductionGroups, 1, 1);
            _device.Dispatch(_diagnostics, _motionFinal, 1, 1, 1);
            _device.EndSample(PassNames.MotionReduction);
            _motionReadback = _device.RequestReadback(_buffers.MotionTotals);
        }

        void PollMotion()
        {
            if (_motionReadback == null || !_motionReadback.IsDone) return;
            var request = _motionReadback;
            _motionReadback = null;
            if (request.HasError) return;
            request.GetData(_motionRow);
            _timeStep.ReportMotion(_motionRow[0].X, _motionRow[0].Y);
            ReportSolveIterations(_motionRow[1]);
        }

        /// <summary>Reads max |v| and max |a| now (blocking) and feeds the time-step controller.</summary>
        public void ReadMotion(out float maxSpeed, out float maxAcceleration)
        {
            ThrowIfDisposed();
            PushConstants();
            _device.Dispatch(_diagnostics, _motionPartial, _reductionGroups, 1, 1);
            _device.Dispatch(_diagnostics, _motionFinal, 1, 1, 1);
            _buffers.MotionTotals.GetData(_motionRow);
            ReportSolveIterations(_motionRow[1]);
            maxSpeed = _motionRow[0].X;
            maxAcceleration = _motionRow[0].Y;
        }
    }
}
