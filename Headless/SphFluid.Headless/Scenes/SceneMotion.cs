using System;
using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Scenes;

/// <summary>A <c>SphereDriver</c> of the scene: the core's law and the obstacle it drives.</summary>
public sealed record DrivenSphere(int ObstacleIndex, DriveLaw Drive);

/// <summary>
/// Everything in the scene that moves on its own while the fluid runs, by the core's laws (<see cref="SpinLaw"/>,
/// <see cref="DriveLaw"/>) that the Unity components also apply.
/// </summary>
public sealed class SceneMotion
{
    /// <summary>The container's spin, or null.</summary>
    public SpinLaw? ContainerSpin { get; init; }

    /// <summary>World position of the spinner's Transform, which the spin turns about.</summary>
    public Vector3 SpinPivot { get; init; }

    public IReadOnlyList<DrivenSphere> SphereDrives { get; init; } = Array.Empty<DrivenSphere>();

    [MemberNotNullWhen(true, nameof(ContainerSpin))]
    public bool MovesContainer => ContainerSpin != null;
    public bool MovesObstacles => SphereDrives.Count > 0;

    /// <summary>The container at the end of a frame from <paramref name="from"/> to <paramref name="to"/>, with the
    /// velocities that brought it there (what <see cref="FluidSimulation.UpdateContainer"/> takes).</summary>
    public ContainerDescription ContainerOver(ContainerDescription rest, double from, double to) =>
        ContainerSpin?.Over(rest, SpinPivot, from, to) ?? rest;

    /// <summary>The obstacles at the end of a frame, as <see cref="ContainerOver"/>.</summary>
    public List<RigidSphere> ObstaclesOver(IReadOnlyList<RigidSphere> rest, double from, double to)
    {
        var list = new List<RigidSphere>(rest.Count);
        for (int i = 0; i < rest.Count; i++) list.Add(rest[i].Clone());
        foreach (var driven in SphereDrives) list[driven.ObstacleIndex] = driven.Drive.Over(rest[driven.ObstacleIndex], from, to);
        return list;
    }
}
