using System.Collections.Generic;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>Small engine-free scenes for the spawn, validation, planner and time-step tests.</summary>
    internal static class SimulationTestScenes
    {
        internal static PhaseDescription Water() => new PhaseDescription("Water", 1000f, 0.001f);
        internal static PhaseDescription Oil() => new PhaseDescription("Oil", 900f, 0.05f);

        /// <summary>A 0.5 m tank, water in the lower half, oil on top (s = 0.02: 25 x 6 x 25 and 25 x 6 x 25 particles).</summary>
        internal static FluidSceneDescription OilOnWater()
        {
            return new FluidSceneDescription
            {
                Settings = new FluidSettings(),
                Container = new ContainerDescription { Size = new Vector3(0.5f, 0.5f, 0.5f) },
                SpawnBoxes = new List<FluidBlock>
                {
                    new FluidBlock("Water", Water(), new Vector3(0f, -0.19f, 0f), new Vector3(0.5f, 0.12f, 0.5f)) { Seed = 1 },
                    new FluidBlock("Oil", Oil(), new Vector3(0f, -0.07f, 0f), new Vector3(0.5f, 0.12f, 0.5f)) { Seed = 2 },
                },
            };
        }

        internal static FluidSceneDescription SingleWater()
        {
            var scene = OilOnWater();
            scene.SpawnBoxes.RemoveAt(1);
            return scene;
        }
    }
}
