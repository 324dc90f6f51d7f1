using System.Numerics;
using System.Runtime.InteropServices;

namespace SphFluid.Simulation
{
    /// <summary>
    /// One row of the GPU phase table (<c>PhaseProperties</c> in Shaders/Include/Phase.hlsl), indexed by
    /// <see cref="Particle.Phase"/>: what a liquid is, physically and optically. Three 16-byte groups.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PhaseProperties
    {
        public const int Stride = 48;

        /// <summary>Rest density rho0, kg/m^3.</summary>
        public float RestDensity;

        /// <summary>Dynamic viscosity mu, Pa·s.</summary>
        public float Viscosity;

        /// <summary>Mass of one particle of this phase, kg.</summary>
        public float ParticleMass;

        /// <summary>Surface tension sigma, N/m (0 = none).</summary>
        public float SurfaceTension;

        /// <summary>Linear RGB tint and opacity used by the point shader and the headless snapshots.</summary>
        public Vector4 Color;

        /// <summary>Schlick's reflectance at normal incidence, ((n - 1) / (n + 1))^2: 0.02 water, 0.035 oil.</summary>
        public float FresnelF0;

        /// <summary>Beer-Lambert absorption coefficient of the tint, 1/m.</summary>
        public float Absorption;

        /// <summary>This phase's rest number density rho0 / m over the lattice's delta0, in whose units a boundary particle's
        /// weight omega_b is given: the wall stands for its volume filled at the rest number density of the fluid that meets
        /// it (SphBoundary.hlsl's WallWeight). s^3 / c for a derived mass whose particles stand for the cell c.</summary>
        public float WallWeightScale;

        /// <summary>1 / the phase's particle count (0 for none), set by the simulation once it has spawned: the DFSPH
        /// solves hold each phase's average error to the tolerance (FoldSolveErrors), not the average over all particles.</summary>
        public float InverseParticleCount;
    }
}
