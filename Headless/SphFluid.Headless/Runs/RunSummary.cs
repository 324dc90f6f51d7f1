using System.Globalization;
using System.Linq;
using System.Text;
using SphFluid.Headless.Output;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;

namespace SphFluid.Headless.Runs;

/// <summary>The outcome of a simulate run, as summary.txt and the closing line print it.</summary>
public sealed record RunSummary(LoadedScene Scene, FluidSimulation Simulation, string Device, double SimulatedSeconds, int Frames,
    int Substeps, int CappedFrames, double WallSeconds, int Snapshots, DiagnosticsReport First, DiagnosticsReport Last,
    LayeringSample Layering, string Failure, string OutputDirectory)
{
    static readonly CultureInfo C = CultureInfo.InvariantCulture;

    public bool Ok => Failure == null;

    public string OneLine() => string.Format(C,
        "{0}: {1:F3} s simulated in {2} frames / {3} sub-steps, {4:F1} s wall ({5:F2} s per simulated s){6}; {7} snapshot(s){8}; mass {9}",
        Ok ? "done" : "FAILED", SimulatedSeconds, Frames, Substeps, WallSeconds, SimulatedSeconds > 0 ? WallSeconds / SimulatedSeconds : 0,
        CappedFrames > 0 ? $", {CappedFrames} frame(s) capped at MaxSubsteps" : "", Snapshots,
        Layering != null && double.IsFinite(Layering.LayeringIndex) ? string.Format(C, "; layering index {0:F2}", Layering.LayeringIndex) : "",
        First != null && Last != null ? string.Format(C, "{0:G9} -> {1:G9} kg", First.TotalMass, Last.TotalMass) : "n/a");

    public string ToText()
    {
        var b = new StringBuilder();
        b.AppendLine($"scene: {Scene.Path}");
        b.AppendLine($"device: {Device}");
        b.AppendLine($"particles: {Simulation.ParticleCount}");
        b.AppendLine(Simulation.Plan.ToString());
        b.AppendLine(string.Format(C, "simulated: {0:F4} s in {1} frames, {2} sub-steps ({3} capped frames)", SimulatedSeconds, Frames, Substeps, CappedFrames));
        b.AppendLine(string.Format(C, "wall clock: {0:F2} s", WallSeconds));
        b.AppendLine($"result: {(Ok ? "ok" : "FAILED: " + Failure)}");
        if (First != null) b.AppendLine($"first diagnostics: {First}");
        if (Last != null) b.AppendLine($"last diagnostics:  {Last}");
        if (Layering != null)
        {
            var phases = Simulation.Phases;
            b.Append("final mean height above the floor:");
            for (int k = 0; k < phases.Count; k++) b.Append(string.Format(C, " {0} {1:F4} m", phases[k].Name, Layering.MeanHeights[k]));
            b.AppendLine();
            if (phases.Count > 1)
            {
                string order = string.Join(" < ", Enumerable.Range(0, phases.Count).OrderBy(k => Layering.MeanHeights[k]).Select(k => phases[k].Name));
                b.AppendLine(string.Format(C, "layering index: {0:F3} (1 = lightest phase fully above the heaviest, 0 = mixed); order from the floor up: {1}", Layering.LayeringIndex, order));
            }
        }
        b.AppendLine($"files: diagnostics.csv, frame_0000.png .. frame_{Snapshots - 1:D4}.png{(Simulation.Phases.Count > 1 ? ", layering.png" : "")}, summary.txt");
        return b.ToString();
    }
}
