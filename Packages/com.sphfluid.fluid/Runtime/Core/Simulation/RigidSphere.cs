using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>A solid sphere that pushes fluid out of itself with its velocity: what a SphereObstacle component
    /// describes to the engine-free core.</summary>
    public sealed class RigidSphere
    {
        public string Name { get; set; } = "Sphere";

        /// <summary>World-space centre, m.</summary>
        public Vector3 Center { get; set; }

        /// <summary>Radius, m (> 0).</summary>
        public float Radius { get; set; } = 0.05f;

        /// <summary>World-space velocity, m/s.</summary>
        public Vector3 Velocity { get; set; }

        public RigidSphere() { }

        public RigidSphere(Vector3 center, float radius, Vector3 velocity)
        {
            Center = center;
            Radius = radius;
            Velocity = velocity;
        }

        public RigidSphere Clone() => (RigidSphere)MemberwiseClone();

        public override string ToString() => $"Sphere '{Name}' at {Center} r {Radius}";
    }
}
