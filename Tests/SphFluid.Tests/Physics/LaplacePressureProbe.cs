using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// What the SurfaceTension setting, Akinci et al.'s cohesion coefficient gamma (SphSurfaceTension.hlsl), makes as a
    /// surface tension: cubes of water without gravity pull themselves into droplets, and Laplace's law says the pressure
    /// inside a droplet of radius R stands 2 sigma / R above the outside's. Three droplets of 10, 14 and 20 spacings a side
    /// (WCSPH, a soft Tait stiffness so the pressure reads clearly) give the pressure at their cores, averaged over 0.5 to
    /// 1.5 s, and a least-squares fit p = p_flat + 2 sigma / R gives sigma. p_flat is the cohesion's pull on a flat
    /// surface, which compresses the liquid as a whole and which no liquid's surface tension does. Further fixtures vary
    /// the support ratio and the rest density. A measurement (one to three minutes of lavapipe a fixture, about 20 for
    /// all nine), run by name:
    /// <c>bash Headless/test.sh --filter FullyQualifiedName~LaplacePressureProbe</c>.
    /// </summary>
    [Explicit("a measurement, minutes of lavapipe")]
    [TestFixture(KernelFamily.CubicSpline, 2f, 0.005f, 1000f, 1f)]
    [TestFixture(KernelFamily.CubicSpline, 2f, 0.01f, 1000f, 1f)]
    [TestFixture(KernelFamily.WendlandC2, 2.85f, 0.005f, 1000f, 1f)]
    [TestFixture(KernelFamily.WendlandC2, 2.85f, 0.01f, 1000f, 1f)]
    // The support ratio, at the ends of each kernel's allowed range.
    [TestFixture(KernelFamily.CubicSpline, 2.25f, 0.005f, 1000f, 1f)]
    [TestFixture(KernelFamily.WendlandC2, 2f, 0.005f, 1000f, 1f)]
    [TestFixture(KernelFamily.WendlandC2, 4f, 0.005f, 1000f, 1f)]
    // The rest density, with gamma m^2 held (the cohesion's pull per pair the same, the curvature term's gamma m not).
    [TestFixture(KernelFamily.CubicSpline, 2f, 0.005f, 500f, 4f)]
    [TestFixture(KernelFamily.CubicSpline, 2f, 0.005f, 2000f, 0.25f)]
    public sealed class LaplacePressureProbe
    {
        readonly KernelFamily _kernel;
        readonly float _supportRatio, _spacing, _restDensity, _gamma;

        public LaplacePressureProbe(KernelFamily kernel, float supportRatio, float spacing, float restDensity, float gamma)
        {
            _kernel = kernel;
            _supportRatio = supportRatio;
            _spacing = spacing;
            _restDensity = restDensity;
            _gamma = gamma;
        }

        (double Radius, double Pressure) Droplet(int particlesASide)
        {
            var settings = SolverScenes.Coarse(_spacing);
            settings.SmoothingKernel = _kernel;
            settings.SmoothingRadius = _supportRatio * _spacing;
            settings.Gravity = Vector3.Zero;
            settings.XsphEpsilon = 0f;
            settings.Stiffness = 2000f;
            settings.MaxSubsteps = 200;
            float side = particlesASide * _spacing;
            // A viscous liquid (2 mm^2/s, water's 2 Pa s) so that the cube's rounding rings down within the half second
            // before sampling.
            var liquid = SolverScenes.Water(2f * _restDensity / 1000f, _gamma);
            liquid.RestDensity = _restDensity;
            var water = SolverScenes.Box("Water", liquid, Vector3.Zero, new Vector3(side), jitter: 0.05f);
            var scene = SolverScenes.Scene(settings, new Vector3(60 * _spacing), water);
            Assert.That(scene.Validate(), Is.Empty);
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            var pressures = new List<double>();
            var radii = new List<double>();
            for (int sample = 5; sample <= 15; sample++)
            {
                while (sim.SimulatedTime < 0.1 * sample - 1e-6) sim.Step(1f / 60f);
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                var centre = particles.Aggregate(Vector3.Zero, (a, p) => a + p.Position) / particles.Length;
                var r = particles.Select(p => (double)(p.Position - centre).Length()).ToArray();
                double radius = Math.Sqrt(r.Select(x => x * x).Average() / 0.6); // a uniform ball: <r^2> = 3/5 R^2
                var core = Enumerable.Range(0, particles.Length).Where(i => r[i] < 0.5 * radius).ToArray();
                pressures.Add(core.Average(i => (double)densities[i].Y));
                radii.Add(radius);
            }
            double p = pressures.Average(), sd = Math.Sqrt(pressures.Select(x => (x - p) * (x - p)).Average());
            TestContext.Progress.WriteLine($"{_kernel} at {_supportRatio} spacings of {_spacing} m, {particlesASide} a side: " +
                $"N {sim.ParticleCount}, radius {radii.Average():F4} m, core pressure {p:F1} Pa (sd {sd:F1} over {pressures.Count} samples)");
            return (radii.Average(), p);
        }

        [Test]
        public void TheDropletsGiveSigma()
        {
            var drops = new[] { 10, 14, 20 }.Select(Droplet).ToArray();
            double mx = drops.Average(d => 1 / d.Radius), my = drops.Average(d => d.Pressure);
            double slope = drops.Sum(d => (1 / d.Radius - mx) * (d.Pressure - my)) / drops.Sum(d => (1 / d.Radius - mx) * (1 / d.Radius - mx));
            double flat = my - slope * mx;
            double sigma = slope / 2;
            TestContext.Progress.WriteLine($"{_kernel} at {_supportRatio} spacings of {_spacing} m, rho0 {_restDensity}, gamma {_gamma}: " +
                $"sigma {sigma:F3} N/m ({sigma / _gamma:F2} gamma; sigma / (gamma rho0^2 s^2) " +
                $"{sigma / (_gamma * _restDensity * _restDensity * _spacing * _spacing):F4}), p_flat {flat:F1} Pa; " +
                "fit residuals " + string.Join(", ", drops.Select(d => $"{d.Pressure - flat - slope / d.Radius:F1} Pa")));
            Assert.That(sigma, Is.GreaterThan(0.0), "a droplet's core pressure falls as it grows");
        }
    }
}
