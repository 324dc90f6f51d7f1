using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Output;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// Whether the OilAndWater interface settles as a liquid's would: a measurement run by name,
    /// `bash Headless/test.sh --filter FullyQualifiedName~InternalSeicheProbe`, which CI does not run.
    /// <para>
    /// Once the lock exchange has laid the oil over the water, the interface is left tilted and should rock as the
    /// fundamental internal seiche of the tank, decaying to flat. Two layers of depths h1 (oil, rho1) over h2 (water,
    /// rho2) with a free surface, in a tank of length L, rock at the slow root of
    ///   omega^4 (rho2 coth(k h1) coth(k h2) + rho1) - omega^2 rho2 g k (coth(k h1) + coth(k h2)) + (rho2 - rho1) g^2 k^2 = 0,
    /// k = pi / L (Lamb, "Hydrodynamics", art. 231). The depths are the layers' measured volumes over the floor.
    /// </para>
    /// <para>
    /// The interface's signed rise along the tank (<see cref="InterfaceTilt.Rises"/>) is sampled every 50 ms from 2 s
    /// on; its zero crossings give the period, its extremes between them the decay. Two fixtures: the scene as shipped
    /// (the RestingTank configuration: delta-SPH, Wendland C2 at 2.85 spacings, LatticeStability) and the scene in its
    /// previous configuration (summation, the cubic spline at 2 spacings), whose interface froze tilted.
    /// </para>
    /// </summary>
    [Explicit("a measurement, not a check: run it by name")]
    [TestFixture(false)]
    [TestFixture(true)]
    public sealed class InternalSeicheProbe
    {
        const double Seconds = 12.0, Sample = 0.05, Settled = 2.0;
        readonly bool _cubicSpline;

        public InternalSeicheProbe(bool cubicSpline) => _cubicSpline = cubicSpline;

        [Test]
        public void TheInterfaceRocksAtTheSeichePeriod()
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            var s = scene.Settings;
            if (_cubicSpline)
            {
                s.SmoothingKernel = KernelFamily.CubicSpline;
                s.SmoothingRadius = 2f * s.ParticleSpacing;
                s.WcsphDensity = WcsphDensity.Summation;
            }
            string name = $"OilAndWater, {s.WcsphDensity}, {s.SmoothingKernel} at {s.SmoothingRadius / s.ParticleSpacing:F2} spacings";

            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            var times = new List<double>();
            var rises = new List<double>();
            FluidMeasures? last = null;
            double next = Settled;
            while (sim.SimulatedTime < Seconds - 1e-6)
            {
                sim.Step(1f / 60f);
                if (sim.SimulatedTime < next - 1e-6) continue;
                next += Sample;
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                last = FluidMeasures.Measure(sim.SimulatedTime, particles, densities, sim.PhaseRows, scene.Container, s.Gravity, s.ParticleSpacing, s.SmoothingRadius);
                times.Add(sim.SimulatedTime);
                rises.Add(last.InterfaceRises[0].AlongU);
            }
            Assert.That(last, Is.Not.Null);
            var report = sim.ReadDiagnostics();

            // Layer depths from the measured volumes, and the seiche the two-layer theory gives them.
            var phases = sim.PhaseRows;
            double floorArea = scene.Container.Size.X * scene.Container.Size.Z;
            var depth = new double[phases.Count];
            for (int i = 0; i < particles.Length; i++)
                depth[particles[i].Phase] += phases[(int)particles[i].Phase].ParticleMass / densities[i].X / floorArea;
            int water = phases[0].RestDensity > phases[1].RestDensity ? 0 : 1, oil = 1 - water;
            double period = TwoLayerSeichePeriod(scene.Container.Size.X, depth[oil], phases[oil].RestDensity, depth[water], phases[water].RestDensity, s.Gravity.Length());

            var crossings = new List<double>();
            for (int i = 1; i < rises.Count; i++)
                if (Math.Sign(rises[i]) != Math.Sign(rises[i - 1]) && rises[i - 1] != 0)
                    crossings.Add(times[i - 1] + (times[i] - times[i - 1]) * rises[i - 1] / (rises[i - 1] - rises[i]));
            var extremes = new List<double>();
            for (int c = 0; c + 1 < crossings.Count; c++)
                extremes.Add(Enumerable.Range(0, rises.Count).Where(i => times[i] > crossings[c] && times[i] < crossings[c + 1]).Max(i => Math.Abs(rises[i])));

            string measured = crossings.Count >= 2
                ? $"crossings at {string.Join(", ", crossings.Select(t => t.ToString("F2")))} s: period {2 * (crossings[^1] - crossings[0]) / (crossings.Count - 1):F2} s; " +
                  $"swings {string.Join(", ", extremes.Select(a => (1000 * a).ToString("F1")))} mm"
                : $"{crossings.Count} crossing(s) after {Settled} s: the tilt holds";
            TestContext.Progress.WriteLine($"internal seiche ({name}): layers {1000 * depth[oil]:F1} mm oil over {1000 * depth[water]:F1} mm water, " +
                $"theory {period:F2} s; {measured}; rise along the tank at {Settled} s {1000 * rises[0]:F1} mm, at {Seconds} s {1000 * rises[^1]:F1} mm; " +
                $"max speed at {Seconds} s {1000 * report.MaxSpeed:F1} mm/s; clamp hits {report.ClampHits}");
        }

        /// <summary>The fundamental internal seiche's period, s: the slow root of the two-layer dispersion relation with a
        /// free surface at k = pi / L.</summary>
        static double TwoLayerSeichePeriod(double length, double upperDepth, double upperDensity, double lowerDepth, double lowerDensity, double g)
        {
            double k = Math.PI / length, cu = 1 / Math.Tanh(k * upperDepth), cl = 1 / Math.Tanh(k * lowerDepth);
            double a = lowerDensity * cu * cl + upperDensity, b = lowerDensity * g * k * (cu + cl), c = (lowerDensity - upperDensity) * g * g * k * k;
            double omega2 = (b - Math.Sqrt(b * b - 4 * a * c)) / (2 * a);
            return 2 * Math.PI / Math.Sqrt(omega2);
        }
    }
}
