using System;
using System.Globalization;
using System.Linq;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// What the viscous force does to a wave. The sloshing tank of <see cref="SurfaceSeicheTests"/> with free-slip walls
    /// has no Stokes layer, so a Newtonian liquid's viscosity damps its standing wave through the potential flow's
    /// strain, at 2 nu k^2 at any depth to first order in nu k^2 / omega (Lamb, "Hydrodynamics", art. 348;
    /// <c>SurfaceSeiche.DecayRate</c> without walls), and through the vortical layer its free surface needs, which Lamb's
    /// exact linear wave adds (art. 349; <see cref="SurfaceSeiche.ViscousMode"/>): at the probe's 20 Pa s that wave
    /// decays at 0.72 of 2 nu k^2 and swings 7.3 % slower. The tank runs twice, its water at water's viscosity and at
    /// the viscous run's (20 Pa s, or the fixture's "V Pa s"), and the difference of the two fitted decays, the
    /// viscosity's own share, is printed against that difference in both theories, with how much slower the viscous run
    /// swings. A viscous force that sums mu |grad v|^2, as Morris's pair term does, dissipates half what the stress
    /// mu (grad v + grad v^T) does in a potential flow, whose velocity gradient is symmetric; the strain rate's stress
    /// (the "strain rate" fixtures) more; the "viscous step F" fixtures run both tanks at the same sub-steps, at most F
    /// times the viscous run's explicit limit; the fixtures that name the difference first (the viscosity, the swing,
    /// the kernel's reach; WCSPH's density, artificial viscosity, XSPH, kernel and stiffness; DFSPH's kernel, step and
    /// tolerances) ask why WCSPH's share stays short and whether DFSPH's own damping adds to the viscosity's
    /// (Headless/docs/physics.md, "A viscous liquid's wave, against Lamb's exact wave"). A measurement (about an hour
    /// and a quarter of lavapipe), run by name:
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
    [TestFixture("5 Pa s, no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("10 Pa s, no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("40 Pa s, no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("5 Pa s, no artificial viscosity, no XSPH, free-slip, narrow")]
    [TestFixture("10 Pa s, no artificial viscosity, no XSPH, free-slip, narrow")]
    [TestFixture("40 Pa s, no artificial viscosity, no XSPH, free-slip, narrow")]
    [TestFixture("half the spacing, 5 Pa s, no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("half swing, half the spacing, no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("support 4, no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("support 4, no artificial viscosity, no XSPH, free-slip, narrow")]
    [TestFixture("support 3.4, no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    [TestFixture("half the spacing, support 3.4, no artificial viscosity, no XSPH, free-slip, narrow, strain rate")]
    public sealed class ViscousSeicheProbe
    {
        /// <summary>Pa s, unless the fixture names its own ("V Pa s"): nu = 0.02 m^2/s, 2 nu k^2 = 2.5/s against the
        /// wave's 8.7 rad/s, so it still swings.</summary>
        const float Viscous = 20f;

        readonly string _configuration;

        public ViscousSeicheProbe(string configuration) => _configuration = configuration;

        [Test]
        public void TheViscositysShareOfTheDecayAgainstLambsViscousWave()
        {
            Assert.That(Measure(_configuration).ViscousRun.Report.NanCount, Is.EqualTo(0));
        }

        /// <summary>The viscosity's share of the decay, /s (the viscous run's fitted decay less the still run's), and the same
        /// difference by the energy method (2 nu k^2) and by Lamb's exact wave.</summary>
        internal sealed record Share(double Measured, double FirstOrder, double Exact, SurfaceSeicheTests.Slosh ViscousRun)
        {
            public double OfLambsWave => Measured / Exact;
        }

        /// <summary>Runs the named configuration's still and viscous tanks and prints the viscosity's share of the decay.</summary>
        internal static Share Measure(string configuration)
        {
            var named = SloshingTankConfiguration.Parts(configuration).Select(p => SloshingTankConfiguration.ProbeViscosity.Match(p)).FirstOrDefault(m => m.Success);
            float viscous = named != null ? float.Parse(named.Groups[1].Value, CultureInfo.InvariantCulture) : Viscous;
            var (still, stillMode, _) = Slosh(configuration, viscous, null);
            var (run, mode, largestStep) = Slosh(configuration, viscous, viscous);
            var share = new Share(run.MeasuredDecay - still.MeasuredDecay, run.Decay - still.Decay, mode.Gamma - stillMode.Gamma, run);
            double slower = run.MeasuredPeriod / still.MeasuredPeriod - 1, slowerInTheory = stillMode.Omega / mode.Omega - 1;
            TestContext.Progress.WriteLine($"RestingTank ({configuration}) at {viscous} Pa s, largest sub-step {1000 * largestStep:F3} ms ({1000 * (1.0 / 60) / Math.Ceiling(1.0 / 60 / largestStep):F2} ms in 60 Hz frames): the viscosity's share of the decay " +
                $"{share.Measured:F3}/s ({run.MeasuredDecay:F3} less {still.MeasuredDecay:F3}), 2 nu k^2 {share.FirstOrder:F3}/s: {share.Measured / share.FirstOrder:F2} of it; " +
                $"Lamb's viscous wave {share.Exact:F3}/s: {share.OfLambsWave:F2} of it; the viscous run's period {100 * slower:+0.00;-0.00} % past the still run's, " +
                $"Lamb's wave's {100 * slowerInTheory:+0.00;-0.00} %");
            return share;
        }

        /// <summary>The run at <paramref name="viscosity"/> Pa s (water's if null), the exact linear mode
        /// (<see cref="SurfaceSeiche.ViscousMode"/>) of its tank and measured depth, and its largest sub-step.</summary>
        static (SurfaceSeicheTests.Slosh Run, (double Gamma, double Omega) Mode, float LargestStep) Slosh(string configuration, float viscousRun, float? viscosity)
        {
            var scene = SloshingTankConfiguration.Load(configuration);
            var step = SloshingTankConfiguration.Parts(configuration).Select(p => SloshingTankConfiguration.ViscousStep.Match(p)).FirstOrDefault(m => m.Success);
            if (step != null)
            {
                // Both runs at most F times the viscous run's explicit limit (the frame's sub-steps are equal and no
                // longer), so that the method's own damping, which follows DFSPH's step, is the same in both: below 1 the
                // viscosity is explicit, above it the implicit solve's.
                var viscous = SloshingTankConfiguration.Load(configuration);
                viscous.SpawnBoxes.Single().Phase.Viscosity = viscousRun;
                double f = double.Parse(step.Groups[1].Value, CultureInfo.InvariantCulture);
                scene.Settings.MaxTimeStep = (float)(f * TimeStepController.ForScene(viscous).ViscousTimeStep);
            }
            var phase = scene.SpawnBoxes.Single().Phase;
            if (viscosity.HasValue) phase.Viscosity = viscosity.Value;
            double nu = phase.Viscosity / phase.RestDensity;
            // Two of the finer lattice's spacings, the same swing; "half swing" tilts the finer lattice by one, to show
            // whether the linear theory holds at the probe's swing (k a = 0.2).
            bool halfSwing = SloshingTankConfiguration.Parts(configuration).Contains("half swing");
            if (halfSwing && !SloshingTankConfiguration.HalvesTheSpacing(configuration))
                throw new ArgumentException($"'{configuration}': a half swing is one spacing of the finer lattice, so it needs \"half the spacing\"");
            SurfaceSeicheTests.TiltSurface(scene, (SloshingTankConfiguration.HalvesTheSpacing(configuration) ? 2 : 1) / (halfSwing ? 2 : 1));
            var run = SurfaceSeicheTests.Run(scene, $"RestingTank ({configuration}), {(viscosity.HasValue ? $"{viscosity} Pa s" : "water")}", 1.5,
                highestDecay: 10);
            return (run, SurfaceSeiche.ViscousMode(scene.Container.Size.X, run.Depth, scene.Settings.Gravity.Length(), nu), scene.Settings.MaxTimeStep);
        }
    }
}
