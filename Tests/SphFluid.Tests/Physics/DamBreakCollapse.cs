using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Output;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The collapse of a water column of width a and height 2a against the end wall of a tank ("An experimental
    /// study of the collapse of liquid columns on a rigid horizontal plane", Martin and Moyce 1952), at two
    /// resolutions, a / s = 8 and 12 (probes add finer ones). The surge front x (from the back wall) is compared as
    /// Z = x / a against T = t sqrt(2 g / a), the paper's variables, at the times of the paper's measurements for the a = 2.25 in
    /// column (its figure 3, n^2 = 2). The tank is a slice a / 2 deep with slip walls, standing in for the paper's
    /// two-dimensional collapse. The front is the farthest particle centre on the floor (<see cref="DamBreakFront"/>)
    /// plus half a spacing: the lattice's outermost centres sit half a spacing inside the fluid's edge.
    /// Each fixture runs the collapse with its own pressure solver and settings (<see cref="Configure"/>); what holds
    /// for any of them is checked here, how near the paper each comes in its own fixture.
    /// </summary>
    public abstract class DamBreakCollapse
    {
        protected const float A = 0.1f, Gravity = 9.81f;

        /// <summary>Martin and Moyce's front for a = 2.25 in, n^2 = 2: (T, Z) points digitised from their figure 3, as tabulated in the
        /// PySPH project's dam-break validation data (measurements of the 1952 experiment, not code).</summary>
        protected static readonly (double T, double Z)[] Measured =
            { (0.832, 1.217), (1.219, 1.474), (1.997, 2.292), (2.547, 2.995), (3.345, 4.134) };

        static readonly double TimeScale = Math.Sqrt(2.0 * Gravity / A);

        /// <summary>Z at each of <see cref="Measured"/>'s times, by resolution a / s.</summary>
        protected readonly Dictionary<int, double[]> Fronts = new Dictionary<int, double[]>();
        readonly Dictionary<int, DiagnosticsReport> _reports = new Dictionary<int, DiagnosticsReport>();

        /// <summary>The fixture's solver and settings, applied to the column's scene.</summary>
        protected abstract void Configure(FluidSettings settings);

        /// <summary>The resolutions a / s the fixture runs; 8 and 12, which the checks below compare, among them.</summary>
        protected virtual IReadOnlyList<int> Resolutions => new[] { 8, 12 };

        /// <summary>What the printed lines call the fixture's configuration.</summary>
        protected virtual string Label => GetType().Name;

        /// <summary>Z at the paper's last measurement over the paper's, less one, at resolution a / s.</summary>
        protected double LastLead(int perWidth) => Fronts[perWidth][Measured.Length - 1] / Measured[Measured.Length - 1].Z - 1.0;

        public static FluidSceneDescription Column(int perWidth)
        {
            float s = A / perWidth;
            var settings = new FluidSettings { ParticleSpacing = s, SmoothingRadius = 2f * s, MaxSubsteps = 400 };
            var tank = new Vector3(5f * A, 2.4f * A, 0.5f * A);
            var water = new Vector3(A, 2f * A, tank.Z);
            var box = SolverScenes.Box("Water", SolverScenes.Water(viscosity: 0.001f),
                new Vector3(-0.5f * tank.X + 0.5f * A, -0.5f * tank.Y + A, 0f), water, jitter: 0f);
            var scene = SolverScenes.Scene(settings, tank, box);
            scene.Container.Friction = WallFriction.Slip;
            return scene;
        }

        [OneTimeSetUp]
        public void CollapseAtEachResolution()
        {
            foreach (int perWidth in Resolutions)
            {
                var scene = Column(perWidth);
                Configure(scene.Settings);
                var wall = System.Diagnostics.Stopwatch.StartNew();
                using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
                var particles = new Particle[sim.ParticleCount];
                var frame = new GravityFrame(scene.Container, scene.Settings.Gravity);
                var local = new Vector3[sim.ParticleCount];
                float s = scene.Settings.ParticleSpacing;
                var times = new List<double>();
                var fronts = new List<double>();
                double end = Measured[Measured.Length - 1].T / TimeScale + 0.01;
                const float step = 1f / 240f;
                while (true)
                {
                    sim.Particles.GetData(particles);
                    for (int i = 0; i < particles.Length; i++) local[i] = frame.ToLocal(particles[i].Position);
                    times.Add(sim.SimulatedTime);
                    fronts.Add(DamBreakFront.Measure(local, frame, s, scene.Settings.SmoothingRadius).SurgeFront + 0.5 * s);
                    if (sim.SimulatedTime >= end) break;
                    sim.Step(step);
                }
                _reports[perWidth] = sim.ReadDiagnostics();
                Fronts[perWidth] = Measured.Select(m => Interpolate(times, fronts, m.T / TimeScale) / A).ToArray();
                TestContext.Progress.WriteLine($"dam break ({Label}) a/s = {perWidth}: N = {sim.ParticleCount}, {sim.BoundaryCount} boundary; Z at T " +
                    string.Join(", ", Measured.Select((m, k) => $"{m.T:F2}: {Fronts[perWidth][k]:F3} (M&M {m.Z:F3}, {100 * (Fronts[perWidth][k] / m.Z - 1):+0.0;-0.0} %)")) +
                    $"; {_reports[perWidth]}; {wall.Elapsed.TotalSeconds:F0} s of wall");
            }
        }

        static double Interpolate(List<double> times, List<double> values, double t)
        {
            for (int i = 1; i < times.Count; i++)
                if (times[i] >= t)
                {
                    double w = (t - times[i - 1]) / (times[i] - times[i - 1]);
                    return values[i - 1] + w * (values[i] - values[i - 1]);
                }
            return values[values.Count - 1];
        }

        [Test]
        public void TheFrontsAtTwoResolutionsAgreeWithinFivePerCent()
        {
            for (int k = 0; k < Measured.Length; k++)
                Assert.That(Fronts[12][k], Is.EqualTo(Fronts[8][k]).Within(0.05 * Fronts[8][k]), $"Z at T = {Measured[k].T}");
        }

        [Test]
        public void TheSurgeRunsAlongTheFloor()
        {
            Assert.That(Fronts[12][Measured.Length - 1], Is.GreaterThan(2.5), "Z at the last measured time: the column collapsed");
        }

        [TestCase(8)]
        [TestCase(12)]
        public void NothingLeavesTheTank(int perWidth)
        {
            Assert.That(_reports[perWidth].OutsideCount, Is.EqualTo(0));
            Assert.That(_reports[perWidth].NanCount, Is.EqualTo(0));
            Assert.That(_reports[perWidth].ClampHits, Is.EqualTo(0), "the wall particles alone held the surge");
        }
    }
}
