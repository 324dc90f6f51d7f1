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
    /// A sphere made of boundary particles is driven through a pool at 0.25 m/s for one second: it must push the
    /// water aside, and no fluid particle centre may be inside its radius at any frame (1/60 s) of the run. Under both
    /// pressure solvers: DFSPH's wall constraint counts the sphere's own shells at rest (BoundarySampling.OwnNumberDensities).
    /// </summary>
    [TestFixture(PressureSolver.Wcsph)]
    [TestFixture(PressureSolver.Dfsph)]
    public sealed class SphereThroughPoolTests
    {
        readonly PressureSolver _solver;

        public SphereThroughPoolTests(PressureSolver solver) => _solver = solver;

        const float Radius = 0.04f, Speed = 0.25f, StartX = -0.12f, Depth = 0.12f;
        static readonly Vector3 Tank = new Vector3(0.4f, 0.24f, 0.12f);
        int _count, _clampHits, _outsideCount, _nanCount, _insideFrames, _pushed;
        double _closest = double.PositiveInfinity, _travel;

        static Vector3 CentreAt(double t) => new Vector3(StartX + Speed * (float)t, -0.5f * Tank.Y + 0.5f * Depth, 0f);

        [OneTimeSetUp]
        public void DriveTheSphere()
        {
            var settings = new FluidSettings { ParticleSpacing = 0.02f, SmoothingRadius = 0.04f, MaxSubsteps = 200, PressureSolver = _solver };
            var scene = SolverScenes.Scene(settings, Tank,
                SolverScenes.Box("Water", SolverScenes.Water(viscosity: 0.001f), new Vector3(0f, -0.5f * Tank.Y + 0.5f * Depth, 0f), new Vector3(Tank.X, Depth, Tank.Z)));
            scene.Obstacles.Add(new RigidSphere(CentreAt(0), Radius, new Vector3(Speed, 0f, 0f)));
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            _count = sim.ParticleCount;
            var particles = new Particle[_count];
            sim.Particles.GetData(particles);
            var start = particles.ToDictionary(p => p.Id, p => p.Position);
            for (int frame = 1; frame <= 60; frame++)
            {
                // Where the sphere stands at the frame's end, as a Unity Transform reads after it moved; the solver sweeps
                // it there from where the last frame left it.
                var centre = CentreAt(sim.SimulatedTime + 1.0 / 60.0);
                sim.UpdateObstacles(new List<RigidSphere> { new RigidSphere(centre, Radius, new Vector3(Speed, 0f, 0f)) });
                sim.Step(1f / 60f);
                sim.Particles.GetData(particles);
                double closest = particles.Min(p => (double)Vector3.Distance(p.Position, centre));
                _closest = Math.Min(_closest, closest);
                if (closest < Radius) _insideFrames++;
            }
            _travel = CentreAt(sim.SimulatedTime).X - StartX;
            // Water that lay in the sphere's path at the start (within its radius of the line it travelled) and was pushed.
            var end = CentreAt(sim.SimulatedTime);
            foreach (var p in particles)
            {
                var s = start[p.Id];
                bool inPath = s.X > StartX + Radius && s.X < end.X && new Vector2(s.Y - end.Y, s.Z - end.Z).Length() < Radius;
                if (inPath && Vector3.Distance(p.Position, s) > 0.5f * Radius) _pushed++;
            }
            var report = sim.ReadDiagnostics();
            _clampHits = report.ClampHits;
            _outsideCount = report.OutsideCount;
            _nanCount = report.NanCount;
            TestContext.Progress.WriteLine($"{_solver}: sphere r = {Radius} m through a pool at {Speed} m/s, 1 s: N = {_count}, {sim.BoundaryCount} boundary, travelled {_travel:F3} m; " +
                $"closest fluid centre {1000 * _closest:F1} mm from the sphere centre (radius {1000 * Radius:F0} mm), frames with a centre inside {_insideFrames}; " +
                $"particles in its path moved more than r/2: {_pushed}; clamp hits {_clampHits}; {report}");
        }

        [Test]
        public void TheSphereCrossesHalfThePool()
        {
            Assert.That(_count, Is.InRange(200, 2000));
            Assert.That(_travel, Is.EqualTo(Speed * 1.0).Within(1e-3));
        }

        [Test]
        public void NoFluidCentreIsInsideTheSphereAtAnyFrame()
        {
            Assert.That(_insideFrames, Is.EqualTo(0));
            Assert.That(_closest, Is.GreaterThan(Radius));
        }

        [Test]
        public void TheSphereDisplacesTheWaterInItsPath() => Assert.That(_pushed, Is.GreaterThan(5));

        [Test]
        public void TheSphereParticlesHoldTheFluidWithoutTheClamp() => Assert.That(_clampHits, Is.EqualTo(0));

        [Test]
        public void NothingLeavesThePool()
        {
            Assert.That(_outsideCount, Is.EqualTo(0));
            Assert.That(_nanCount, Is.EqualTo(0));
        }
    }
}
