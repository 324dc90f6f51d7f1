using System.Collections.Generic;
using System.Globalization;
using System.Text;
using SphFluid.Runtime;
using SphFluid.Simulation;
using UnityEditor;
using UnityEngine;

namespace SphFluid.Editor
{
    /// <summary>
    /// The simulator's inspector: the default fields, then what the scene will spawn (or why it cannot start),
    /// and in play mode the live figures with Pause / Step / Reset, so an edited spawn box can be respawned at once.
    /// </summary>
    [CustomEditor(typeof(Fluid))]
    public sealed class FluidInspector : UnityEditor.Editor
    {
        public override bool RequiresConstantRepaint() => Application.isPlaying;

        public override void OnInspectorGUI()
        {
            DrawDefaultInspector();
            var simulator = (Fluid)target;
            EditorGUILayout.Space();
            if (Application.isPlaying) DrawRunning(simulator);
            else DrawScene(simulator);
        }

        static void DrawScene(Fluid simulator)
        {
            FluidSceneDescription scene = simulator.DescribeScene();
            IReadOnlyList<ValidationError> errors = scene.Validate();
            if (errors.Count > 0)
            {
                var lines = new List<string>();
                foreach (ValidationError e in errors) lines.Add(e.Message);
                EditorGUILayout.HelpBox("The simulation will not start:\n" + string.Join("\n", lines), MessageType.Error);
                return;
            }
            PipelineSummary(scene, out string summary);
            EditorGUILayout.HelpBox(summary, MessageType.Info);
        }

        static void PipelineSummary(FluidSceneDescription scene, out string summary)
        {
            SimulationPlan plan = PipelinePlanner.Plan(scene, false);
            summary = string.Format(CultureInfo.InvariantCulture, "{0} particles in {1} spawn box(es), {2} phase(s), {3} sphere(s)\nEffects: {4}",
                SpawnLayout.TotalCount(scene), scene.SpawnBoxes.Count, plan.PhaseCount, plan.ObstacleCount,
                plan.Keywords.Count == 0 ? "(none)" : string.Join(" ", plan.Keywords));
        }

        /// <summary>What the solver settings above cost while it runs: the frame's GPU time per simulated second, each
        /// phase's density error and the pressure solve's iterations, as the demo's on-screen readout words them.</summary>
        static string Cost(Fluid simulator, StepReport step)
        {
            // The running simulation's solver: the step report of a frame not yet stepped names none.
            bool dfsph = simulator.Simulation.Scene.Settings.PressureSolver == PressureSolver.Dfsph;
            var text = new StringBuilder(dfsph ? "Pressure solver: DFSPH\n" : "Pressure solver: WCSPH\n");
            if (simulator.TryGetGpuMilliseconds(out double gpu)) ReadoutText.AppendGpuCost(text, gpu, step);
            else text.Append(ReadoutText.GpuTimeUnavailable);
            DiagnosticsReport diagnostics = simulator.LatestDiagnostics;
            if (diagnostics == null)
                return text.Append("\nDensity error: no read-back yet (or Request Diagnostics is off)").ToString();
            foreach (PhaseDiagnostics phase in diagnostics.Phases) text.Append('\n').Append(phase);
            ReadoutText.AppendSolves(text.Append('\n'), diagnostics, simulator.Simulation);
            if (simulator.Simulation.ViscositySolveRounds > 0)
                ReadoutText.AppendViscositySolve(text.Append('\n'), simulator.Simulation.ViscositySolveRounds);
            return text.ToString();
        }

        static void DrawRunning(Fluid simulator)
        {
            if (!simulator.IsRunning)
            {
                EditorGUILayout.HelpBox("Not running: " + (simulator.FailureReason ?? "disabled"), MessageType.Warning);
            }
            else
            {
                StepReport step = simulator.LastStep;
                EditorGUILayout.LabelField("Particles", simulator.ParticleCount.ToString(CultureInfo.InvariantCulture));
                EditorGUILayout.LabelField("Simulated time", simulator.SimulatedTime.ToString("F2", CultureInfo.InvariantCulture) + " s");
                EditorGUILayout.LabelField("Sub-steps", string.Format(CultureInfo.InvariantCulture, "{0} x {1:F3} ms ({2}){3}",
                    step.Substeps, step.TimeStep * 1000f, step.Limit, step.Capped ? ", capped" : ""));
                EditorGUILayout.HelpBox(Cost(simulator, step), MessageType.None);
                if (simulator.HealthProblem != null)
                    EditorGUILayout.HelpBox("Paused by the health check: " + simulator.HealthProblem.Message, MessageType.Error);
            }
            using (new EditorGUILayout.HorizontalScope())
            {
                if (GUILayout.Button(simulator.IsPaused ? "Resume" : "Pause")) simulator.TogglePause();
                if (GUILayout.Button("Step")) simulator.StepOnce();
                if (GUILayout.Button("Reset (respawn)")) simulator.ResetSimulation();
            }
        }
    }
}
