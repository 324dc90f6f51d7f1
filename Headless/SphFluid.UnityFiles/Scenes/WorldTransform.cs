using System.Numerics;

namespace SphFluid.UnityFiles.Scenes;

/// <summary>
/// A Transform's pose in world space, composed up its parent chain the way Unity does:
/// position = parent.position + parent.rotation * (parent.scale ⊙ local.position), rotation = parent.rotation * local.rotation,
/// scale = parent.scale ⊙ local.scale (Unity's lossyScale; exact unless a rotated parent is non-uniformly scaled).
/// </summary>
public readonly record struct WorldTransform(Vector3 Position, Quaternion Rotation, Vector3 Scale)
{
    public static readonly WorldTransform Identity = new(Vector3.Zero, Quaternion.Identity, Vector3.One);

    /// <summary>A local pose placed under this one.</summary>
    public WorldTransform Compose(Vector3 localPosition, Quaternion localRotation, Vector3 localScale) => new(
        Position + Vector3.Transform(Scale * localPosition, Rotation),
        Quaternion.Normalize(Rotation * localRotation),
        Scale * localScale);

    /// <summary>A point given in this transform's local space, in world space (Unity's Transform.TransformPoint).</summary>
    public Vector3 TransformPoint(Vector3 local) => Position + Vector3.Transform(Scale * local, Rotation);

    /// <summary>A direction rotated into world space, ignoring scale (Unity's Transform.TransformDirection).</summary>
    public Vector3 TransformDirection(Vector3 local) => Vector3.Transform(local, Rotation);

    /// <summary>
    /// Local-to-world in System.Numerics' row-vector convention (<c>Vector3.Transform(p, m)</c>, translation in M41..M43).
    /// For HLSL <c>mul(m, float4(p, 1))</c> use <see cref="Matrix4x4.Transpose"/>.
    /// </summary>
    public Matrix4x4 LocalToWorld =>
        Matrix4x4.CreateScale(Scale) * Matrix4x4.CreateFromQuaternion(Rotation) * Matrix4x4.CreateTranslation(Position);
}
