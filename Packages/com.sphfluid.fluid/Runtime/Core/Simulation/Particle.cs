using System.Numerics;
using System.Runtime.InteropServices;

namespace SphFluid.Simulation
{
    /// <summary>
    /// One SPH particle as the GPU stores it (<c>Particle</c> in Shaders/Include/Particle.hlsl).
    /// Two 16-byte groups, so D3D's and Vulkan's structured-buffer layouts agree (no float3 stride trap).
    /// The solver re-sorts particles by grid cell every step; <see cref="Id"/> keeps their identity.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Particle
    {
        public const int Stride = 32;

        /// <summary>World-space position, m.</summary>
        public Vector3 Position;

        /// <summary>Index into the phase table.</summary>
        public uint Phase;

        /// <summary>World-space velocity, m/s.</summary>
        public Vector3 Velocity;

        /// <summary>Stable identity from spawn, unchanged by sorting.</summary>
        public uint Id;

        public Particle(Vector3 position, Vector3 velocity, uint phase, uint id)
        {
            Position = position;
            Phase = phase;
            Velocity = velocity;
            Id = id;
        }
    }
}
