using System.Collections.Generic;
using System.Globalization;
using System.Text;
using SphFluid.Runtime;
using SphFluid.Simulation;
using UnityEngine;

namespace SphFluid.Demo
{
    /// <summary>On-screen figures of the running simulation (IMGUI): FPS, particles, sub-steps and dt, GPU time,
    /// density error per phase, the effects the planner switched on.</summary>
    /// <remarks>
    /// Formatting numbers makes strings, so the text is composed a few times a second and the same string is
    /// drawn in between; IMGUI itself still allocates in OnGUI, which is why the fluid's own frames are
    /// measured without a readout (FluidPlayModeTests).
    /// </remarks>
    public sealed class FluidReadout : MonoBehaviour
    {
        [SerializeField, Tooltip("The simulator shown; empty = the scene's Fluid.")]
        Fluid simulator = null;

        [SerializeField, Tooltip("Show the readout.")]
        bool visible = true;

        [SerializeField, Range(8, 40), Tooltip("Text size, points.")]
        int fontSize = 14;

        /// <summary>Seconds between two compositions of the text (real time).</summary>
        public const float RefreshSeconds = 0.25f;

        readonly StringBuilder _text = new StringBuilder();
        string _shown = "";
        float _nextRefresh;
        readonly SimulatorTarget _target = new SimulatorTarget();
        GUIStyle _style;
        float _smoothedDelta = 1f / 60f;

        public bool Visible
        {
            get => visible;
            set => visible = value;
        }

        void Update()
        {
            _smoothedDelta = Mathf.Lerp(_smoothedDelta, Time.unscaledDeltaTime, 0.05f);
        }

        void OnGUI()
        {
            if (!visible) return;
            if (_style == null || _style.fontSize != fontSize)
                _style = new GUIStyle(GUI.skin.label) { fontSize = fontSize, richText = false };
            if (Event.current.type == EventType.Layout && Time.unscaledTime >= _nextRefresh)
            {
                // Layout comes before Repaint in each OnGUI round, so both draw the same text.
                _nextRefresh = Time.unscaledTime + RefreshSeconds;
                Compose(_target.Resolve(simulator));
                _shown = _text.ToString();
            }
            GUILayout.BeginArea(new Rect(10f, 10f, Mathf.Min(560f, Screen.width - 20f), Screen.height - 20f));
            GUILayout.BeginVertical(GUI.skin.box);
            GUILayout.Label(_shown, _style);
            GUILayout.EndVertical();
            GUILayout.EndArea();
        }

        void Compose(Fluid target)
        {
            CultureInfo c = CultureInfo.InvariantCulture;
            _text.Clear();
            _text.AppendFormat(c, "FPS {0:F1} ({1:F1} ms)\n", 1f / Mathf.Max(_smoothedDelta, 1e-6f), _smoothedDelta * 1000f);
            if (target == null)
            {
                _text.Append("No Fluid in the scene");
                return;
            }
            if (!target.IsRunning)
            {
                _text.Append("Not running: ").Append(target.FailureReason ?? "disabled");
                return;
            }

            _text.AppendFormat(c, "Particles {0}   t = {1:F2} s{2}\n", target.ParticleCount, target.SimulatedTime, target.IsPaused ? "   PAUSED" : "");
            if (target.HealthProblem != null)
                _text.Append("UNHEALTHY, paused (R resets): ").Append(target.HealthProblem.Message).Append('\n');
            StepReport step = target.LastStep;
            _text.AppendFormat(c, "{5}: sub-steps {0} x dt {1:F3} ms (stable {2:F3} ms, limited by {3}){4}\n",
                step.Substeps, step.TimeStep * 1000f, step.StableTimeStep * 1000f, step.Limit, step.Capped ? "  CAPPED: slower than real time" : "",
                step.PressureSolver == PressureSolver.Dfsph ? "DFSPH" : "WCSPH");
            if (target.TryGetGpuMilliseconds(out double gpu))
                ReadoutText.AppendGpuCost(_text, gpu, step);
            else
                _text.Append(ReadoutText.GpuTimeUnavailable);
            _text.Append('\n');

            DiagnosticsReport diagnostics = target.LatestDiagnostics;
            if (diagnostics != null)
            {
                foreach (PhaseDiagnostics phase in diagnostics.Phases)
                    _text.Append(phase).Append('\n');
                _text.AppendFormat(c, "vmax {0:F2} m/s   KE {1:G3} J   NaN {2}   outside {3}\n",
                    diagnostics.MaxSpeed, diagnostics.KineticEnergy, diagnostics.NanCount, diagnostics.OutsideCount);
                FluidSimulation simulation = target.Simulation;
                if (simulation != null) ReadoutText.AppendSolves(_text, diagnostics, simulation).Append('\n');
                if (simulation != null && simulation.ViscositySolveRounds > 0)
                    ReadoutText.AppendViscositySolve(_text, simulation.ViscositySolveRounds).Append('\n');
            }

            SimulationPlan plan = target.Plan;
            if (plan != null)
            {
                _text.Append("Effects: ");
                if (plan.Keywords.Count == 0) _text.Append("(single phase, no extras)");
                AppendJoined(plan.Keywords, " ");
                if (plan.Damping) _text.Append(" DAMPING");
                _text.Append('\n').Append("Sub-step: ");
                AppendJoined(plan.SubstepPasses, " > ");
                _text.Append('\n');
            }
            _text.Append("RMB orbit  wheel zoom  LMB drag sphere  Space pause  . / N step  R reset  Tab next scene");
        }

        void AppendJoined(IReadOnlyList<string> items, string separator)
        {
            for (int i = 0; i < items.Count; i++)
            {
                if (i > 0) _text.Append(separator);
                _text.Append(items[i]);
            }
        }
    }
}
