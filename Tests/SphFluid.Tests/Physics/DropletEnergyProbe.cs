using System;
using System.Collections.Generic;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The energy the surface force gives a droplet, against what surface tension can: a cube of 1 000 particles (5 mm
    /// spacings, water's viscosity, no gravity) rounding up releases at most sigma (A_cube - A_ball), a fifth of its
    /// surface energy, and a liquid this thin damps its oscillations over minutes, so its kinetic energy should rise to
    /// about that and stay; without tension it should stay at rest. Prints the kinetic energy and the fastest particle
    /// every 0.1 s for 1.5 s, the release, the health check's bounds, and at the end how much of the kinetic energy is
    /// the droplet moving as a whole. A measurement (two minutes of lavapipe for all six), run by name:
    /// <c>bash Headless/test.sh --filter FullyQualifiedName~DropletEnergyProbe</c>.
    /// </summary>
    [Explicit("a measurement, a minute of lavapipe")]
    // Without tension the droplet has nothing to release: what it gains is its spawn's compression.
    [TestFixture(0f, PressureSolver.Wcsph)]
    [TestFixture(0f, PressureSolver.Dfsph)]
    [TestFixture(0.072f, PressureSolver.Wcsph)]
    [TestFixture(0.072f, PressureSolver.Dfsph)]
    [TestFixture(1f, PressureSolver.Wcsph)]
    [TestFixture(1f, PressureSolver.Dfsph)]
    public sealed class DropletEnergyProbe
    {
        const float Spacing = 0.005f;
        const int Side = 10;
        readonly float _sigma;
        readonly PressureSolver _solver;

        public DropletEnergyProbe(float sigma, PressureSolver solver)
        {
            _sigma = sigma;
            _solver = solver;
        }

        [Test]
        public void KineticEnergyAgainstTheRelease()
        {
            var scene = LaplaceDroplets.Scene(KernelFamily.CubicSpline, 2f, Spacing, 1000f, _sigma, Side);
            scene.SpawnBoxes[0].Phase.Viscosity = 0.001f;
            scene.Settings.PressureSolver = _solver;
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var check = new HealthCheck(scene, sim.ParticleCount);
            double side = Side * Spacing, volume = side * side * side;
            double ballArea = Math.Pow(36 * Math.PI * volume * volume, 1.0 / 3.0);
            double release = _sigma * (6 * side * side - ballArea);
            var series = new List<string>();
            double most = 0;
            float fastest = 0f;
            int frame = 0;
            while (sim.SimulatedTime < 1.5 - 1e-6)
            {
                sim.Step(1f / 60f);
                var report = sim.ReadDiagnostics();
                most = Math.Max(most, report.KineticEnergy);
                fastest = Math.Max(fastest, report.MaxSpeed);
                if (++frame % 6 == 0) series.Add($"{1000 * report.KineticEnergy:F2}/{report.MaxSpeed:F2}");
            }
            // How much of the kinetic energy is the droplet moving as a whole (DropletDriftProbe).
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            var ball = LaplaceDroplets.Ball(particles, Spacing);
            double particleMass = scene.SpawnBoxes[0].Phase.RestDensity * Spacing * Spacing * Spacing;
            var (drift, kinetic, carried) = LaplaceDroplets.Motion(particles, ball.Members, particleMass);
            TestContext.Progress.WriteLine($"droplet at {_sigma} N/m under {_solver}: release {1000 * release:F2} mJ; kinetic energy at most " +
                $"{1000 * most:F2} mJ ({(release > 0 ? $"{most / release:F1} x" : "no release")}), fastest {fastest:F2} m/s (health bounds {check.SpeedBound:F3} m/s, " +
                $"{1000 * check.EnergyBound:F2} mJ); mJ / m/s every 0.1 s: {string.Join(" ", series)}; at 1.5 s the droplet moves at " +
                $"{drift.Length():F3} m/s, {(kinetic > 0 ? carried / kinetic : 0):P0} of {1000 * kinetic:F2} mJ, with " +
                $"{particles.Length - ball.Members.Length} particles shed");
        }
    }
}
