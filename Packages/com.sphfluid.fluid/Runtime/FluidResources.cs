using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// The assets every <see cref="Fluid"/> runs and draws with: the four compute shaders, the particle material and
    /// the URP particle shader. One asset in the package's Resources folder, so a Fluid component has no slots to wire
    /// and a project that adds the package by git URL gets them wired (player builds include Resources folders).
    /// </summary>
    public sealed class FluidResources : ScriptableObject
    {
        /// <summary>Name of the asset under Runtime/Resources, as Resources.Load finds it.</summary>
        public const string ResourceName = "SphFluidResources";

        [SerializeField, Tooltip("FluidSolver.compute: density, pressure, forces, integration, boundaries.")]
        ComputeShader solverShader = null;

        [SerializeField, Tooltip("FluidDiagnostics.compute: motion and health reductions.")]
        ComputeShader diagnosticsShader = null;

        [SerializeField, Tooltip("ParticleSort.compute: counting sort of particles by grid cell.")]
        ComputeShader sortShader = null;

        [SerializeField, Tooltip("PrefixSum.compute: the scan the sort is built on.")]
        ComputeShader prefixSumShader = null;

        [SerializeField, Tooltip("FluidParticles.mat on FluidParticles.shader (Built-in pipeline); its values also drive the URP shader.")]
        Material particleMaterial = null;

        [SerializeField, Tooltip("FluidParticlesUniversal.shader: drawn with the material's values when URP is the active pipeline.")]
        Shader universalParticleShader = null;

        public Material ParticleMaterial => particleMaterial;

        public Shader UniversalParticleShader => universalParticleShader;

        /// <summary>The pipeline's compute shaders, in the order the device loads them.</summary>
        public ComputeShader[] ComputeShaders() => new[] { solverShader, diagnosticsShader, sortShader, prefixSumShader };

        /// <summary>The first empty field, or null: the asset was edited or not imported.</summary>
        public string MissingField()
        {
            if (solverShader == null) return nameof(solverShader);
            if (diagnosticsShader == null) return nameof(diagnosticsShader);
            if (sortShader == null) return nameof(sortShader);
            if (prefixSumShader == null) return nameof(prefixSumShader);
            if (particleMaterial == null) return nameof(particleMaterial);
            if (universalParticleShader == null) return nameof(universalParticleShader);
            return null;
        }

        /// <summary>The package's resources asset, or null when it is missing from the project.</summary>
        public static FluidResources Load() => Resources.Load<FluidResources>(ResourceName);
    }
}
