using System.Collections.Generic;
using SphFluid.Simulation;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// A solid sphere the fluid flows around. Its centre is this Transform's position; its velocity comes
    /// from how the Transform moves between frames (drag it, animate it, or use a <see cref="SphereDriver"/>).
    /// </summary>
    [AddComponentMenu("SPH Fluid/Sphere Obstacle")]
    [DisallowMultipleComponent]
    public sealed class SphereObstacle : MonoBehaviour
    {
        [SerializeField, Min(0.0001f), Tooltip("Radius in local units, m; scaled by the largest lossy-scale component like a SphereCollider (0.5 fits Unity's sphere mesh).")]
        float radius = 0.5f;

        /// <summary>Radius in metres, world space.</summary>
        public float WorldRadius => radius * LargestScale;

        float LargestScale
        {
            get
            {
                Vector3 s = FluidContainer.Abs(transform.lossyScale);
                return Mathf.Max(s.x, Mathf.Max(s.y, s.z));
            }
        }

        /// <summary>How the world radius that a refusal quotes comes from the field and the scales above it.</summary>
        internal string WorldRadiusNote()
        {
            var parents = new List<string>();
            for (Transform t = transform.parent; t != null; t = t.parent) parents.Add(t.name);
            return RigidSphere.WorldRadiusNote(radius, LargestScale, parents);
        }

        public RigidSphere Describe(Vector3 velocity) =>
            DescribeInto(new RigidSphere { Name = name }, velocity);

        /// <summary>Writes centre, radius and <paramref name="velocity"/> into <paramref name="description"/> but not
        /// its Name: reading <c>name</c> makes a new string each time, and the simulator refills one description
        /// per sphere every frame.</summary>
        public RigidSphere DescribeInto(RigidSphere description, Vector3 velocity)
        {
            description.Center = transform.position.ToNumerics();
            description.Radius = WorldRadius;
            description.Velocity = velocity.ToNumerics();
            return description;
        }

        public IReadOnlyList<ValidationError> ValidationErrors() => ComponentValidation.ObstacleErrors(Describe(Vector3.zero));

        void OnValidate() => ComponentValidation.Log(ValidationErrors(), this, WorldRadiusNote());

        void OnDrawGizmos()
        {
            Gizmos.color = new Color(1f, 0.6f, 0.2f, 1f);
            Gizmos.DrawWireSphere(transform.position, WorldRadius);
        }
    }
}
