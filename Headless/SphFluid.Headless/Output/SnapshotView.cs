using System;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>Which way an orthographic snapshot looks.</summary>
public enum ViewAxis
{
    /// <summary>From the front (-z towards +z, as Unity's default camera): x right, y up.</summary>
    Side,

    /// <summary>From above (+y looking down): x right, z up the image.</summary>
    Top,
}

/// <summary>
/// An orthographic view of the container: a fixed world rectangle mapped onto the image, with a depth
/// along the viewing direction for painter's order. The rectangle holds the container in any rotation it
/// can take when it spins, so frames of one run line up.
/// </summary>
public sealed class SnapshotView
{
    public ViewAxis Axis { get; }
    public int Width { get; }
    public int Height { get; }
    readonly Vector2 _min;
    readonly float _pixelsPerMetre;

    public SnapshotView(ViewAxis axis, ContainerDescription container, bool containerTurns, int width)
    {
        Axis = axis;
        Vector2 lo = new(float.MaxValue), hi = new(float.MinValue);
        if (containerTurns)
        {
            float r = container.Size.Length() * 0.5f;
            var c = Project(container.Position);
            lo = c - new Vector2(r);
            hi = c + new Vector2(r);
        }
        else
        {
            foreach (var corner in Corners(container))
            {
                var p = Project(corner);
                lo = Vector2.Min(lo, p);
                hi = Vector2.Max(hi, p);
            }
        }
        var extent = Vector2.Max(hi - lo, new Vector2(1e-3f));
        var margin = extent * 0.06f;
        _min = lo - margin;
        extent += 2 * margin;
        Width = width;
        _pixelsPerMetre = width / extent.X;
        Height = Math.Clamp((int)MathF.Ceiling(extent.Y * _pixelsPerMetre), 16, 4 * width);
    }

    public float PixelsPerMetre => _pixelsPerMetre;

    /// <summary>World point to image coordinates (pixels, y down).</summary>
    public Vector2 ToImage(Vector3 world)
    {
        var p = Project(world);
        return new Vector2((p.X - _min.X) * _pixelsPerMetre, Height - (p.Y - _min.Y) * _pixelsPerMetre);
    }

    /// <summary>Distance from the viewer along the viewing direction: larger is farther (drawn first).</summary>
    public float Depth(Vector3 world) => Axis == ViewAxis.Side ? world.Z : -world.Y;

    Vector2 Project(Vector3 p) => Axis == ViewAxis.Side ? new Vector2(p.X, p.Y) : new Vector2(p.X, p.Z);

    /// <summary>The eight corners of the container box in world space.</summary>
    public static Vector3[] Corners(ContainerDescription container)
    {
        var half = container.Size * 0.5f;
        var rotation = Quaternion.Normalize(container.Rotation);
        var corners = new Vector3[8];
        for (int i = 0; i < 8; i++)
        {
            var local = new Vector3((i & 1) != 0 ? half.X : -half.X, (i & 2) != 0 ? half.Y : -half.Y, (i & 4) != 0 ? half.Z : -half.Z);
            corners[i] = container.Position + Vector3.Transform(local, rotation);
        }
        return corners;
    }
}
