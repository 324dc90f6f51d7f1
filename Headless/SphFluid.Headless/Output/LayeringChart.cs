using System.Collections.Generic;
using System.Linq;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// layering.png / layering.svg for multi-phase runs: the mean height of each phase above the floor (along gravity
/// from the container's lowest corner) against simulated time, in the phase's colour, and the layering index on the
/// right axis ((ordered - inverted) / pairs: 1 = layered by density, 0 = mixed, -1 = upside down).
/// </summary>
public static class LayeringChart
{
    public const string Stem = "layering";

    public static Chart Build(string sceneName, IReadOnlyList<FluidMeasures> samples, IReadOnlyList<PhaseDescription> phases)
    {
        var chart = new Chart($"Layering over time: {sceneName}", "simulated time (s)", "mean height above the floor (m)");
        double[] times = samples.Select(s => s.Time).ToArray();
        for (int k = 0; k < phases.Count; k++)
        {
            double[] heights = samples.Select(s => s.Phases[k].MeanHeight).ToArray();
            var line = chart.Plot.Add.Scatter(times, heights);
            line.LegendText = $"{phases[k].Name} mean height (rho0 {phases[k].RestDensity:G4} kg/m^3)";
            System.Numerics.Vector4 c = phases[k].Color;
            line.Color = new ScottPlot.Color(Channel(c.X), Channel(c.Y), Channel(c.Z));
            line.LineWidth = 2;
            line.MarkerSize = 4;
        }
        var index = chart.Plot.Add.Scatter(times, samples.Select(s => s.LayeringIndex).ToArray());
        index.LegendText = "layering index (right axis)";
        index.Color = ScottPlot.Colors.Black;
        index.LineWidth = 2;
        index.MarkerSize = 0;
        index.Axes.YAxis = chart.Plot.Axes.Right;
        chart.Plot.Axes.Right.Label.Text = "layering index (1 layered, -1 upside down)";
        chart.LegendCorner = ScottPlot.Alignment.LowerRight;
        chart.Plot.Axes.SetLimitsY(-1.05, 1.05, chart.Plot.Axes.Right);
        chart.Plot.Axes.SetLimitsY(0, samples.SelectMany(s => s.Phases).Select(p => p.MeanHeight).Where(double.IsFinite).DefaultIfEmpty(0.1).Max() * 1.15, chart.Plot.Axes.Left);
        return chart;
    }

    /// <summary>Linear colour (as the scene stores it) to an sRGB byte, darkened a little so light phases show on white.</summary>
    static byte Channel(float linear)
    {
        double srgb = linear <= 0.0031308 ? 12.92 * linear : 1.055 * System.Math.Pow(linear, 1 / 2.4) - 0.055;
        return (byte)System.Math.Clamp(srgb * 0.85 * 255, 0, 255);
    }
}
