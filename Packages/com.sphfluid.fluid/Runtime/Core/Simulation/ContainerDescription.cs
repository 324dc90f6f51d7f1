using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>The boundary box the fluid lives in, possibly moving and turning.</summary>
    public sealed class ContainerDescription
    {
        /// <summary>World-space centre, m.</summary>
        public Vector3 Position { get; set; }

        public Quaternion Rotation { get; set; } = Quaternion.Identity;

        /// <summary>Inner edge lengths, m.</summary>
        public Vector3 Size { get; set; } = new Vector3(0.5f, 0.5f, 0.5f);

        /// <summary>Linear velocity of the centre, m/s (the walls push the fluid with it).</summary>
        public Vector3 Velocity { get; set; }

        /// <summary>Angular velocity about the centre, rad/s, world axes.</summary>
        public Vector3 AngularVelocity { get; set; }

        /// <summary>The fastest a point of its walls can move, m/s: |V| + |w| times half the diagonal (a bound: the
        /// corners turn fastest).</summary>
        public float FastestWallSpeed => Velocity.Length() + AngularVelocity.Length() * 0.5f * Size.Length();

        /// <summary>How the walls (and obstacles) hold the fluid tangentially: no slip by default.</summary>
        public WallFriction Friction { get; set; } = WallFriction.NoSlip;

        public ContainerDescription() { }

        public ContainerDescription(Vector3 position, Quaternion rotation, Vector3 size)
        {
            Position = position;
            Rotation = rotation;
            Size = size;
        }

        public ContainerDescription Clone() => (ContainerDescription)MemberwiseClone();

        /// <summary>Same placement (position, rotation, size): no transform upload is needed.</summary>
        public bool SamePlacement(ContainerDescription other) =>
            other != null && Position == other.Position && Rotation == other.Rotation && Size == other.Size;

        /// <summary>World point to container-local coordinates, q = R^T (x - c).</summary>
        public Vector3 ToLocal(Vector3 world) =>
            Vector3.Transform(world - Position, Quaternion.Conjugate(Quaternion.Normalize(Rotation)));

        public override string ToString() => $"Container at {Position} size {Size}";
    }
}
