using System;
using System.Globalization;
using System.Linq;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// What the viscous force does to a wave. The sloshing tank of <see cref="SurfaceSeicheTests"/> with free-slip walls
    /// has no Stokes layer, so a Newtonian liquid's viscosity damps its standing wave only through the potential flow's
    /// strain, at 2 nu k^2 at any depth (Lamb, "Hydrodynamics", art. 348; <c>SurfaceSeiche.DecayRate</c> without walls).
    /// The tank runs twice, its water at water's viscosity and at <see cref="Viscous"/> Pa s, and the difference of the
    /// two fitted decays, the viscosity's own share, is printed against that difference in theory. A viscous force that
    /// sums mu |grad v|^2, as Morris's pair term does, dissipates at most half what the stress mu (grad v + grad v^T)
    /// does in a potential flow, whose velocity gradient is symmetric: Morris's Laplacian shows 0.32 to 0.45 of it, the
    /// strain rate's stress (the "strain rate" fixtures) more; the "viscous step F" fixtures run both tanks at the same
    /// sub-steps, at most F times the viscous run's explicit limit; the fixtures that name the difference first (WCSPH's
    /// density, artificial viscosity, XSPH, kernel and stiffness; DFSPH's kernel, step and tolerances) ask why WCSPH's
    /// share stays near half and whether DFSPH's own damping adds to the viscosity's (Headless/docs/physics.md, "A
    /// viscous liquid's wave, against Lamb's 2 nu k^2"). A measurement (about 48 minutes of lavapipe), run by name:
    /// <c>bash Headless/test.sh --filter FullyQualifiedName~ViscousSeicheProbe</c>; a fixture's own words join the
    /// filter without their spaces, e.g. <c>"FullyQualifiedName~ViscousSeicheProbe&amp;FullyQualifiedName~tight"</c>.
    /// </summary>
    [Explicit("a measurement, not a check: run it by name")]
    [TestFixture("dfsph, free-slip")]
    [TestFixture("free-slip")]
    [TestFixture("dfsph, free-slip, narrow")]
    [TestFixture("dfsph, free-slip, narrow, half the spacing")]
    [TestFixture("free-slip, narrow")]
    [TestFixture("free-slip, narrow, half the spacing")]
    [TestFixture("dfsph, free-slip, strain rate")]
    [TestFixture("free-slip, strain rate")]
    [TestFixture("dfsph, free-slip, narrow, strain rate")]
    [TestFixture("dfsph, free-slip, narrow, strain rate, half the spacing")]
    [TestFixture("free-slip, narrow, strain rate")]
    [TestFixture("free-slip, narrow, strain rate, half the spacing")]
    [TestFixture("viscous step 0.999, dfsph, free-slip, narrow")]
    [TestFixture("viscous step 1.6, dfsph, free-slip, narrow")]
    [TestFixture("viscous step 0.999, dfsph, free-slip, narrow, strain rate")]
    [TestFixture("summation density, free-slip, narrow, strain rate")]
    [TestFixture("summation density, free-slip, narrow")]
    [TestFixture("no artificial viscosity, free-slip, narrow, strain rate")]
    [TestFixture("no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("cubic spline, free-slip, narrow, strain rate")]
    [TestFixture("stiffness x4, free-slip, narrow, strain rate")]
    [TestFixture("stiffness x16, free-slip, narrow, strain rate")]
    [TestFixture("stiffness x16, no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("no artificial viscosity, no XSPH, free-slip, narrow")]
    [TestFixture("viscous step 0.38, no artificial viscosity, no XSPH, free-slip, narrow")]
    [TestFixture("half the spacing, viscous step 0.38, no artificial viscosity, no XSPH, free-slip, narrow")]
    [TestFixture("half the spacing, no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("cubic spline, free-slip, narrow")]
    [TestFixture("Wendland C2 relaxed, viscous step 0.999, dfsph, free-slip, narrow, strain rate")]
    [TestFixture("viscous step 0.45, dfsph, free-slip, narrow, strain rate")]
    [TestFixture("tight solves, viscous step 0.999, dfsph, free-slip, narrow, strain rate")]
    [TestFixture("tight solves, viscous step 0.999, dfsph, free-slip, narrow")]
    public sealed class ViscousSeicheProbe
    {
        /// <summary>Pa s: nu = 0.02 m^2/s, 2 nu k^2 = 2.5/s against the wave's 8.7 rad/s, so it still swings.</summary>
        const float Viscous = 20f;

        readonly string _configuration;
        float _largestStep;

        public ViscousSeicheProbe(string configuration) => _configuration = configuration;

        [Test]
        public void TheViscositysShareOfTheDecayAgainstTwiceNuKSquared()
        {
            var still = Slosh(null);
            var viscous = Slosh(Viscous);
            double measured = viscous.MeasuredDecay - still.MeasuredDecay, theory = viscous.Decay - still.Decay;
            TestContext.Progress.WriteLine($"RestingTank ({_configuration}) at {Viscous} Pa s, largest sub-step {1000 * _largestStep:F3} ms ({1000 * (1.0 / 60) / Math.Ceiling(1.0 / 60 / _largestStep):F2} ms in 60 Hz frames): the viscosity's share of the decay " +
                $"{measured:F3}/s ({viscous.MeasuredDecay:F3} less {still.MeasuredDecay:F3}), 2 nu k^2 {theory:F3}/s: {measured / theory:F2} of it");
            Assert.That(viscous.Report.NanCount, Is.EqualTo(0));
        }

        SurfaceSeicheTests.Slosh Slosh(float? viscosity)
        {
            var scene = SloshingTankConfiguration.Load(_configuration);
            var step = _configuration.Split(',').Select(p => SloshingTankConfiguration.ViscousStep.Match(p.Trim())).FirstOrDefault(m => m.Success);
            if (step != null)
            {
                // Both runs at most F times the viscous run's explicit limit (the frame's sub-steps are equal and no
                // longer), so that the method's own damping, which follows DFSPH's step, is the same in both: below 1 the
                // viscosity is explicit, above it the implicit solve's.
                var viscous = SloshingTankConfiguration.Load(_configuration);
                viscous.SpawnBoxes.Single().Phase.Viscosity = Viscous;
                double f = double.Parse(step.Groups[1].Value, CultureInfo.InvariantCulture);
                scene.Settings.MaxTimeStep = (float)(f * TimeStepController.ForScene(viscous).ViscousTimeStep);
            }
            if (viscosity.HasValue) scene.SpawnBoxes.Single().Phase.Viscosity = viscosity.Value;
            _largestStep = scene.Settings.MaxTimeStep;
            // Two of the finer lattice's spacings, the same swing.
            SurfaceSeicheTests.TiltSurface(scene, SloshingTankConfiguration.HalvesTheSpacing(_configuration) ? 2 : 1);
            return SurfaceSeicheTests.Run(scene, $"RestingTank ({_configuration}), {(viscosity.HasValue ? $"{viscosity} Pa s" : "water")}", 1.5,
                highestDecay: 10);
        }
    }
}
