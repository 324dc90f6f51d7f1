using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// A container half full of water turns at 90 deg/s about z for one second (a quarter turn): the wall particles
    /// turn with it and must hold every fluid particle inside, without the last-resort clamp. One run, checked at
    /// every frame (1/60 s) from read-back particles in container-local space.
    /// </summary>
    public sealed class RotatingContainerTests
    {
        const float Omega = 0.5f * MathF.PI; // 90 deg/s
        static readonly Vector3 Size = new Vector3(0.3f, 0.3f, 0.1f);
        int _count, _mostOutside, _clampHits, _outsideCount, _nanCount;
        double _deepestOutside = double.NegativeInfinity, _angle;

        [OneTimeSetUp]
        public void TurnAQuarter()
        {
            var settings = new FluidSettings { ParticleSpacing = 0.025f, SmoothingRadius = 0.05f, MaxSubsteps = 200 };
            var scene = SolverScenes.Scene(settings, Size,
                SolverScenes.Box("Water", SolverScenes.Water(viscosity: 0.001f), new Vector3(0f, -0.075f, 0f), new Vector3(0.3f, 0.15f, 0.1f)));
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            _count = sim.ParticleCount;
            var particles = new Particle[_count];
            const int frames = 60;
            for (int frame = 1; frame <= frames; frame++)
            {
                _angle = Omega * frame / 60.0;
                var container = new ContainerDescription
                {
                    Size = Size,
                    Rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, (float)_angle),
                    AngularVelocity = new Vector3(0f, 0f, Omega),
                };
                sim.UpdateContainer(container);
                sim.Step(1f / 60f);
                sim.Particles.GetData(particles);
                int outside = 0;
                foreach (var p in particles)
                {
                    var q = container.ToLocal(p.Position);
                    // How far the particle centre lies beyond the nearest wall (negative: inside).
                    double beyond = Math.Max(Math.Abs(q.X) - 0.5 * Size.X, Math.Max(Math.Abs(q.Y) - 0.5 * Size.Y, Math.Abs(q.Z) - 0.5 * Size.Z));
                    _deepestOutside = Math.Max(_deepestOutside, beyond);
                    if (beyond > 0) outside++;
                }
                _mostOutside = Math.Max(_mostOutside, outside);
            }
            var report = sim.ReadDiagnostics();
            _clampHits = report.ClampHits;
            _outsideCount = report.OutsideCount;
            _nanCount = report.NanCount;
            TestContext.Progress.WriteLine($"rotating container 90 deg/s, 1 s: N = {_count}, {sim.BoundaryCount} boundary, turned {_angle * 180 / Math.PI:F1} deg; " +
                $"most particles outside in a frame {_mostOutside}, closest centre to a wall {-1000 * _deepestOutside:F2} mm inside; clamp hits {_clampHits}; {report}");
        }

        [Test]
        public void AFewHundredParticlesTurnAQuarter()
        {
            Assert.That(_count, Is.InRange(200, 1000));
            Assert.That(_angle * 180 / Math.PI, Is.EqualTo(90.0).Within(1e-3));
        }

        [Test]
        public void EveryParticleStaysInsideAtEveryFrame()
        {
            Assert.That(_mostOutside, Is.EqualTo(0));
            Assert.That(_deepestOutside, Is.LessThan(0.0));
            Assert.That(_outsideCount, Is.EqualTo(0));
            Assert.That(_nanCount, Is.EqualTo(0));
        }

        [Test]
        public void TheWallParticlesHoldTheFluidWithoutTheClamp() => Assert.That(_clampHits, Is.EqualTo(0));
    }
}
