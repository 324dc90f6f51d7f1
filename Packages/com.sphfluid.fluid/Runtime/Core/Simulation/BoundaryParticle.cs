using System.Numerics;
using System.Runtime.InteropServices;

namespace SphFluid.Simulation
{
    /// <summary>
    /// One boundary particle as the GPU stores it (<c>BoundaryParticle</c> in Shaders/Include/BoundaryParticle.hlsl):
    /// a sample of a container wall or an obstacle that takes part in density and pressure. The same 32-byte
    /// layout as <see cref="Particle"/> (position first), so the particle sort orders it unchanged.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct BoundaryParticle
    {
        public const int Stride = 32;

        /// <summary><see cref="Owner"/> of the container's walls.</summary>
        public const uint ContainerOwner = 0xFFFFFFFFu;

        /// <summary>Position, m: in the owner's frame at rest (container-local, or relative to a sphere's centre);
        /// world space once placed.</summary>
        public Vector3 Position;

        /// <summary>omega = V_b / s^3: the number of fluid particles on the rest lattice it stands for (BoundarySampling).</summary>
        public float Weight;

        /// <summary>World velocity once placed, m/s (the wall's velocity there).</summary>
        public Vector3 Velocity;

        /// <summary><see cref="ContainerOwner"/>, or the index of the sphere obstacle it belongs to.</summary>
        public uint Owner;

        public BoundaryParticle(Vector3 position, float weight, uint owner)
        {
            Position = position;
            Weight = weight;
            Velocity = Vector3.Zero;
            Owner = owner;
        }
    }
}
