using System;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// The container as gravity sees it. Two notions of "height" are kept apart on purpose:
/// <list type="bullet">
/// <item>World height: along -gravity, from the container's lowest corner. Mean heights, extents, potential energy
/// and the layering order use it, so a turning box still measures "up" as the fluid feels it.</item>
/// <item>Container-local faces: the floor is the face gravity points at in the container's own frame (the local
/// axis with the largest share of gravity); the four faces around it are the walls; the other is the ceiling.
/// The floor and wall layers, the surge front and the back-wall column use them, because a validation
/// engineer compares those with marks on the tank.</item>
/// </list>
/// Without gravity, "down" is -y (world and local).
/// </summary>
public sealed class GravityFrame
{
    readonly ContainerDescription _container;
    readonly int _floorAxis;
    readonly float _floorSign;
    readonly Vector3 _half;

    public GravityFrame(ContainerDescription container, Vector3 gravity)
    {
        _container = container ?? throw new ArgumentNullException(nameof(container));
        _half = container.Size * 0.5f;
        bool hasGravity = gravity.LengthSquared() > 1e-12f;
        Up = hasGravity ? -Vector3.Normalize(gravity) : Vector3.UnitY;

        float lo = float.MaxValue, hi = float.MinValue;
        var rotation = Quaternion.Normalize(container.Rotation);
        for (int c = 0; c < 8; c++)
        {
            var local = new Vector3((c & 1) != 0 ? _half.X : -_half.X, (c & 2) != 0 ? _half.Y : -_half.Y, (c & 4) != 0 ? _half.Z : -_half.Z);
            float h = Vector3.Dot(container.Position + Vector3.Transform(local, rotation), Up);
            lo = Math.Min(lo, h);
            hi = Math.Max(hi, h);
        }
        LowestCorner = lo;
        Extent = hi - lo;

        var down = hasGravity ? Vector3.Transform(Vector3.Normalize(gravity), Quaternion.Conjugate(rotation)) : -Vector3.UnitY;
        var a = Vector3.Abs(down);
        _floorAxis = a.X > a.Y && a.X > a.Z ? 0 : a.Z > a.Y ? 2 : 1;
        _floorSign = Component(down, _floorAxis) >= 0 ? 1f : -1f;
    }

    /// <summary>World direction against gravity.</summary>
    public Vector3 Up { get; }

    /// <summary>World height (along <see cref="Up"/>) of the container's lowest corner, m.</summary>
    public float LowestCorner { get; }

    /// <summary>The container's extent along <see cref="Up"/>, m.</summary>
    public float Extent { get; }

    /// <summary>Container-local axis (0 x, 1 y, 2 z) normal to the floor.</summary>
    public int FloorAxis => _floorAxis;

    /// <summary>Height along -gravity above the container's lowest corner, m.</summary>
    public float HeightOf(Vector3 world) => Vector3.Dot(world, Up) - LowestCorner;

    /// <summary>Container-local coordinates of a world point.</summary>
    public Vector3 ToLocal(Vector3 world) => _container.ToLocal(world);

    /// <summary>Distance from the floor face, container-local, m.</summary>
    public float AboveFloor(Vector3 local) => Component(_half, _floorAxis) - _floorSign * Component(local, _floorAxis);

    /// <summary>Distance to the nearest of the four walls around the floor, container-local, m.</summary>
    public float FromWalls(Vector3 local)
    {
        float d = float.MaxValue;
        for (int axis = 0; axis < 3; axis++)
            if (axis != _floorAxis) d = Math.Min(d, Component(_half, axis) - Math.Abs(Component(local, axis)));
        return d;
    }

    /// <summary>Container-local x measured from the back wall (the x = -size/2 face), m.</summary>
    public float FromBackWall(Vector3 local) => local.X + _half.X;

    static float Component(Vector3 v, int axis) => axis == 0 ? v.X : axis == 1 ? v.Y : v.Z;
}
