using System;
using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Scenes;

/// <summary>A <c>SphereDriver</c> of the scene: the core's law and the obstacle it drives.</summary>
public sealed record DrivenSphere(int ObstacleIndex, SphereDrive Drive);

/// <summary>
/// Everything in the scene that moves on its own while the fluid runs, by the core's laws (<see cref="ContainerSpin"/>,
/// <see cref="SphereDrive"/>) that the Unity components also apply.
/// </summary>
public sealed class SceneMotion
{
    /// <summary>The container's spin, or null.</summary>
    public ContainerSpin? ContainerSpin { get; init; }

    /// <summary>World position of the spinner's Transform, which the spin turns about.</summary>
    public Vector3 SpinPivot { get; init; }

    public IReadOnlyList<DrivenSphere> SphereDrives { get; init; } = Array.Empty<DrivenSphere>();

    [MemberNotNullWhen(true, nameof(ContainerSpin))]
    public bool MovesContainer => ContainerSpin != null;
    public bool MovesObstacles => SphereDrives.Count > 0;

    public ContainerDescription ContainerAt(ContainerDescription rest, double t) => ContainerSpin?.At(rest, SpinPivot, t) ?? rest;

    public List<RigidSphere> ObstaclesAt(IReadOnlyList<RigidSphere> rest, double t)
    {
        var list = new List<RigidSphere>(rest.Count);
        for (int i = 0; i < rest.Count; i++) list.Add(rest[i].Clone());
        foreach (var driven in SphereDrives) list[driven.ObstacleIndex] = driven.Drive.At(rest[driven.ObstacleIndex], t);
        return list;
    }
}
