using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// layering.png for multi-phase runs. Left panel: mean height of each phase above the floor against time
/// (phase colours; grey grid lines every tenth of the container height, time runs left to right over the
/// run) and the layering index in white (bottom edge -1, top edge 1). Right panel: the final vertical
/// profile, each height band split into the phases' shares of its particles (floor at the bottom). Heights
/// are measured against gravity from the container's lowest corner.
/// </summary>
public static class LayeringFigure
{
    const int PanelHeight = 320, ChartWidth = 480, ProfileWidth = 160, Gap = 16, Pad = 12;
    static readonly Rgb Background = new(18, 20, 26), Grid = new(60, 64, 72), Axis = new(150, 150, 150), Index = new(235, 235, 235);

    public static RgbImage Render(IReadOnlyList<FluidMeasures> samples, ReadOnlySpan<Particle> finalParticles,
        IReadOnlyList<PhaseProperties> phases, ContainerDescription container, Vector3 gravity)
    {
        var image = new RgbImage(Pad * 2 + ChartWidth + Gap + ProfileWidth, Pad * 2 + PanelHeight);
        image.Fill(Background);
        var colors = new Rgb[phases.Count];
        for (int k = 0; k < phases.Count; k++) colors[k] = Rgb.FromLinear(phases[k].Color.X, phases[k].Color.Y, phases[k].Color.Z);
        var frame = new GravityFrame(container, gravity);
        double height = frame.Extent;

        // Chart frame and grid.
        int x0 = Pad, y0 = Pad, x1 = Pad + ChartWidth, y1 = Pad + PanelHeight;
        for (int g = 1; g < 10; g++)
        {
            float y = y1 - g * PanelHeight / 10f;
            image.DrawLine(x0, y, x1, y, Grid);
        }
        Frame(image, x0, y0, x1, y1);
        if (samples.Count > 0)
        {
            double t0 = samples[0].Time, t1 = Math.Max(samples[^1].Time, t0 + 1e-9);
            float X(double t) => (float)(x0 + (t - t0) / (t1 - t0) * ChartWidth);
            float YHeight(double h) => (float)(y1 - Math.Clamp(h / height, 0, 1) * PanelHeight);
            float YIndex(double i) => (float)(y1 - (Math.Clamp(i, -1, 1) + 1) / 2 * PanelHeight);
            for (int s = 1; s < samples.Count; s++)
            {
                var a = samples[s - 1];
                var b = samples[s];
                for (int k = 0; k < phases.Count; k++)
                {
                    double ha = a.Phases[k].MeanHeight, hb = b.Phases[k].MeanHeight;
                    if (!double.IsFinite(ha) || !double.IsFinite(hb)) continue;
                    for (int w = -1; w <= 1; w++)
                        image.DrawLine(X(a.Time), YHeight(ha) + w, X(b.Time), YHeight(hb) + w, colors[k]);
                }
                if (double.IsFinite(a.LayeringIndex) && double.IsFinite(b.LayeringIndex))
                    image.DrawLine(X(a.Time), YIndex(a.LayeringIndex), X(b.Time), YIndex(b.LayeringIndex), Index);
            }
        }

        // Final profile: bands of the container height, each split by phase share.
        int px0 = x1 + Gap, px1 = px0 + ProfileWidth;
        const int bands = 40;
        var counts = new int[bands, Math.Max(1, phases.Count)];
        foreach (var p in finalParticles)
        {
            if (p.Phase >= phases.Count) continue;
            double h = frame.HeightOf(p.Position);
            if (!double.IsFinite(h)) continue;
            int band = Math.Clamp((int)(h / height * bands), 0, bands - 1);
            counts[band, p.Phase]++;
        }
        for (int band = 0; band < bands; band++)
        {
            int total = 0;
            for (int k = 0; k < phases.Count; k++) total += counts[band, k];
            if (total == 0) continue;
            int top = y1 - (band + 1) * PanelHeight / bands, bottom = y1 - band * PanelHeight / bands;
            float x = px0;
            for (int k = 0; k < phases.Count; k++)
            {
                float w = (float)counts[band, k] / total * ProfileWidth;
                for (int y = top; y < bottom; y++)
                    for (int xi = (int)MathF.Round(x); xi < (int)MathF.Round(x + w); xi++) image.Set(xi, y, colors[k]);
                x += w;
            }
        }
        Frame(image, px0, y0, px1, y1);
        return image;
    }

    static void Frame(RgbImage image, int x0, int y0, int x1, int y1)
    {
        image.DrawLine(x0, y0, x1, y0, Axis);
        image.DrawLine(x1, y0, x1, y1, Axis);
        image.DrawLine(x1, y1, x0, y1, Axis);
        image.DrawLine(x0, y1, x0, y0, Axis);
    }
}
