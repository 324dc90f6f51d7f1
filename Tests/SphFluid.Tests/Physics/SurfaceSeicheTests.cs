using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Output;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// A sloshing tank against linear wave theory: the shipped RestingTank's water (0.4 m along the sloshing, 0.3 m deep,
    /// 25 mm spacing; WCSPH, delta-SPH, Wendland C2 at 2.85 spacings) spawned with its free surface tilted into the tank's
    /// fundamental mode by one spacing at the end walls (<see cref="TiltSurface"/>; k a = 0.21 for the mode, a swing
    /// that lengthens a deep-water standing wave's period by under one per cent, Tadjbakhsh and Keller, "Standing surface
    /// waves of finite amplitude") and left to slosh for two periods. The surface's signed rise along the
    /// tank (<see cref="InterfaceTilt.SurfaceRise"/>) is sampled every frame; a damped oscillation fitted to it gives the
    /// period, which must be the standing wave's of <see cref="SurfaceSeiche"/> for the water's measured depth, and its
    /// decay, which is printed beside the laminar theory's. <see cref="SurfaceSeicheProbe"/> measures the other solver,
    /// kernel and resolutions.
    /// </summary>
    public sealed class SurfaceSeicheTests
    {
        Slosh _slosh = null!;

        [OneTimeSetUp]
        public void SloshTwoPeriods()
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("RestingTank"), RunnerPaths.Project).Description;
            TiltSurface(scene, 1);
            _slosh = Run(scene, "RestingTank.unity, tilted by 1 spacing", 1.5);
        }

        /// <summary>Within 3 % of the linear standing wave's period, the bar the resting tank's pressure gradient meets
        /// against rho0 g.</summary>
        [Test]
        public void TheSurfaceSloshesAtTheStandingWavePeriodWithinThreePerCent() =>
            Assert.That(_slosh.MeasuredPeriod, Is.EqualTo(_slosh.Period).Within(0.03 * _slosh.Period));

        [Test]
        public void NothingLeavesAndTheLastResortClampStaysIdle()
        {
            Assert.That(_slosh.Report.OutsideCount, Is.EqualTo(0));
            Assert.That(_slosh.Report.ClampHits, Is.EqualTo(0));
            Assert.That(_slosh.Report.NanCount, Is.EqualTo(0));
        }

        internal sealed record Slosh(double Period, double MeasuredPeriod, double Decay, double MeasuredDecay, double Depth, DiagnosticsReport Report);

        /// <summary>The one box of water in columns one spacing wide, each <paramref name="spacings"/> round(cos(pi x /
        /// L)) spacings above or below its spawned depth, whole spacings so that every column's lattice is the box's.</summary>
        internal static void TiltSurface(FluidSceneDescription scene, int spacings)
        {
            var water = scene.SpawnBoxes.Single();
            var container = scene.Container;
            float s = scene.Settings.ParticleSpacing, floor = container.Position.Y - container.Size.Y / 2;
            int columns = (int)Math.Round(container.Size.X / s), depth = (int)Math.Round(water.Size.Y / s);
            var tilted = new List<FluidBlock>();
            for (int c = 0; c < columns; c++)
            {
                int rise = (int)Math.Round(spacings * Math.Cos(Math.PI * (c + 0.5) / columns));
                float height = (depth + rise) * s;
                var column = water.Clone();
                column.Phase = water.Phase;
                column.Center = new Vector3(container.Position.X - container.Size.X / 2 + (c + 0.5f) * s, floor + height / 2, water.Center.Z);
                column.Size = new Vector3(s, height, water.Size.Z);
                tilted.Add(column);
            }
            scene.SpawnBoxes = tilted;
        }

        /// <summary>Runs the tilted tank for <paramref name="seconds"/>, sampling the surface's rise every frame, and
        /// prints the fit beside the theory for the container's length and the water's measured depth; the fit looks for
        /// a decay up to <paramref name="highestDecay"/> per second.</summary>
        internal static Slosh Run(FluidSceneDescription scene, string name, double seconds, double highestDecay = 2)
        {
            var s = scene.Settings;
            var container = scene.Container;
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            var times = new List<double>();
            var rises = new List<double>();
            void Sample()
            {
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                var measures = FluidMeasures.Measure(sim.SimulatedTime, particles, densities, sim.PhaseRows, container, s.Gravity, s.ParticleSpacing, s.SmoothingRadius);
                times.Add(sim.SimulatedTime);
                rises.Add(measures.SurfaceRise.AlongU);
            }
            Sample();
            while (sim.SimulatedTime < seconds - 1e-6)
            {
                sim.Step(1f / 60f);
                Sample();
            }
            var report = sim.ReadDiagnostics();

            var phase = sim.PhaseRows.Single();
            double volume = 0;
            for (int i = 0; i < particles.Length; i++) volume += phase.ParticleMass / densities[i].X;
            double depth = volume / (container.Size.X * container.Size.Z), g = s.Gravity.Length();
            double omega = SurfaceSeiche.AngularFrequency(container.Size.X, depth, g);
            double decay = SurfaceSeiche.DecayRate(container.Size.X, container.Size.Z, depth, g, phase.RestDensity, phase.Viscosity,
                container.Friction == WallFriction.NoSlip);
            var fit = InternalSeiche.FitDampedOscillation(times, rises, highestOmega: 3 * omega, highestGamma: highestDecay);
            var slosh = new Slosh(2 * Math.PI / omega, 2 * Math.PI / fit.Omega, decay, fit.Gamma, depth, report);

            // Where the fluid's centres end beside the end walls: its own length is their span plus a spacing.
            float left = container.Position.X - container.Size.X / 2, right = container.Position.X + container.Size.X / 2;
            double nearest = particles.Min(p => p.Position.X) - left, farthest = right - particles.Max(p => p.Position.X);
            double ownLength = container.Size.X - nearest - farthest + s.ParticleSpacing;
            var crossings = InternalSeiche.ZeroCrossings(times, rises);
            TestContext.Progress.WriteLine(
                $"surface seiche ({name}: {s.PressureSolver}, {s.SmoothingKernel} at {s.SmoothingRadius / s.ParticleSpacing:F2} spacings, " +
                $"spacing {1000 * s.ParticleSpacing:F2} mm, {1000 * container.Size.Z:F0} mm wide), N={sim.ParticleCount}: depth {1000 * depth:F1} mm; " +
                $"last sub-step {1000 * sim.LastStep.TimeStep:F3} ms, viscous explicit limit {1000 * sim.TimeStep.ViscousTimeStep:F3} ms" +
                $"{(sim.Plan.ImplicitViscosity ? " (implicit beyond it)" : "")}; " +
                $"theory: period {slosh.Period:F4} s, laminar decay {decay:F4}/s; fitted over {seconds} s: period {slosh.MeasuredPeriod:F4} s " +
                $"({100 * (slosh.MeasuredPeriod / slosh.Period - 1):+0.00;-0.00} %), decay {fit.Gamma:F3}/s (RMS residual {1000 * fit.Residual:F2} mm); " +
                $"rise at 0 s {1000 * rises[0]:F1} mm; crossings at {string.Join(", ", crossings.Select(t => t.ToString("F3")))} s; " +
                $"end walls' nearest centres {1000 * nearest:F1} and {1000 * farthest:F1} mm from their faces (the fluid's own length " +
                $"{1000 * ownLength:F1} mm); {report}");
            return slosh;
        }
    }
}
