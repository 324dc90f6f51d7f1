using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// A sphere sunk a third of its radius into a pool's floor and held still, as a boulder on a river bed: no work is done
    /// on the water, so over its first second its mechanical energy may not rise above the spawn's, nothing may move faster
    /// than a fall through one spacing, sqrt(2 g s), and the clamp catches nothing. Under DFSPH a wall particle's
    /// constraint counts the container's lattice and its own sphere at rest, never a sphere's weighed-up shells
    /// (SphBoundary.hlsl's CountsInWallSum): with every wall summed, the floor's particles beside the sphere asked for a
    /// density no motion of the water could give. (DFSPH only: WCSPH's spawn stores elastic energy in its compression,
    /// which the mechanical energy does not count.)
    /// </summary>
    public sealed class SunkSphereTests
    {
        const float Spacing = 0.015f, Radius = 0.045f, Sunk = 0.015f, Depth = 0.12f;
        static readonly Vector3 Tank = new Vector3(0.3f, 0.2f, 0.12f);
        double _energyRise = double.MinValue, _fastest, _fallSpeed;
        int _spawned, _counted, _lostOrBroken, _clampHits;

        [OneTimeSetUp]
        public void HoldTheSphereOneSecond()
        {
            var settings = new FluidSettings { ParticleSpacing = Spacing, SmoothingRadius = 2f * Spacing, MaxSubsteps = 200, PressureSolver = PressureSolver.Dfsph };
            float floor = -0.5f * Tank.Y;
            var scene = SolverScenes.Scene(settings, Tank,
                SolverScenes.Box("Water", SolverScenes.Water(viscosity: 0.001f), new Vector3(0f, floor + 0.5f * Depth, 0f), new Vector3(Tank.X, Depth, Tank.Z)));
            scene.Obstacles.Add(new RigidSphere(new Vector3(0f, floor + Radius - Sunk, 0f), Radius, Vector3.Zero));
            _fallSpeed = Math.Sqrt(2.0 * 9.81 * Spacing);
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            _spawned = sim.ParticleCount;
            var particles = new Particle[_spawned];
            sim.Particles.GetData(particles);
            var gravity = (Vector3)settings.Gravity;
            double spawnEnergy = FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity);
            var report = sim.ReadDiagnostics();
            for (int frame = 1; frame <= 60; frame++)
            {
                sim.Step(1f / 60f);
                report = sim.ReadDiagnostics();
                sim.Particles.GetData(particles);
                _energyRise = Math.Max(_energyRise, FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity) - spawnEnergy);
                _fastest = Math.Max(_fastest, report.MaxSpeed);
            }
            _counted = report.ParticleCount;
            _lostOrBroken = report.OutsideCount + report.NanCount;
            _clampHits = report.ClampHits;
            TestContext.Progress.WriteLine($"DFSPH: sphere r = {Radius} m sunk {Sunk} m into the floor, N = {_spawned}, 1 s: largest energy rise " +
                $"{_energyRise:G3} J over {spawnEnergy:F4} J at spawn, fastest {_fastest:F3} m/s (a fall through a spacing {_fallSpeed:F3}); {report}");
        }

        [Test]
        public void NoWorkIsDoneOnTheWater() => Assert.That(_energyRise, Is.LessThanOrEqualTo(0.0));

        [Test]
        public void NothingMovesFasterThanAFallThroughOneSpacing() => Assert.That(_fastest, Is.LessThan(_fallSpeed));

        [Test]
        public void NothingIsLostOrClamped()
        {
            Assert.That(_counted, Is.EqualTo(_spawned));
            Assert.That(_lostOrBroken, Is.EqualTo(0));
            Assert.That(_clampHits, Is.EqualTo(0));
        }
    }
}
