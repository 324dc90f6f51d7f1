using System;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The room an incompressible fluid needs in its closed container. The container has walls on all six faces, so a
    /// fluid that fills it keeps its mean density whatever its pressure: DFSPH's constant-density solve can take a
    /// compression away only into free volume. OilAndWater cut down to the liquids' top (a flush lid) reads 0.09 %
    /// compressed on average and runs out of iterations in every sub-step from 0.8 s while its pressure climbs; a lid a
    /// tenth of a spacing higher runs (Headless/docs/known-limits.md, "Under DFSPH a fluid that fills its closed container
    /// exactly stalls"). The rule asks for free volume of at least the density tolerance's share of the fluid's, the
    /// room to relieve a compression that large; a scene with less may still run, so this is a warning, not a refusal.
    /// WCSPH compresses instead, and needs none.
    /// </summary>
    public static class FreeVolume
    {
        /// <summary>Null unless <paramref name="scene"/> (valid) runs DFSPH with less free volume than it needs; then why,
        /// with the volumes and how much more room the container needs. A sphere obstacle counts whole, as if inside.</summary>
        public static string Warning(FluidSceneDescription scene)
        {
            var settings = scene.Settings;
            if (settings.PressureSolver != PressureSolver.Dfsph) return null;
            var size = scene.Container.Size;
            double container = (double)size.X * size.Y * size.Z;
            double fluid = 0.0, obstacles = 0.0;
            foreach (var box in scene.SpawnBoxes)
                fluid += SpawnLayout.SpawnedCount(scene, box) * SpawnLayout.CellVolume(settings, box);
            if (scene.Obstacles != null)
                foreach (var sphere in scene.Obstacles)
                    obstacles += 4.0 / 3.0 * Math.PI * Math.Pow(sphere.Radius, 3);
            double free = container - fluid - obstacles;
            double needed = settings.DensityTolerance / 100.0 * fluid;
            if (free >= needed) return null;
            return $"under DFSPH the fluid ({ValidationRules.Format(fluid)} m^3){(obstacles > 0 ? $" and the sphere obstacles ({ValidationRules.Format(obstacles)} m^3) leave" : " leaves")} " +
                $"{ValidationRules.Format(Math.Max(0.0, free))} m^3 of the closed {ValidationRules.Format(container)} m^3 container free, less than the " +
                $"{ValidationRules.Format(needed)} m^3 (DensityTolerance {ValidationRules.Format(settings.DensityTolerance)} % of the fluid's volume) its " +
                "constant-density solve needs to take a compression away: its solves may run out of iterations while the pressure climbs. " +
                $"Give the container {ValidationRules.Format(needed - free)} m^3 more room (its height {ValidationRules.Format((needed - free) / ((double)size.X * size.Z))} m more), spawn less fluid, or run WCSPH";
        }
    }
}
