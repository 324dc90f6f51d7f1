using System.Collections.Generic;
using System.Linq;

namespace SphFluid.Headless.Output;

/// <summary>bench-scaling.png / .svg: milliseconds per sub-step (wall clock and GPU) against the particle count.</summary>
public static class BenchScalingChart
{
    public const string Stem = "bench-scaling";

    public static Chart Build(string sceneName, string deviceName, string solverName, IReadOnlyList<(int Particles, double WallMs, double GpuMs)> rows)
    {
        var chart = new Chart($"Bench scaling: {sceneName}, {solverName} on {deviceName}", "particles", "milliseconds per sub-step (ms)");
        double[] particles = rows.Select(r => (double)r.Particles).ToArray();
        var wall = chart.Plot.Add.Scatter(particles, rows.Select(r => r.WallMs).ToArray());
        wall.LegendText = "wall clock per sub-step (submit to idle)";
        wall.LineWidth = 2;
        wall.MarkerSize = 7;
        var gpu = chart.Plot.Add.Scatter(particles, rows.Select(r => r.GpuMs).ToArray());
        gpu.LegendText = "GPU per sub-step (sum of pass timestamps)";
        gpu.LineWidth = 2;
        gpu.MarkerSize = 7;
        gpu.MarkerShape = ScottPlot.MarkerShape.FilledSquare;
        chart.Plot.Axes.SetLimitsY(0, rows.Select(r => System.Math.Max(r.WallMs, r.GpuMs)).DefaultIfEmpty(1).Max() * 1.15);
        chart.LegendCorner = ScottPlot.Alignment.UpperLeft;
        return chart;
    }
}
