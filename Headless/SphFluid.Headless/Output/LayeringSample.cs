using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// Where each phase sits at one instant: its mean height above the container floor (container-local, so a
/// tilted box measures along its own up axis) and a layering index for multi-phase fluids:
/// (mean height of the lightest phase - mean height of the heaviest) / (H / 2), where H = fluid volume /
/// floor area is the depth of the settled pool. Perfect layers give 1 whatever the volume split
/// (the heavy layer's centre is f_h H / 2 up, the light one's f_h H + f_l H / 2), a uniform mix gives 0,
/// heavy over light gives a negative value.
/// </summary>
public sealed record LayeringSample(double Time, IReadOnlyList<double> MeanHeights, double LayeringIndex)
{
    public static LayeringSample Measure(double time, ReadOnlySpan<Particle> particles, IReadOnlyList<PhaseProperties> phases,
        ContainerDescription container, float particleSpacing)
    {
        var sum = new double[phases.Count];
        var count = new long[phases.Count];
        float floor = -container.Size.Y * 0.5f;
        foreach (var p in particles)
        {
            if (p.Phase >= phases.Count) continue;
            var q = container.ToLocal(p.Position);
            if (!float.IsFinite(q.Y)) continue;
            sum[p.Phase] += q.Y - floor;
            count[p.Phase]++;
        }
        var means = new double[phases.Count];
        for (int k = 0; k < means.Length; k++) means[k] = count[k] > 0 ? sum[k] / count[k] : double.NaN;

        double index = double.NaN;
        if (phases.Count > 1)
        {
            int light = 0, heavy = 0;
            for (int k = 1; k < phases.Count; k++)
            {
                if (phases[k].RestDensity < phases[light].RestDensity) light = k;
                if (phases[k].RestDensity > phases[heavy].RestDensity) heavy = k;
            }
            double volume = particles.Length * Math.Pow(particleSpacing, 3);
            double depth = volume / Math.Max(1e-12, container.Size.X * container.Size.Z);
            if (light != heavy && depth > 0) index = (means[light] - means[heavy]) / (0.5 * depth);
        }
        return new LayeringSample(time, means, index);
    }
}
