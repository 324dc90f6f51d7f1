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
    /// The surface tension a liquid makes, read from Laplace's law: cubes of the liquid without gravity pull themselves
    /// into droplets, whose core pressure stands 2 sigma / R above the outside's. Each droplet runs WCSPH with a soft Tait
    /// stiffness (2000 Pa) so the pressure reads clearly, and gives its pressure within half its radius, averaged over
    /// 0.5 to 1.5 s; a least-squares fit p = p_flat + 2 sigma / R over the droplets gives sigma. Shared by
    /// <see cref="LaplacePressureProbe"/> and <see cref="LaplaceLawTests"/>.
    /// </summary>
    public static class LaplaceDroplets
    {
        public sealed class Fit
        {
            /// <summary>The tension the droplets make, N/m.</summary>
            public double Sigma;
            /// <summary>The fit's pressure at 1 / R = 0, Pa: what the force does to a flat surface.</summary>
            public double Flat;
            /// <summary>Each droplet's core pressure less the fit's, Pa.</summary>
            public double[] Residuals = Array.Empty<double>();

            public override string ToString() =>
                $"sigma {Sigma:F3} N/m, p_flat {Flat:F1} Pa; fit residuals {string.Join(", ", Residuals.Select(r => $"{r:F1} Pa"))}";
        }

        /// <summary>Fits the droplets of <paramref name="sides"/> spacings a side of a liquid whose SurfaceTension is
        /// <paramref name="sigma"/> N/m.</summary>
        public static Fit Measure(KernelFamily kernel, float supportRatio, float spacing, float restDensity, float sigma,
            params int[] sides)
        {
            var drops = sides.Select(side => Droplet(kernel, supportRatio, spacing, restDensity, sigma, side)).ToArray();
            double mx = drops.Average(d => 1 / d.Radius), my = drops.Average(d => d.Pressure);
            double slope = drops.Sum(d => (1 / d.Radius - mx) * (d.Pressure - my)) / drops.Sum(d => (1 / d.Radius - mx) * (1 / d.Radius - mx));
            double flat = my - slope * mx;
            return new Fit
            {
                Sigma = slope / 2,
                Flat = flat,
                Residuals = drops.Select(d => d.Pressure - flat - slope / d.Radius).ToArray(),
            };
        }

        /// <summary>The scene of one droplet: a cube of <paramref name="particlesASide"/> spacings a side in a container
        /// 60 spacings wide, without gravity.</summary>
        public static FluidSceneDescription Scene(KernelFamily kernel, float supportRatio, float spacing, float restDensity,
            float sigma, int particlesASide)
        {
            var settings = SolverScenes.Coarse(spacing);
            settings.SmoothingKernel = kernel;
            settings.SmoothingRadius = supportRatio * spacing;
            settings.Gravity = Vector3.Zero;
            settings.XsphEpsilon = 0f;
            settings.Stiffness = 2000f;
            settings.MaxSubsteps = 200;
            float side = particlesASide * spacing;
            // A viscous liquid (2 mm^2/s, water's 2 Pa s) so that the cube's rounding rings down within the half second
            // before sampling.
            var liquid = SolverScenes.Water(2f * restDensity / 1000f, sigma);
            liquid.RestDensity = restDensity;
            var box = SolverScenes.Box("Water", liquid, Vector3.Zero, new Vector3(side), jitter: 0.05f);
            var scene = SolverScenes.Scene(settings, new Vector3(60 * spacing), box);
            Assert.That(scene.Validate(), Is.Empty);
            return scene;
        }

        static (double Radius, double Pressure) Droplet(KernelFamily kernel, float supportRatio, float spacing, float restDensity,
            float sigma, int particlesASide)
        {
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, Scene(kernel, supportRatio, spacing, restDensity, sigma, particlesASide));
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
            TestContext.Progress.WriteLine($"{kernel} at {supportRatio} spacings of {spacing} m, {particlesASide} a side: " +
                $"N {sim.ParticleCount}, radius {radii.Average():F4} m, core pressure {p:F1} Pa (sd {sd:F1} over {pressures.Count} samples)");
            return (radii.Average(), p);
        }
    }
}
