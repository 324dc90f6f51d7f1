using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>Small scenes for the GPU solver tests: coarse spacing, few particles, soft but stable settings.</summary>
    public static class SolverScenes
    {
        public static PhaseDescription Water(float viscosity = 0.05f, float tension = 0f) => new PhaseDescription
        {
            Name = "Water", RestDensity = 1000f, Viscosity = viscosity, SurfaceTension = tension,
            Color = new Vector4(0.1f, 0.3f, 0.9f, 0.8f), FresnelF0 = 0.02f, Absorption = 2f,
        };

        public static PhaseDescription Oil(float viscosity = 0.05f, float tension = 0f) => new PhaseDescription
        {
            Name = "Oil", RestDensity = 900f, Viscosity = viscosity, SurfaceTension = tension,
            Color = new Vector4(0.9f, 0.7f, 0.1f, 0.8f), FresnelF0 = 0.035f, Absorption = 4f,
        };

        /// <summary>Settings for a coarse tank: s = 4 cm, h = 8 cm, c about 10 m/s.</summary>
        public static FluidSettings Coarse(float spacing = 0.04f) => new FluidSettings
        {
            ParticleSpacing = spacing,
            SmoothingRadius = 2f * spacing,
            Stiffness = 15000f,
            Gamma = 7f,
            XsphEpsilon = 0.02f,
            MaxSubsteps = 64,
            MaxTimeStep = 0.005f,
        };

        public static FluidBlock Box(string name, PhaseDescription phase, Vector3 center, Vector3 size, int seed = 1, float jitter = 0.05f) =>
            new FluidBlock { Name = name, Phase = phase, Center = center, Size = size, Seed = seed, Jitter = jitter };

        public static FluidSceneDescription Scene(FluidSettings settings, Vector3 containerSize, params FluidBlock[] boxes) =>
            new FluidSceneDescription
            {
                Settings = settings,
                Container = new ContainerDescription { Size = containerSize },
                SpawnBoxes = new List<FluidBlock>(boxes),
            };

        /// <summary>A deterministic pseudo-random generator for test cases (same on every runtime).</summary>
        public sealed class Rng
        {
            ulong _state;
            public Rng(ulong seed) { _state = seed * 0x9E3779B97F4A7C15UL + 1UL; }

            public double Next()
            {
                unchecked
                {
                    ulong z = _state += 0x9E3779B97F4A7C15UL;
                    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
                    z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
                    z ^= z >> 31;
                    return (z >> 11) * (1.0 / (1UL << 53));
                }
            }

            public float Range(float min, float max) => (float)(min + (max - min) * Next());

            public Vector3 InBox(Vector3 half) => new Vector3(Range(-half.X, half.X), Range(-half.Y, half.Y), Range(-half.Z, half.Z));
        }
    }
}
