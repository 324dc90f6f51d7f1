using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// How far the DFSPH resting tank's fitted pressure gradient (<see cref="DivergenceFreeTankTests"/>) strays from rho0 g
    /// with the spawn's jitter seed, at the tank's 0.1 % tolerance and at the 0.01 % its hydrostatic test runs: the
    /// gradient each frame, its means over every 0.1 s, over 0.5 to 1 s and over 1 to 2 s, in % off rho0 g. A measurement
    /// (about 25 s of lavapipe a fixture at 0.01 %), run by name:
    /// <c>bash Headless/test.sh --filter FullyQualifiedName~DivergenceFreeTankScatterProbe</c>.
    /// </summary>
    [Explicit("a measurement, minutes of lavapipe")]
    [TestFixture(0.1f)]
    [TestFixture(0.01f)]
    public sealed class DivergenceFreeTankScatterProbe
    {
        const float Spacing = 0.025f, Floor = -0.2f;
        const double RhoG = RestingTankTests.RestDensity * 9.81;
        readonly float _tolerance;

        public DivergenceFreeTankScatterProbe(float tolerance) => _tolerance = tolerance;

        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        public void TheGradientOverTwoSeconds(int seed)
        {
            var scene = RestingTankTests.Tank(Spacing);
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            scene.Settings.DensityTolerance = _tolerance;
            scene.SpawnBoxes[0].Seed = seed;
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            var warmStart = new Vector2[sim.ParticleCount];
            double support = scene.Settings.SmoothingRadius;
            var tenths = new List<string>();
            double block = 0, firstHalf = 0, nextSecond = 0;
            int inBlock = 0, inFirstHalf = 0, inNextSecond = 0;
            while (sim.SimulatedTime < 2.0 - 1e-6)
            {
                sim.Step(1f / 60f);
                double applied = TankMeasures.DivergenceFreePressureGradients(sim, particles, densities, warmStart, Floor, support).Applied;
                double offBy = 100 * (-applied / RhoG - 1);
                block += offBy;
                if (++inBlock == 6)
                {
                    tenths.Add($"{block / inBlock:F1}");
                    block = 0;
                    inBlock = 0;
                }
                if (sim.SimulatedTime > 0.5 + 1e-6 && sim.SimulatedTime <= 1.0 + 1e-6) { firstHalf += offBy; inFirstHalf++; }
                if (sim.SimulatedTime > 1.0 + 1e-6) { nextSecond += offBy; inNextSecond++; }
            }
            TestContext.Progress.WriteLine($"DFSPH resting tank at {_tolerance} %, seed {seed}: dp/dy off rho0 g by (%) " +
                $"{firstHalf / inFirstHalf:F2} over 0.5 to 1 s, {nextSecond / inNextSecond:F2} over 1 to 2 s; every 0.1 s: {string.Join(" ", tenths)}");
        }
    }
}
