using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// Spin-up: a closed cube 12 cm on a side, its bottom half water at 10 Pa s under gravity, turned about the vertical at
    /// 2 rad/s from rest, its no-slip walls dragging the liquid round. A Newtonian liquid ends in rigid rotation with its
    /// box (its surface a paraboloid 0.7 mm deep at this spin), its angular momentum about the axis I Omega, I the
    /// liquid's moment of inertia about it: a rigid rotation has no strain rate and so no stress. The strain rate's
    /// viscous stress must reach it. Morris's pair force (the default) also acts on a rigid rotation where the free
    /// surface cuts the supports, a torque the walls' drag must balance, so under it the liquid lags its box for as
    /// long as the box turns. Measured at 1 and 2 s: under the strain rate's stress 1.0046 and 1.0013 (DFSPH), 1.0039
    /// and 1.0010 (WCSPH), past the box in the spin-up's overshoot and settling onto it; under Morris's 0.9911 and
    /// 0.9843, 0.9866 and 0.9915.
    /// </summary>
    [TestFixture(PressureSolver.Wcsph)]
    [TestFixture(PressureSolver.Dfsph)]
    public sealed class SpinUpTests
    {
        const float Omega = 2f, Side = 0.12f, Viscosity = 10f, Seconds = 2f;

        readonly PressureSolver _solver;

        public SpinUpTests(PressureSolver solver) => _solver = solver;

        /// <summary>The liquid's angular momentum about the box's axis over I Omega, at <see cref="Seconds"/> and half of it.</summary>
        (double half, double end) SpinUp(ViscousStress stress, bool validated = false, int frames = (int)(Seconds * 60))
        {
            var settings = SolverScenes.Coarse(Side / 8);
            settings.PressureSolver = _solver;
            settings.ViscousStress = stress;
            settings.XsphEpsilon = 0f;
            settings.MaxSubsteps = 1000;
            var box = new Vector3(Side);
            var scene = SolverScenes.Scene(settings, box, SolverScenes.Box("Liquid", SolverScenes.Water(Viscosity),
                new Vector3(0f, -Side / 4, 0f), new Vector3(Side, Side / 2, Side), jitter: 0f));
            using var sim = new FluidSimulation(validated ? GpuTestDevice.Shared : GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            double half = 0.0;
            for (int frame = 1; frame <= frames; frame++)
            {
                sim.UpdateContainer(new ContainerDescription
                {
                    Size = box,
                    Rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitY, Omega * frame / 60f),
                    AngularVelocity = new Vector3(0f, Omega, 0f),
                });
                sim.Step(1f / 60f);
                if (frame == frames / 2 || frame == frames)
                {
                    sim.Particles.GetData(particles);
                    double l = 0.0, inertia = 0.0;
                    foreach (var p in particles)
                    {
                        l += (double)p.Position.Z * p.Velocity.X - (double)p.Position.X * p.Velocity.Z;
                        inertia += (double)p.Position.X * p.Position.X + (double)p.Position.Z * p.Position.Z;
                    }
                    if (frame == frames) return (half, l / (inertia * Omega));
                    half = l / (inertia * Omega);
                }
            }
            throw new InvalidOperationException("unreachable");
        }

        /// <summary>Two frames on the validated device: the turning walls' kernels (DFSPH's WallMovedDensityFactor) in this
        /// scene's variant must also run under the validation layer (GpuTestDevice).</summary>
        [Test]
        public void TheTurningBoxRunsUnderTheValidationLayer()
        {
            var (_, end) = SpinUp(ViscousStress.StrainRate, validated: true, frames: 2);
            Assert.That(end, Is.GreaterThan(0.0), "the walls drag the liquid round");
        }

        [Test]
        public void UnderTheStrainRatesStressTheLiquidTurnsWithItsBox()
        {
            var (half, end) = SpinUp(ViscousStress.StrainRate);
            var (morrisHalf, morrisEnd) = SpinUp(ViscousStress.Laplacian);
            TestContext.Progress.WriteLine($"spin-up of a 12 cm box half full of liquid at {Viscosity} Pa s, {_solver}: angular momentum over I Omega at " +
                $"{Seconds / 2} and {Seconds} s: strain rate {half:F4}, {end:F4}; Morris's {morrisHalf:F4}, {morrisEnd:F4}");
            Assert.That(end, Is.EqualTo(1.0).Within(0.003), "the strain rate's stress: rigid rotation with the box");
            Assert.That(morrisEnd, Is.LessThan(0.995), "Morris's force brakes the rotation at the free surface (the known limit)");
        }
    }
}
