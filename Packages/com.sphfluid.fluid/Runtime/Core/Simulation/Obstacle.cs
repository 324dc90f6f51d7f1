using System.Numerics;
using System.Runtime.InteropServices;

namespace SphFluid.Simulation
{
    /// <summary>One sphere obstacle as the GPU reads it (<c>Obstacle</c> in Shaders/Include/SphBoundary.hlsl):
    /// two 16-byte groups.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Obstacle
    {
        public const int Stride = 32;

        public Vector3 Center;
        public float Radius;
        public Vector3 Velocity;
        float _padding;

        public Obstacle(RigidSphere obstacle)
        {
            Center = obstacle.Center;
            Radius = obstacle.Radius;
            Velocity = obstacle.Velocity;
            _padding = 0f;
        }
    }
}
