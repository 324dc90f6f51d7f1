using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// Draws particles as discs of their phase colour in painter's order (farthest first), shaded darker with
/// depth so the third dimension reads, over the container's wire box and any sphere obstacles.
/// </summary>
public static class SnapshotRenderer
{
    static readonly Rgb Background = new(18, 20, 26);
    static readonly Rgb Wall = new(200, 200, 200);
    static readonly Rgb Obstacle = new(255, 153, 51);

    public static RgbImage Render(SnapshotView view, ReadOnlySpan<Particle> particles, IReadOnlyList<PhaseProperties> phases,
        ContainerDescription container, IReadOnlyList<RigidSphere> obstacles, float particleSpacing)
    {
        var image = new RgbImage(view.Width, view.Height);
        image.Fill(Background);

        var colors = new Rgb[Math.Max(1, phases.Count)];
        for (int k = 0; k < phases.Count; k++)
            colors[k] = Rgb.FromLinear(phases[k].Color.X, phases[k].Color.Y, phases[k].Color.Z);

        var order = new int[particles.Length];
        var depth = new float[particles.Length];
        float near = float.MaxValue, far = float.MinValue;
        for (int i = 0; i < particles.Length; i++)
        {
            order[i] = i;
            depth[i] = view.Depth(particles[i].Position);
            if (float.IsFinite(depth[i]))
            {
                near = Math.Min(near, depth[i]);
                far = Math.Max(far, depth[i]);
            }
        }
        Array.Sort(depth, order);
        float range = far > near ? far - near : 1f;
        float radius = Math.Max(1.2f, 0.6f * particleSpacing * view.PixelsPerMetre);

        if (obstacles != null)
            foreach (var o in obstacles)
            {
                var c = view.ToImage(o.Center);
                image.FillDisc(c.X, c.Y, o.Radius * view.PixelsPerMetre, Obstacle.Scale(0.55f));
            }

        for (int n = particles.Length - 1; n >= 0; n--)
        {
            var p = particles[order[n]];
            if (!float.IsFinite(p.Position.X) || !float.IsFinite(p.Position.Y) || !float.IsFinite(p.Position.Z)) continue;
            var c = view.ToImage(p.Position);
            float shade = 1f - 0.45f * (depth[n] - near) / range;
            var color = p.Phase < colors.Length ? colors[p.Phase] : new Rgb(255, 0, 255);
            image.FillDisc(c.X, c.Y, radius, color.Scale(shade));
        }

        DrawBox(image, view, container);
        if (obstacles != null)
            foreach (var o in obstacles) DrawCircle(image, view, o.Center, o.Radius, Obstacle);
        return image;
    }

    static void DrawBox(RgbImage image, SnapshotView view, ContainerDescription container)
    {
        var corners = SnapshotView.Corners(container);
        for (int a = 0; a < 8; a++)
            for (int bit = 1; bit < 8; bit <<= 1)
            {
                int b = a | bit;
                if (b == a) continue;
                var p = view.ToImage(corners[a]);
                var q = view.ToImage(corners[b]);
                image.DrawLine(p.X, p.Y, q.X, q.Y, Wall);
            }
    }

    static void DrawCircle(RgbImage image, SnapshotView view, Vector3 centre, float radius, Rgb color)
    {
        var c = view.ToImage(centre);
        float r = radius * view.PixelsPerMetre;
        int segments = Math.Clamp((int)(r * 2), 16, 256);
        for (int i = 0; i < segments; i++)
        {
            float a0 = 2 * MathF.PI * i / segments, a1 = 2 * MathF.PI * (i + 1) / segments;
            image.DrawLine(c.X + r * MathF.Cos(a0), c.Y + r * MathF.Sin(a0), c.X + r * MathF.Cos(a1), c.Y + r * MathF.Sin(a1), color);
        }
    }
}
