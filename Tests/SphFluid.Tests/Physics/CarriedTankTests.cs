using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// Galilean invariance with moving walls: the resting tank of <see cref="DivergenceFreeTankTests"/>, carried sideways at
    /// 0.5 m/s with its water moving along from spawn, must stay at rest in the container's frame as the same tank does
    /// in a container at rest. The container is pushed every frame (as the Unity component pushes its transform), so the
    /// walls are placed and sorted again every frame, and the grid must follow the container.
    /// <para>
    /// Measured after half a second on lavapipe, in the container's frame, against the same tank at rest: with the walls
    /// placed once per frame and the grid left where the container spawned, WCSPH's carried tank surged (kinetic energy
    /// 3.67 J against 0.0051 J at rest, its fastest particle at 2.3 m/s, 5 clamp hits, compressed 0.858 % against 0.282 %,
    /// the column 6.3 % above its spawned height) and DFSPH's held 7 times the energy at rest (0.136 J against 0.0193 J),
    /// was compressed 0.191 % against 0.094 % and stood 1.63 % high. With the walls carried through the sub-steps and the
    /// grid following the container: WCSPH 0.0061 J, 0.289 %, 0.35 % low (0.36 % at rest); DFSPH 0.0232 J, 0.089 %,
    /// 0.38 % low (0.37 % at rest).
    /// </para>
    /// </summary>
    [TestFixture(PressureSolver.Dfsph)]
    [TestFixture(PressureSolver.Wcsph)]
    public sealed class CarriedTankTests
    {
        const float Spacing = 0.025f, Speed = 0.5f;
        const double Seconds = 0.5;
        readonly PressureSolver _solver;
        Carried _rest, _carried;

        public CarriedTankTests(PressureSolver solver) => _solver = solver;

        sealed record Carried(double KineticEnergy, double Compression, double Height, double Spawned, DiagnosticsReport Report);

        [OneTimeSetUp]
        public void CarryHalfASecond()
        {
            _rest = Run(Vector3.Zero);
            _carried = Run(new Vector3(Speed, 0f, 0f));
        }

        Carried Run(Vector3 velocity)
        {
            var scene = RestingTankTests.Tank(Spacing);
            scene.Settings.PressureSolver = _solver;
            scene.Settings.DensityTolerance = 0.1f;
            foreach (var box in scene.SpawnBoxes) box.InitialVelocity = velocity;
            var container = scene.Container.Clone();
            float floor = container.Position.Y - 0.5f * container.Size.Y;
            var start = container.Position;
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            double spawned = TankMeasures.ColumnHeight(particles, floor);
            while (sim.SimulatedTime < Seconds - 1e-6)
            {
                container.Position = start + velocity * (float)(sim.SimulatedTime + 1.0 / 60.0); // where the frame ends
                container.Velocity = velocity;
                sim.UpdateContainer(container);
                sim.Step(1f / 60f);
            }
            sim.Particles.GetData(particles);
            double kinetic = 0;
            foreach (var p in particles) kinetic += 0.5 * sim.PhaseRows[(int)p.Phase].ParticleMass * (p.Velocity - velocity).LengthSquared();
            var report = sim.ReadDiagnostics();
            var result = new Carried(kinetic, report.Phases[0].AverageDensityError, TankMeasures.ColumnHeight(particles, floor), spawned, report);
            TestContext.Progress.WriteLine($"{_solver} tank carried at {velocity.X} m/s, N={sim.ParticleCount}: kinetic energy in the container's frame " +
                $"{result.KineticEnergy:G3} J, average compression {100 * result.Compression:F4} %, column {result.Height:F4} m at {Seconds} s " +
                $"({100 * (result.Height / spawned - 1):F2} % of its spawned {spawned:F4} m); {report}");
            return result;
        }

        /// <summary>An exactly Galilean-invariant scheme would match the tank at rest to rounding. The carried tank's walls are
        /// sorted again every sub-step on a grid that moves, which changes the order of the sums, and under DFSPH they start
        /// their solves without a warm start (kept per sorted slot, it is cleared by every re-sort): the residual motion of a
        /// resting tank, itself chaotic, may differ by a small factor (1.2 measured for both solvers), not by the 7 and 730
        /// measured with the walls placed once per frame.</summary>
        [Test]
        public void TheCarriedTankMovesLittleMoreThanTheTankAtRestInItsFrame() =>
            Assert.That(_carried.KineticEnergy, Is.LessThanOrEqualTo(5.0 * _rest.KineticEnergy), $"at rest {_rest.KineticEnergy:G3} J");

        [Test]
        public void TheCarriedTankIsCompressedNoMoreThanTheTankAtRest() =>
            Assert.That(_carried.Compression, Is.LessThanOrEqualTo(1.5 * _rest.Compression), $"at rest {100 * _rest.Compression:F4} %");

        /// <summary>The resting tank's bar (RestingTankTests), for the carried column.</summary>
        [Test]
        public void TheCarriedColumnKeepsItsSpawnedHeightWithinOnePercent() =>
            Assert.That(_carried.Height, Is.EqualTo(_carried.Spawned).Within(0.01 * _carried.Spawned));

        [Test]
        public void NothingIsLostOrClamped()
        {
            Assert.That(_carried.Report.NanCount, Is.EqualTo(0));
            Assert.That(_carried.Report.OutsideCount, Is.EqualTo(0));
            Assert.That(_carried.Report.ClampHits, Is.EqualTo(0));
        }
    }
}
