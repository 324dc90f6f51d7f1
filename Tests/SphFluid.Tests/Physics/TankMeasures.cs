using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>What a validation engineer measures in a tank, from read-back particles (container axis-aligned, gravity -y).</summary>
    public static class TankMeasures
    {
        /// <summary>Height of a column of fluid resting on the floor, from its centroid: a uniform column of height
        /// H has its particles' mean height at H / 2. Unlike the topmost particle, this is not moved by the single
        /// free-surface layer that summation density packs about a quarter spacing tighter, yet any slump of the
        /// column shows in full.</summary>
        public static double ColumnHeight(Particle[] particles, float floorY) =>
            2.0 * particles.Average(p => (double)(p.Position.Y - floorY));

        /// <summary>Least-squares slope dp/dy over the particles between <paramref name="fromY"/> and <paramref name="toY"/>, Pa/m.</summary>
        public static double PressureGradient(Particle[] particles, Vector4[] densities, double fromY, double toY)
        {
            var points = Enumerable.Range(0, particles.Length)
                .Where(i => particles[i].Position.Y >= fromY && particles[i].Position.Y <= toY)
                .Select(i => ((double)particles[i].Position.Y, (double)densities[i].Y)).ToList();
            double my = points.Average(q => q.Item1), mp = points.Average(q => q.Item2);
            double sxy = points.Sum(q => (q.Item1 - my) * (q.Item2 - mp));
            double sxx = points.Sum(q => (q.Item1 - my) * (q.Item1 - my));
            return sxy / sxx;
        }

        /// <summary>
        /// Each particle's pressure in <see cref="PressureGradient"/>'s layout (Y): WCSPH's from its equation of state
        /// (Densities.y); under DFSPH what both solves applied in the last sub-step, p = q delta^2, the constant-density
        /// solve's in Densities.y (its readout) and the divergence-free solve's summed q in the warm start's y, by id.
        /// </summary>
        public static Vector4[] AppliedPressure(Particle[] particles, Vector4[] densities, Vector2[] warmStart, PressureSolver solver)
        {
            var pressures = new Vector4[particles.Length];
            for (int i = 0; i < particles.Length; i++)
            {
                float delta = densities[i].Z;
                float divergenceFree = solver == PressureSolver.Dfsph ? warmStart[particles[i].Id].Y * delta * delta : 0f;
                pressures[i] = new Vector4(0f, densities[i].Y + divergenceFree, 0f, 0f);
            }
            return pressures;
        }

        /// <summary>A DFSPH tank's pressure gradients now, read back into the given arrays: the pressure both solves applied
        /// in the last sub-step (<see cref="AppliedPressure"/>) and the constant-density solve's alone, each fitted over the
        /// band from 0.75 supports above the floor to 1.25 below the surface, Pa/m.</summary>
        public static (double Applied, double DensitySolve) DivergenceFreePressureGradients(FluidSimulation sim, Particle[] particles,
            Vector4[] densities, Vector2[] warmStart, float floorY, double support)
        {
            sim.Particles.GetData(particles);
            sim.Densities.GetData(densities);
            sim.WarmStart.GetData(warmStart);
            var total = AppliedPressure(particles, densities, warmStart, PressureSolver.Dfsph);
            double surface = floorY + ColumnHeight(particles, floorY);
            double from = floorY + 0.75 * support, to = surface - 1.25 * support;
            return (PressureGradient(particles, total, from, to), PressureGradient(particles, densities, from, to));
        }

        public static double MaxSpeed(Particle[] particles) => particles.Max(p => (double)p.Velocity.Length());

        /// <summary>The smallest distance from a particle centre to a face of the container, m (inside: positive).</summary>
        public static double ClosestToWalls(Particle[] particles, ContainerDescription container) => particles.Min(p =>
        {
            var gap = container.Size / 2 - Vector3.Abs(p.Position - container.Position);
            return (double)Math.Min(gap.X, Math.Min(gap.Y, gap.Z));
        });
    }
}
