using System.Globalization;
using System.Linq;
using System.Text;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Output;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;

namespace SphFluid.Headless.Runs;

/// <summary>The outcome of a simulate run, as summary.txt and the closing line print it.</summary>
public sealed record RunSummary(LoadedScene Scene, FluidSimulation Simulation, string Device, double SimulatedSeconds, int Frames,
    int Substeps, int CappedFrames, double WallSeconds, int Snapshots, DiagnosticsReport? First, DiagnosticsReport? Last,
    FluidMeasures? Measures, string? Failure, string OutputDirectory)
{
    static readonly CultureInfo C = CultureInfo.InvariantCulture;

    public bool Ok => Failure == null;

    /// <summary>Particle exports written (particles_NNNN.vtu/.ply), 0 without --export-every.</summary>
    public int Exports { get; init; }

    /// <summary>The settings the run simulated (after the command line's overrides).</summary>
    public required FluidSettings Settings { get; init; }

    /// <summary>DFSPH: how much of the run's time its solves ran out of iterations (empty under WCSPH).</summary>
    public SolveCutOffs CutOffs { get; init; } = new SolveCutOffs();

    /// <summary>What a run whose DFSPH solves ran out in more than a tenth of its time should be told, or null.</summary>
    public string? CutOffWarning() => CutOffs.Warning(Settings);

    public string OneLine() => string.Format(C,
        "{0} ({11}): {1:F3} s simulated in {2} frames / {3} sub-steps, {4:F1} s wall ({5:F2} s per simulated s){6}; {7} snapshot(s){8}{9}; mass {10}",
        Ok ? "done" : "FAILED", SimulatedSeconds, Frames, Substeps, WallSeconds, SimulatedSeconds > 0 ? WallSeconds / SimulatedSeconds : 0,
        CappedFrames > 0 ? $", {CappedFrames} frame(s) capped at MaxSubsteps" : "", Snapshots,
        Exports > 0 ? $", {Exports} particle export(s)" : "",
        Measures != null && double.IsFinite(Measures.LayeringIndex) ? string.Format(C, "; layering index {0:F2}", Measures.LayeringIndex) : "",
        First != null && Last != null ? string.Format(C, "{0:G9} -> {1:G9} kg", First.TotalMass, Last.TotalMass) : "n/a",
        SolverChoice.ShortName(Settings.PressureSolver));

    public string ToText()
    {
        var b = new StringBuilder();
        b.AppendLine($"scene: {Scene.Path}");
        b.AppendLine($"device: {Device}");
        b.AppendLine($"particles: {Simulation.ParticleCount}");
        b.AppendLine(Simulation.Plan.ToString());
        b.AppendLine(SolverChoice.Describe(Settings, Simulation));
        b.AppendLine(string.Format(C, "simulated: {0:F4} s in {1} frames, {2} sub-steps ({3} capped frames)", SimulatedSeconds, Frames, Substeps, CappedFrames));
        b.AppendLine(string.Format(C, "wall clock: {0:F2} s", WallSeconds));
        b.AppendLine($"result: {(Ok ? "ok" : "FAILED: " + Failure)}");
        if (Settings.PressureSolver == PressureSolver.Dfsph)
            b.AppendLine(string.Format(C, "solves cut off at MaxSolverIterations: constant density in {0:P1} of the simulated time, divergence-free in {1:P1}",
                CutOffs.DensityShare, CutOffs.DivergenceShare));
        if (CutOffWarning() is string warning) b.AppendLine("warning: " + warning);
        if (First != null) b.AppendLine($"first diagnostics: {First}");
        if (Last != null) b.AppendLine($"last diagnostics:  {Last}");
        if (Measures != null) AppendMeasures(b, Measures);
        b.Append($"files: diagnostics.csv, frame_0000.png .. frame_{Snapshots - 1:D4}.png{(Simulation.Phases.Count > 1 ? ", layering.png, layering.svg" : "")}");
        if (Exports > 0) b.Append($", particles_0000.vtu/.ply .. particles_{Exports - 1:D4}.vtu/.ply, {ParticleExport.IndexName}");
        b.AppendLine(", summary.txt");
        return b.ToString();
    }

    void AppendMeasures(StringBuilder b, FluidMeasures m)
    {
        var phases = Simulation.Phases;
        b.AppendLine(string.Format(C, "final measures at t = {0:F4} s (heights along -gravity from the container's lowest corner; layers within one spacing of a face):", m.Time));
        b.AppendLine("  phase | compression avg / max | expansion avg / max | mean height m | bottom m | top m | floor share | wall share");
        for (int k = 0; k < phases.Count; k++)
        {
            var p = m.Phases[k];
            // A '|' in the name is escaped, as in Markdown, so that the bars still part the columns.
            b.AppendLine(string.Format(C, "  {0} | {1:P2} / {2:P2} | {3:P2} / {4:P2} | {5:F4} | {6:F4} | {7:F4} | {8:P1} | {9:P1}", MarkdownCell.Escape(phases[k].Name),
                p.CompressionAverage, p.CompressionMax, p.ExpansionAverage, p.ExpansionMax, p.MeanHeight, p.Bottom, p.Top, p.FloorShare, p.WallShare));
        }
        if (phases.Count > 1)
        {
            string order = string.Join(" < ", Enumerable.Range(0, phases.Count).OrderBy(k => m.Phases[k].MeanHeight).Select(k => phases[k].Name));
            b.AppendLine(string.Format(C, "layering index: {0:F3} (pairs of different density, (ordered - inverted) / pairs: 1 = perfectly layered, 0 = mixed, -1 = upside down); mean heights from the floor up: {1}", m.LayeringIndex, order));
            b.AppendLine(string.Format(C, "interface tilt: {0:F4} m (the least-squares plane through each interface between liquids rises by at most this across the floor; 0 = flat)", m.InterfaceTilt));
        }
        b.AppendLine(string.Format(C, "surge front: {0:F4} m from the back wall (container-local x, fluid within 2 spacings of the floor, spray ignored)", m.SurgeFront));
        b.AppendLine(string.Format(C, "column at the back wall: {0:F4} m above the floor", m.BackWallColumn));
        b.AppendLine(string.Format(C, "energy: kinetic {0:G6} J (GPU), potential {1:G6} J (above the container's lowest corner)", Last?.KineticEnergy ?? double.NaN, m.PotentialEnergy));
    }
}
