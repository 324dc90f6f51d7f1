using System;
using System.Collections.Generic;
using System.Linq;
using SphFluid.Headless.Runs;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// study-pareto.png / .svg: each configuration's observable error against its wall time per simulated second, both on
/// log axes (ticks at powers of ten), one series per solver (and iteration scheme, and divergence tolerance). The
/// reference run has no error by definition and is drawn at the floor of the error axis.
/// </summary>
public static class StudyParetoChart
{
    public const string Stem = "study-pareto";
    public const double ErrorFloor = 1e-4;

    static readonly ScottPlot.MarkerShape[] Markers =
    {
        ScottPlot.MarkerShape.FilledCircle, ScottPlot.MarkerShape.FilledSquare, ScottPlot.MarkerShape.FilledDiamond,
        ScottPlot.MarkerShape.FilledTriangleUp, ScottPlot.MarkerShape.FilledTriangleDown, ScottPlot.MarkerShape.OpenCircle,
    };

    public static Chart Build(string sceneName, string deviceName, IReadOnlyList<StudyRun.Row> rows)
    {
        var chart = new Chart($"Accuracy for time: {sceneName} on {deviceName}", "wall time per simulated second (ms, log)",
            "observable error vs finest run (relative, log)");
        // One series per solver, per iteration scheme of DFSPH and per divergence tolerance the study was given
        // (StudyRun.Configuration.Series), in the matrix's order.
        int drawn = 0;
        foreach (var mine in rows.Where(r => double.IsFinite(r.ObservableError) && r.WallMsPerSecond > 0).GroupBy(r => r.Config.Series))
        {
            var series = chart.Plot.Add.ScatterPoints(mine.Select(r => Math.Log10(r.WallMsPerSecond)).ToArray(),
                mine.Select(r => Math.Log10(Math.Max(r.ObservableError, ErrorFloor))).ToArray());
            series.LegendText = Legend(mine.First().Config, mine.Select(r => r.Config));
            series.MarkerSize = 9;
            series.MarkerShape = Markers[drawn++ % Markers.Length];
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

    /// <summary>What varies along a series: WCSPH's stiffness multiples, or DFSPH's density tolerances.</summary>
    static string Legend(StudyRun.Configuration first, IEnumerable<StudyRun.Configuration> configs)
    {
        var c = System.Globalization.CultureInfo.InvariantCulture;
        if (first.Solver != PressureSolver.Dfsph)
            return "WCSPH (Tait stiffness x " + string.Join(", ", configs.Select(k => k.StiffnessFactor.ToString("G3", c)).Distinct()) + ")";
        string tolerances = string.Join(", ", configs.Select(k => k.DensityTolerance.ToString("G3", c)).Distinct()) + " %";
        string name = first.Iteration == SolverIteration.Chebyshev ? "DFSPH Chebyshev-accelerated" : "DFSPH";
        return first.NamesDivergence
            ? string.Format(c, "{0} (density tolerance {1}; divergence {2:G3} %/s)", name, tolerances, first.DivergenceTolerance)
            : string.Format(c, "{0} (density tolerance {1})", name, tolerances);
    }
}
