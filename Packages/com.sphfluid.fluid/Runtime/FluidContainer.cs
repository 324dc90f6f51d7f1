using System.Collections.Generic;
using SphFluid.Simulation;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// The box the fluid lives in: this Transform's position, rotation and lossy scale (a unit cube
    /// scaled to the inner size, in metres). Move or rotate it at run time and the walls push the fluid.
    /// </summary>
    [AddComponentMenu("SPH Fluid/Fluid Container")]
    [DisallowMultipleComponent]
    public sealed class FluidContainer : MonoBehaviour
    {
        [SerializeField, Tooltip("How the walls and obstacles hold the fluid tangentially: NoSlip (a real wall) or Slip (free slip).")]
        WallFriction friction = WallFriction.NoSlip;

        /// <summary>The container at rest where the Transform is now (velocities are the simulator's business).</summary>
        public ContainerDescription Describe() => DescribeInto(new ContainerDescription());

        /// <summary>Writes the placement (position, rotation, size) into <paramref name="description"/>, leaving its
        /// velocities alone: the simulator refills one description every frame instead of making one.</summary>
        public ContainerDescription DescribeInto(ContainerDescription description)
        {
            Transform t = transform;
            description.Position = t.position.ToNumerics();
            description.Rotation = t.rotation.ToNumerics();
            description.Size = Abs(t.lossyScale).ToNumerics();
            description.Friction = friction;
            return description;
        }

        /// <summary>The core's refusals of this container alone (its size against the default particle spacing).</summary>
        public IReadOnlyList<ValidationError> ValidationErrors() =>
            ComponentValidation.ContainerErrors(Describe());

        internal static Vector3 Abs(Vector3 v) => new Vector3(Mathf.Abs(v.x), Mathf.Abs(v.y), Mathf.Abs(v.z));

        void OnValidate() => ComponentValidation.Log(ValidationErrors(), this);

        void OnDrawGizmos()
        {
            Gizmos.matrix = Matrix4x4.TRS(transform.position, transform.rotation, Abs(transform.lossyScale));
            Gizmos.color = new Color(0.8f, 0.8f, 0.8f, 1f);
            Gizmos.DrawWireCube(Vector3.zero, Vector3.one);
            Gizmos.matrix = Matrix4x4.identity;
        }
    }
}
