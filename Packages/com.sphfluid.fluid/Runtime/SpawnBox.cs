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
    public sealed class SpawnBox : MonoBehaviour
    {
        /// <summary>The core's defaults are the inspector's defaults (one source of truth).</summary>
        static readonly SpawnBoxDescription CoreDefaults = new SpawnBoxDescription();

        [Header("Phase")]
        [SerializeField, Tooltip("Phase name; boxes with the same name are one liquid and must agree on every value below.")]
        string phaseName = CoreDefaults.Phase.Name;

        [SerializeField, Min(1f), Tooltip("Rest density rho0, kg/m^3, in [1, 100000] (water 1000, oil 900).")]
        float restDensity = CoreDefaults.Phase.RestDensity;

        [SerializeField, Min(0f), Tooltip("Dynamic viscosity mu, Pa s, in [0, 1000] (water 0.001; the simulation needs more, e.g. 0.5).")]
        float viscosity = CoreDefaults.Phase.Viscosity;

        [SerializeField, Min(0f), Tooltip("Mass of one particle, kg; 0 = derived so that the spawn lattice sits exactly at rest density.")]
        float particleMass = CoreDefaults.Phase.ParticleMass;

        [SerializeField, Range(0f, 10f), Tooltip("Surface tension coefficient gamma, N/m, in [0, 10]; 0 = off (water 0.072).")]
        float surfaceTension = CoreDefaults.Phase.SurfaceTension;

        [Header("Look")]
        [SerializeField, Tooltip("Tint and opacity (sRGB as shown here; the phase table stores it linear).")]
        Color color = new Color(0.2f, 0.45f, 0.9f, 0.8f);

        [SerializeField, Range(0f, 1f), Tooltip("Schlick reflectance at normal incidence, ((n - 1) / (n + 1))^2: water 0.02, oil 0.035.")]
        float fresnelF0 = CoreDefaults.Phase.FresnelF0;

        [SerializeField, Min(0f), Tooltip("Beer-Lambert absorption coefficient of the tint, 1/m, in [0, 10000].")]
        float absorption = CoreDefaults.Phase.Absorption;

        [Header("Spawn")]
        [SerializeField, Tooltip("Velocity every particle starts with, m/s, world space.")]
        Vector3 initialVelocity = Vector3.zero;

        [SerializeField, Range(0f, 0.5f), Tooltip("Random offset of each lattice point, in particle spacings, [0, 0.5].")]
        float jitter = CoreDefaults.Jitter;

        [SerializeField, Tooltip("Seed of the jitter: the same seed spawns the same particles.")]
        int seed = CoreDefaults.Seed;

        public string PhaseName => phaseName;

        public Color Color => color;

        public PhaseDescription DescribePhase()
        {
            return new PhaseDescription(phaseName, restDensity, viscosity)
            {
                ParticleMass = particleMass,
                SurfaceTension = surfaceTension,
                Color = color.linear.ToNumerics(),
                FresnelF0 = fresnelF0,
                Absorption = absorption,
            };
        }

        public SpawnBoxDescription Describe()
        {
            Transform t = transform;
            return new SpawnBoxDescription(name, DescribePhase(), t.position.ToNumerics(), FluidContainer.Abs(t.lossyScale).ToNumerics())
            {
                Rotation = t.rotation.ToNumerics(),
                InitialVelocity = initialVelocity.ToNumerics(),
                Jitter = jitter,
                Seed = seed,
            };
        }

        /// <summary>The core's refusals of this box and its phase (size and placement are checked at start).</summary>
        public IReadOnlyList<ValidationError> ValidationErrors() => ComponentValidation.SpawnBoxErrors(Describe());

        /// <summary>Particles this box spawns with the given settings (the lattice of SpawnLayout).</summary>
        public long ParticleCount(FluidSettings settings) => SpawnLayout.Count(settings, Describe());

        void OnValidate() => ComponentValidation.Log(ValidationErrors(), this);

        void OnDrawGizmos()
        {
            Gizmos.matrix = Matrix4x4.TRS(transform.position, transform.rotation, FluidContainer.Abs(transform.lossyScale));
            Gizmos.color = new Color(color.r, color.g, color.b, 1f);
            Gizmos.DrawWireCube(Vector3.zero, Vector3.one);
            Gizmos.matrix = Matrix4x4.identity;
#if UNITY_EDITOR
            Fluid simulator = FindFirstObjectByType<Fluid>();
            FluidSettings settings = simulator != null ? simulator.DescribeSettings() : new FluidSettings();
            UnityEditor.Handles.color = Gizmos.color;
            UnityEditor.Handles.Label(transform.position, $"{phaseName}: {ParticleCount(settings)} particles");
#endif
        }
    }
}
