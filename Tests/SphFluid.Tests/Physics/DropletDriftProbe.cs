using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// Whether the surface force keeps a droplet where it is: the 1 000-particle droplet of <see cref="LaplaceDroplets"/>
    /// (the cubic spline at 2 spacings of 5 mm, sigma 1 N/m, 2e-3 m^2/s, no gravity) at three rest densities. Nothing
    /// outside pushes it, so its centre should stay put, its kinetic energy fall as its rounding rings down, and a ball
    /// (as far along a diagonal from its centre as along an axis) should be what it rounds to. Prints every 0.3 s the
    /// droplet's speed (its members' mean velocity: <see cref="LaplaceDroplets.Ball"/>), how far it moved, the share of
    /// the kinetic energy that speed carries, the particles it shed, and its reach along the axes and the diagonals. A
    /// measurement (two minutes of lavapipe for the three), run by name:
    /// <c>bash Headless/test.sh --filter FullyQualifiedName~DropletDriftProbe</c>.
    /// </summary>
    [Explicit("a measurement, minutes of lavapipe")]
    [TestFixture(500f)]
    [TestFixture(1000f)]
    [TestFixture(2000f)]
    public sealed class DropletDriftProbe
    {
        const float Spacing = 0.005f;
        readonly float _restDensity;

        public DropletDriftProbe(float restDensity) => _restDensity = restDensity;

        [Test]
        public void TheDropletStaysWhereItIs()
        {
            var scene = LaplaceDroplets.Scene(KernelFamily.CubicSpline, 2f, Spacing, _restDensity, 1f, 10);
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            double mass = _restDensity * Spacing * Spacing * Spacing;
            var rows = new List<string>();
            Vector3 start = Vector3.Zero;
            for (int sample = 0; sample <= 5; sample++)
            {
                while (sim.SimulatedTime < 0.3 * sample - 1e-6) sim.Step(1f / 60f);
                sim.Particles.GetData(particles);
                var ball = LaplaceDroplets.Ball(particles, Spacing);
                if (sample == 0) start = ball.Centre;
                var (velocity, kinetic, carried) = LaplaceDroplets.Motion(particles, ball.Members, mass);
                double axis = 0, diagonal = 0;
                foreach (int i in ball.Members)
                {
                    var d = particles[i].Position - ball.Centre;
                    axis = Math.Max(axis, Math.Max(Math.Abs(d.X), Math.Max(Math.Abs(d.Y), Math.Abs(d.Z))));
                    foreach (var corner in Corners)
                        diagonal = Math.Max(diagonal, Vector3.Dot(d, corner));
                }
                rows.Add($"{sim.SimulatedTime:F1} s: {velocity.Length():F3} m/s, moved {(ball.Centre - start).Length() * 1000:F1} mm, " +
                    $"kinetic {kinetic * 1000:F3} mJ ({(kinetic > 0 ? carried / kinetic : 0):P0} the droplet's), " +
                    $"shed {particles.Length - ball.Members.Length}, " +
                    $"reach {axis * 1000:F1} mm along an axis and {diagonal * 1000:F1} along a diagonal");
            }
            TestContext.Progress.WriteLine($"droplet of {particles.Length} at rho0 {_restDensity} kg/m^3 (a ball of radius " +
                $"{Math.Cbrt(3 * particles.Length / (4 * Math.PI)) * Spacing * 1000:F1} mm):{Environment.NewLine}  " +
                string.Join(Environment.NewLine + "  ", rows));
        }

        static readonly Vector3[] Corners =
            (from x in new[] { -1f, 1f } from y in new[] { -1f, 1f } from z in new[] { -1f, 1f }
             select Vector3.Normalize(new Vector3(x, y, z))).ToArray();
    }
}
