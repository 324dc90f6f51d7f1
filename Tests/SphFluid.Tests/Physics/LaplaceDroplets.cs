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
    /// 0.5 to 1.5 s; a least-squares fit p = p_flat + 2 sigma / R over the droplets gives sigma. R is the droplet's RMS
    /// radius, as <see cref="SurfaceLayerShare"/> was measured with; the fit by the radius of the ball its particles fill
    /// (<see cref="Fit.SigmaByVolume"/>) is printed beside it, with the particles each droplet shed and how far it moved:
    /// the surface force does not conserve momentum, so the droplets drift, and particles they shed inflate the RMS
    /// radius (known-limits.md). Shared by <see cref="LaplacePressureProbe"/> and <see cref="LaplaceLawTests"/>.
    /// </summary>
    public static class LaplaceDroplets
    {
        public sealed class Fit
        {
            /// <summary>The tension the droplets make, N/m, fitted with their RMS radii.</summary>
            public double Sigma;
            /// <summary>The fit's pressure at 1 / R = 0, Pa: what the force does to a flat surface.</summary>
            public double Flat;
            /// <summary>Each droplet's core pressure less the fit's, Pa.</summary>
            public double[] Residuals = Array.Empty<double>();
            /// <summary>The tension fitted instead with the radius of the ball each droplet's particles fill and the pressure
            /// within half of it of the ball's centre, N/m: shed particles move neither.</summary>
            public double SigmaByVolume;

            public override string ToString() =>
                $"sigma {Sigma:F3} N/m, p_flat {Flat:F1} Pa; fit residuals {string.Join(", ", Residuals.Select(r => $"{r:F1} Pa"))}; " +
                $"by the balls' radii sigma {SigmaByVolume:F3} N/m";
        }

        /// <summary>Fits the droplets of <paramref name="sides"/> spacings a side of a liquid whose SurfaceTension is
        /// <paramref name="sigma"/> N/m.</summary>
        public static Fit Measure(KernelFamily kernel, float supportRatio, float spacing, float restDensity, float sigma,
            params int[] sides)
        {
            var drops = sides.Select(side => Droplet(kernel, supportRatio, spacing, restDensity, sigma, side)).ToArray();
            var (slope, flat) = Line(drops.Select(d => (1 / d.RmsRadius, d.Pressure)).ToArray());
            return new Fit
            {
                Sigma = slope / 2,
                Flat = flat,
                Residuals = drops.Select(d => d.Pressure - flat - slope / d.RmsRadius).ToArray(),
                SigmaByVolume = Line(drops.Select(d => (1 / d.BallRadius, d.BallPressure)).ToArray()).Slope / 2,
            };
        }

        /// <summary>The least-squares line y = intercept + slope x.</summary>
        static (double Slope, double Intercept) Line((double X, double Y)[] points)
        {
            double mx = points.Average(p => p.X), my = points.Average(p => p.Y);
            double slope = points.Sum(p => (p.X - mx) * (p.Y - my)) / points.Sum(p => (p.X - mx) * (p.X - mx));
            return (slope, my - slope * mx);
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
            // A viscous liquid (2e-3 m^2/s at every density: 2 Pa s at 1 000 kg/m^3, 2 000 times water's) so that the
            // cube's rounding rings down within the half second before sampling.
            var liquid = SolverScenes.Water(2f * restDensity / 1000f, sigma);
            liquid.RestDensity = restDensity;
            var box = SolverScenes.Box("Water", liquid, Vector3.Zero, new Vector3(side), jitter: 0.05f);
            var scene = SolverScenes.Scene(settings, new Vector3(60 * spacing), box);
            Assert.That(scene.Validate(), Is.Empty);
            return scene;
        }

        static (double RmsRadius, double Pressure, double BallRadius, double BallPressure) Droplet(KernelFamily kernel,
            float supportRatio, float spacing, float restDensity, float sigma, int particlesASide)
        {
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, Scene(kernel, supportRatio, spacing, restDensity, sigma, particlesASide));
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            var pressures = new List<double>();
            var ballPressures = new List<double>();
            var rmsRadii = new List<double>();
            var ballRadii = new List<double>();
            int shed = 0;
            Vector3 start = Vector3.Zero, centre = Vector3.Zero, velocity = Vector3.Zero;
            for (int sample = 5; sample <= 15; sample++)
            {
                while (sim.SimulatedTime < 0.1 * sample - 1e-6) sim.Step(1f / 60f);
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                var centreOfAll = particles.Aggregate(Vector3.Zero, (a, q) => a + q.Position) / particles.Length;
                var r = particles.Select(q => (double)(q.Position - centreOfAll).Length()).ToArray();
                double rmsRadius = Math.Sqrt(r.Select(x => x * x).Average() / 0.6); // a uniform ball: <r^2> = 3/5 R^2
                pressures.Add(Enumerable.Range(0, particles.Length).Where(i => r[i] < 0.5 * rmsRadius).Average(i => (double)densities[i].Y));
                rmsRadii.Add(rmsRadius);
                var ball = Ball(particles, spacing);
                if (sample == 5) start = ball.Centre;
                (centre, shed) = (ball.Centre, particles.Length - ball.Members.Length);
                velocity = Motion(particles, ball.Members, 0.0).Velocity;
                var core = ball.Members.Where(i => (particles[i].Position - ball.Centre).Length() < 0.5 * ball.Radius).ToArray();
                ballPressures.Add(core.Average(i => (double)densities[i].Y));
                ballRadii.Add(ball.Radius);
            }
            double p = pressures.Average(), sd = Math.Sqrt(pressures.Select(x => (x - p) * (x - p)).Average());
            TestContext.Progress.WriteLine($"{kernel} at {supportRatio} spacings of {spacing} m, {particlesASide} a side: " +
                $"N {sim.ParticleCount}, RMS radius {rmsRadii.Average():F4} m (the ball's {ballRadii.Average():F4}), " +
                $"core pressure {p:F1} Pa (sd {sd:F1} over {pressures.Count} samples; the ball's {ballPressures.Average():F1}); " +
                $"at 1.5 s {shed} particles shed, the droplet {(centre - start).Length() * 1000:F1} mm from where it was at 0.5 s " +
                $"and moving at {velocity.Length():F3} m/s");
            return (rmsRadii.Average(), p, ballRadii.Average(), ballPressures.Average());
        }

        /// <summary>The droplet among the particles: those within 1.5 times the radius a ball's median distance gives of
        /// their median point (a spawned cube's corners lie at 1.25 of it), so that particles it shed move neither its
        /// centre nor its radius; the radius is the ball its members fill at one spacing cubed each, as the spawn lattice
        /// filled it.</summary>
        public static (Vector3 Centre, double Radius, int[] Members) Ball(Particle[] particles, float spacing)
        {
            float Median(Func<Particle, float> axis) => particles.Select(axis).OrderBy(x => x).ElementAt(particles.Length / 2);
            var middle = new Vector3(Median(p => p.Position.X), Median(p => p.Position.Y), Median(p => p.Position.Z));
            // Half a uniform ball's particles lie within 0.5^(1/3) of its radius.
            double reach = 1.5 * particles.Select(p => (double)(p.Position - middle).Length()).OrderBy(r => r)
                .ElementAt(particles.Length / 2) / Math.Cbrt(0.5);
            var members = Enumerable.Range(0, particles.Length).Where(i => (particles[i].Position - middle).Length() < reach).ToArray();
            var centre = members.Aggregate(Vector3.Zero, (a, i) => a + particles[i].Position) / members.Length;
            double radius = Math.Cbrt(3 * members.Length / (4 * Math.PI)) * spacing;
            return (centre, radius, members);
        }

        /// <summary>How a droplet moves as a whole: its members' mean velocity, the kinetic energy of every particle, and
        /// the part of it that mean velocity carries (the members' mass moving at it), for particles of
        /// <paramref name="particleMass"/> kg.</summary>
        public static (Vector3 Velocity, double Kinetic, double Carried) Motion(Particle[] particles, int[] members, double particleMass)
        {
            var velocity = members.Aggregate(Vector3.Zero, (a, i) => a + particles[i].Velocity) / members.Length;
            double kinetic = particles.Sum(p => 0.5 * particleMass * p.Velocity.LengthSquared());
            return (velocity, kinetic, 0.5 * particleMass * members.Length * velocity.LengthSquared());
        }
    }
}
