using System;
using System.Collections.Generic;
using System.Linq;
using SphFluid.Headless.Runs;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// study-pareto.png / .svg: each configuration's observable error against its wall time per simulated second, both on
/// log axes (ticks at powers of ten), one series per solver. The reference run has no error by definition and is drawn
/// at the floor of the error axis.
/// </summary>
public static class StudyParetoChart
{
    public const string Stem = "study-pareto";
    public const double ErrorFloor = 1e-4;

    /// <summary>One series per solver, and per iteration scheme of DFSPH (StudyRun.Configuration.Series).</summary>
    static readonly (string Name, string Legend, ScottPlot.MarkerShape Marker)[] Series =
    {
        ("WCSPH", "WCSPH (Tait stiffness multiples)", ScottPlot.MarkerShape.FilledCircle),
        ("DFSPH", "DFSPH (density tolerance 1, 0.1, 0.01 %)", ScottPlot.MarkerShape.FilledSquare),
        ("DFSPH Chebyshev", "DFSPH Chebyshev-accelerated (1, 0.1, 0.01 %)", ScottPlot.MarkerShape.FilledDiamond),
    };

    public static Chart Build(string sceneName, string deviceName, IReadOnlyList<StudyRun.Row> rows)
    {
        var chart = new Chart($"Accuracy for time: {sceneName} on {deviceName}", "wall time per simulated second (ms, log)",
            "observable error vs finest run (relative, log)");
        foreach (var (name, legend, marker) in Series)
        {
            var mine = rows.Where(r => r.Config.Series == name && double.IsFinite(r.ObservableError) && r.WallMsPerSecond > 0).ToList();
            if (mine.Count == 0) continue;
            var series = chart.Plot.Add.ScatterPoints(mine.Select(r => Math.Log10(r.WallMsPerSecond)).ToArray(),
                mine.Select(r => Math.Log10(Math.Max(r.ObservableError, ErrorFloor))).ToArray());
            series.LegendText = legend;
            series.MarkerSize = 9;
            series.MarkerShape = marker;
        }
        // Errors span decades (ticks at powers of ten); wall times may span less than one (ticks between them too).
        foreach (var (axis, decades) in new (ScottPlot.IAxis, bool)[] { (chart.Plot.Axes.Bottom, false), (chart.Plot.Axes.Left, true) })
            axis.TickGenerator = new ScottPlot.TickGenerators.NumericAutomatic
            {
                MinorTickGenerator = new ScottPlot.TickGenerators.LogMinorTickGenerator(),
                IntegerTicksOnly = decades,
                LabelFormatter = v => Math.Pow(10, v).ToString("G3", System.Globalization.CultureInfo.InvariantCulture),
            };
        chart.Plot.Axes.Margins(0.15, 0.15);
        chart.LegendBelow = true; // the points can fall in any corner
        return chart;
    }
}
