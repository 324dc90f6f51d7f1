using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Scenes;

/// <summary>
/// A <c>ContainerSpinner</c> as a function of time: after <see cref="StartDelay"/> the spinner's Transform
/// turns about a world axis through its own position at a steady speed, carrying the container with it.
/// </summary>
public sealed record ContainerSpin(Vector3 Axis, float DegreesPerSecond, float StartDelay, Vector3 Pivot)
{
    public float RadiansPerSecond => DegreesPerSecond * MathF.PI / 180f;

    /// <summary>The container at simulated time <paramref name="t"/>, with the wall velocities of the spin.</summary>
    public ContainerDescription At(ContainerDescription rest, double t)
    {
        var result = rest.Clone();
        if (Axis.LengthSquared() < 1e-12f) return result;
        var axis = Vector3.Normalize(Axis);
        double turning = Math.Max(0.0, t - StartDelay);
        var spin = Quaternion.CreateFromAxisAngle(axis, (float)(turning * RadiansPerSecond));
        result.Position = Pivot + Vector3.Transform(rest.Position - Pivot, spin);
        result.Rotation = Quaternion.Normalize(spin * rest.Rotation);
        if (t >= StartDelay)
        {
            result.AngularVelocity = axis * RadiansPerSecond;
            result.Velocity = Vector3.Cross(result.AngularVelocity, result.Position - Pivot);
        }
        return result;
    }
}

/// <summary>
/// A <c>SphereDriver</c> as a function of time: start + travel (1 - cos(2 pi t' / period)) / 2 with
/// t' = t - startDelay, so the sphere starts and turns at rest; its velocity is the derivative.
/// </summary>
public sealed record SphereDrive(int ObstacleIndex, Vector3 Travel, float Period, float StartDelay)
{
    public SphereObstacleDescription At(SphereObstacleDescription rest, double t)
    {
        var result = rest.Clone();
        double phaseTime = t - StartDelay;
        if (phaseTime < 0 || Period < 0.1f) return result;
        double w = 2.0 * Math.PI / Period;
        result.Center = rest.Center + Travel * (float)(0.5 - 0.5 * Math.Cos(w * phaseTime));
        result.Velocity = Travel * (float)(0.5 * w * Math.Sin(w * phaseTime));
        return result;
    }
}

/// <summary>Everything in the scene that moves on its own while the fluid runs.</summary>
public sealed class SceneMotion
{
    public ContainerSpin ContainerSpin { get; init; }
    public IReadOnlyList<SphereDrive> SphereDrives { get; init; } = Array.Empty<SphereDrive>();

    public bool MovesContainer => ContainerSpin != null;
    public bool MovesObstacles => SphereDrives.Count > 0;

    public ContainerDescription ContainerAt(ContainerDescription rest, double t) => ContainerSpin?.At(rest, t) ?? rest;

    public List<SphereObstacleDescription> ObstaclesAt(IReadOnlyList<SphereObstacleDescription> rest, double t)
    {
        var list = new List<SphereObstacleDescription>(rest.Count);
        for (int i = 0; i < rest.Count; i++) list.Add(rest[i].Clone());
        foreach (var drive in SphereDrives) list[drive.ObstacleIndex] = drive.At(rest[drive.ObstacleIndex], t);
        return list;
    }
}
