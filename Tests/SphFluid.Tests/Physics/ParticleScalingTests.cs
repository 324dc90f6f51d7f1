using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// --particles-scale changes the resolution, not the fluid: the shipped OilAndWater scene, read as the headless
    /// runner reads it and scaled by 0.5, 1 and 2, holds the same mass and the same fluid volume. The mass is the GPU
    /// diagnostics' sum over the spawned particles; the volume is N times the derived particle volume (the phase's
    /// mass over its rest density), summed over the phases. Before, floor(L / s) points per axis lost 6 % of the mass
    /// at four times the particles and a different share at every scale.
    /// </summary>
    public sealed class ParticleScalingTests
    {
        static readonly double[] Scales = { 0.5, 1.0, 2.0 };
        readonly Dictionary<double, (int Count, double Mass, double Volume)> _measured = new Dictionary<double, (int, double, double)>();
        double _boxVolume, _boxMass;

        [OneTimeSetUp]
        public void SpawnAtEachScale()
        {
            var shipped = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            _boxVolume = shipped.SpawnBoxes.Sum(b => (double)b.Size.X * b.Size.Y * b.Size.Z);
            _boxMass = shipped.SpawnBoxes.Sum(b => (double)b.Size.X * b.Size.Y * b.Size.Z * b.Phase.RestDensity);
            foreach (double scale in Scales)
            {
                var description = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
                ParticleScaling.ScaleBy(description, scale);
                using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, description);
                var report = sim.ReadDiagnostics();
                double volume = 0;
                for (int k = 0; k < sim.PhaseRows.Count; k++)
                    volume += report.Phases[k].Count * (double)sim.PhaseRows[k].ParticleMass / sim.PhaseRows[k].RestDensity;
                _measured[scale] = (sim.ParticleCount, report.TotalMass, volume);
                TestContext.Progress.WriteLine($"OilAndWater x{scale}: s = {description.Settings.ParticleSpacing * 1000:F3} mm, N = {sim.ParticleCount}, " +
                    $"mass {report.TotalMass:F4} kg ({100 * (report.TotalMass / _boxMass - 1):+0.000;-0.000} % vs boxes {_boxMass:F4} kg), " +
                    $"volume {volume * 1e3:F5} L ({100 * (volume / _boxVolume - 1):+0.000;-0.000} % vs boxes {_boxVolume * 1e3:F5} L)");
            }
        }

        [Test]
        public void TheScalesSpawnAboutHalfAndTwiceTheParticles()
        {
            Assert.That(_measured[0.5].Count / (double)_measured[1.0].Count, Is.EqualTo(0.5).Within(0.1));
            Assert.That(_measured[2.0].Count / (double)_measured[1.0].Count, Is.EqualTo(2.0).Within(0.2));
        }

        [TestCase(0.5)]
        [TestCase(2.0)]
        public void TheTotalMassIsTheSameWithinHalfAPerCent(double scale) =>
            Assert.That(_measured[scale].Mass, Is.EqualTo(_measured[1.0].Mass).Within(0.005 * _measured[1.0].Mass));

        [TestCase(0.5)]
        [TestCase(2.0)]
        public void TheFluidVolumeIsTheSameWithinTwoPerCent(double scale) =>
            Assert.That(_measured[scale].Volume, Is.EqualTo(_measured[1.0].Volume).Within(0.02 * _measured[1.0].Volume));

        [TestCase(0.5)]
        [TestCase(2.0)]
        [TestCase(8.0)]
        public void AnExplicitMassScalesWithTheParticleVolumeSoTheBoxKeepsItsMass(double scale)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            var oil = scene.SpawnBoxes[1];
            oil.Phase.ParticleMass = 1.1f * scene.BuildPhaseTable()[1].ParticleMass;
            double before = SpawnLayout.Count(scene.Settings, oil) * (double)oil.Phase.ParticleMass;

            ParticleScaling.ScaleBy(scene, scale);

            Assert.That(scene.Validate(), Is.Empty);
            double after = SpawnLayout.Count(scene.Settings, oil) * (double)scene.SpawnBoxes[1].Phase.ParticleMass;
            Assert.That(after, Is.EqualTo(before).Within(1e-4 * before));
            Assert.That(scene.BuildPhaseTable()[1].ParticleMass / DerivedParticleMass.Of(scene, oil.Phase), Is.EqualTo(1.1).Within(1e-5));
        }

        [TestCase(0.5)]
        [TestCase(1.0)]
        [TestCase(2.0)]
        public void EachScaleCarriesRestDensityTimesTheBoxVolumes(double scale) =>
            Assert.That(_measured[scale].Mass, Is.EqualTo(_boxMass).Within(0.005 * _boxMass));
    }
}
