using System.Collections.Generic;
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

        /// <summary>How the world radius that a refusal quotes comes from the component's field where the two differ: a
        /// radius of 0.5 under a scale of 3000 is refused as 1500 m, a number the field does not show. Empty at a scale of 1.
        /// <paramref name="scaledBy"/> names the GameObjects above the sphere, whose scales take part in its own.</summary>
        public static string WorldRadiusNote(float fieldRadius, float largestScale, IReadOnlyList<string> scaledBy)
        {
            if (largestScale == 1f) return "";
            var parents = new List<string>();
            foreach (string name in scaledBy) parents.Add($"'{name}'");
            string under = parents.Count == 0 ? "" : $", which the scales of {string.Join(", ", parents)} take part in";
            return $"(in the world: {ValidationRules.Format(fieldRadius)} times {ValidationRules.Format(largestScale)}, " +
                $"the largest component of its scale in the world{under})";
        }

        public RigidSphere Clone() => (RigidSphere)MemberwiseClone();

        public override string ToString() => $"Sphere '{Name}' at {Center} r {Radius}";
    }
}
