using System.Collections.Generic;
using SphFluid.Simulation;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// Fills its box (this Transform: position, rotation, lossy scale = edge lengths in metres) with one
    /// phase on a regular lattice of the simulator's particle spacing, with a small deterministic jitter.
    /// Boxes that name the same phase share it and must agree on every phase value.
    /// </summary>
    [AddComponentMenu("SPH Fluid/Spawn Box")]
    public sealed class SpawnBox : MonoBehaviour
    {
        [SerializeField, Tooltip("The box's liquid and lattice; each value's default, range, unit and meaning are declared once, in the core's PhaseDescription and FluidBlock.")]
        FluidBlock spawn = new FluidBlock();

        /// <summary>The inspector's values, for scripts (the placement comes from the Transform, see <see cref="Describe"/>).</summary>
        public FluidBlock Spawn => spawn;

        public string PhaseName => spawn.Phase != null ? spawn.Phase.Name : "";

        /// <summary>The phase colour as the inspector shows it (sRGB); the core stores it linear.</summary>
        public Color Color => spawn.Phase != null ? spawn.Phase.Color.ToInspectorColor() : Color.white;

        public PhaseDescription DescribePhase() => spawn.Phase?.Clone();

        /// <summary>A copy of the declared values with the placement of this Transform and the GameObject's name.</summary>
        public FluidBlock Describe()
        {
            Transform t = transform;
            FluidBlock box = spawn.Clone();
            box.Name = name;
            box.Center = t.position.ToNumerics();
            box.Rotation = t.rotation.ToNumerics();
            box.Size = FluidContainer.Abs(t.lossyScale).ToNumerics();
            return box;
        }

        /// <summary>The core's refusals of this box and its phase (size and placement are checked at start).</summary>
        public IReadOnlyList<ValidationError> ValidationErrors() => ComponentValidation.SpawnBoxErrors(Describe());

        /// <summary>Lattice points this box fills with the given settings: what it spawns where no sphere obstacle takes
        /// some (<see cref="SpawnLayout.SpawnedCount"/> counts those out).</summary>
        public long ParticleCount(FluidSettings settings) => SpawnLayout.Count(settings, Describe());

        void OnValidate() => ComponentValidation.Log(ValidationErrors(), this);

        void OnDrawGizmos()
        {
            Color shown = Color;
            Gizmos.matrix = Matrix4x4.TRS(transform.position, transform.rotation, FluidContainer.Abs(transform.lossyScale));
            Gizmos.color = new Color(shown.r, shown.g, shown.b, 1f);
            Gizmos.DrawWireCube(Vector3.zero, Vector3.one);
            Gizmos.matrix = Matrix4x4.identity;
#if UNITY_EDITOR
            // What spawns, as the Fluid inspector's total counts it: less the lattice points inside a sphere obstacle.
            Fluid simulator = FindFirstObjectByType<Fluid>();
            FluidSceneDescription around = simulator != null ? simulator.DescribeSurroundings() : new FluidSceneDescription { Settings = new FluidSettings() };
            UnityEditor.Handles.color = Gizmos.color;
            UnityEditor.Handles.Label(transform.position, $"{PhaseName}: {SpawnLayout.SpawnedCount(around, Describe())} particles");
#endif
        }
    }
}
