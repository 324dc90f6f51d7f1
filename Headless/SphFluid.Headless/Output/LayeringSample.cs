using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// Where each phase sits at one instant: its mean height above the lowest corner of the container, measured
/// against gravity (so a turning box still measures "up" as the fluid feels it), and a layering index for
/// multi-phase fluids:
/// (mean height of the lightest phase - mean height of the heaviest) / (H / 2), where H = fluid volume /
/// floor area (of the upright box) is the depth of the settled pool. Perfect layers give 1 whatever the volume split
/// (the heavy layer's centre is f_h H / 2 up, the light one's f_h H + f_l H / 2), a uniform mix gives 0,
/// heavy over light gives a negative value.
/// </summary>
public sealed record LayeringSample(double Time, IReadOnlyList<double> MeanHeights, double LayeringIndex)
{
    public static LayeringSample Measure(double time, ReadOnlySpan<Particle> particles, IReadOnlyList<PhaseProperties> phases,
        ContainerDescription container, Vector3 gravity, float particleSpacing)
    {
        var sum = new double[phases.Count];
        var count = new long[phases.Count];
        var (up, floor, _) = Vertical(container, gravity);
        foreach (var p in particles)
        {
            if (p.Phase >= phases.Count) continue;
            float h = Vector3.Dot(p.Position, up) - floor;
            if (!float.IsFinite(h)) continue;
            sum[p.Phase] += h;
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

    /// <summary>The up direction (against gravity; +y without gravity), the height of the container's lowest
    /// corner along it, and the container's extent along it.</summary>
    public static (Vector3 Up, float Floor, float Height) Vertical(ContainerDescription container, Vector3 gravity)
    {
        var up = gravity.LengthSquared() > 1e-12f ? -Vector3.Normalize(gravity) : Vector3.UnitY;
        float lo = float.MaxValue, hi = float.MinValue;
        var half = container.Size * 0.5f;
        var rotation = Quaternion.Normalize(container.Rotation);
        for (int c = 0; c < 8; c++)
        {
            var local = new Vector3((c & 1) != 0 ? half.X : -half.X, (c & 2) != 0 ? half.Y : -half.Y, (c & 4) != 0 ? half.Z : -half.Z);
            float h = Vector3.Dot(container.Position + Vector3.Transform(local, rotation), up);
            lo = Math.Min(lo, h);
            hi = Math.Max(hi, h);
        }
        return (up, lo, hi - lo);
    }
}
