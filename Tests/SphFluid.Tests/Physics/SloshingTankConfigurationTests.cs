using System;
using System.Linq;
using System.Reflection;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>The surface probes run by name, not in CI, so CI checks here that each of their fixtures names a
    /// configuration <see cref="SloshingTankConfiguration"/> knows, and that it changes what the name says.</summary>
    public sealed class SloshingTankConfigurationTests
    {
        static readonly Type[] Probes = { typeof(SurfaceSeicheProbe), typeof(SurfaceDispersionProbe), typeof(ViscousSeicheProbe) };

        const int SeicheFixtures = 20, DispersionFixtures = 15, ViscousFixtures = 45;

        [Test]
        public void EverySurfaceProbeFixtureNamesAKnownConfigurationTheSettingsAccept()
        {
            var names = Probes.SelectMany(p => p.GetCustomAttributes<TestFixtureAttribute>()).Select(f => (string)f.Arguments.Single()!).ToList();
            Assert.That(names, Has.Count.EqualTo(SeicheFixtures + DispersionFixtures + ViscousFixtures));
            foreach (var name in names)
            {
                FluidSceneDescription? scene = null;
                Assert.That(() => scene = SloshingTankConfiguration.Load(name), Throws.Nothing, name);
                // What the settings refuse (a kernel past 4 spacings) would otherwise surface only when the probe runs.
                Assert.That(scene!.Validate(), Is.Empty, name);
            }
        }

        [Test]
        public void AMistypedChangeIsRefusedByName()
        {
            Assert.That(() => SloshingTankConfiguration.Load("dfsph, narow"),
                Throws.ArgumentException.With.Message.Contains("no such change to the sloshing tank: narow"));
        }

        [Test]
        public void TheChangesAreApplied()
        {
            var shipped = SloshingTankConfiguration.Load("wcsph");
            var changed = SloshingTankConfiguration.Load("dfsph, support 3.5, narrow, half the spacing");
            Assert.That(changed.Settings.PressureSolver, Is.EqualTo(PressureSolver.Dfsph));
            Assert.That(changed.Container.Size.Z, Is.EqualTo(0.1f));
            Assert.That(changed.Settings.ParticleSpacing, Is.EqualTo(shipped.Settings.ParticleSpacing / 2).Within(1e-7));
            Assert.That(changed.Settings.SmoothingRadius / changed.Settings.ParticleSpacing, Is.EqualTo(3.5).Within(1e-5));

            var wcsph = SloshingTankConfiguration.Load("summation density, no artificial viscosity, no XSPH, stiffness x4");
            Assert.That(shipped.Settings.WcsphDensity, Is.EqualTo(WcsphDensity.DeltaSph));
            Assert.That(wcsph.Settings.WcsphDensity, Is.EqualTo(WcsphDensity.Summation));
            Assert.That(shipped.Settings.ArtificialViscosity, Is.GreaterThan(0f));
            Assert.That(wcsph.Settings.ArtificialViscosity, Is.EqualTo(0f));
            Assert.That(shipped.Settings.XsphEpsilon, Is.GreaterThan(0f));
            Assert.That(wcsph.Settings.XsphEpsilon, Is.EqualTo(0f));
            Assert.That(wcsph.Settings.Stiffness, Is.EqualTo(4 * shipped.Settings.Stiffness));

            var solves = SloshingTankConfiguration.Load("dfsph, loose solves, chebyshev, max step 0.5 ms");
            Assert.That(solves.Settings.DensityTolerance, Is.EqualTo(1f));
            Assert.That(solves.Settings.DivergenceTolerance, Is.EqualTo(100f));
            Assert.That(solves.Settings.SolverIteration, Is.EqualTo(SolverIteration.Chebyshev));
            Assert.That(solves.Settings.MaxTimeStep, Is.EqualTo(0.0005f).Within(1e-9));
            Assert.That(shipped.Settings.MaxTimeStep, Is.EqualTo(0.005f).Within(1e-9));
        }
    }
}
