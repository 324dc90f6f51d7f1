using System;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    public sealed class TimeStepControllerTests
    {
        static FluidSettings Settings() => new FluidSettings
        {
            SmoothingRadius = 0.04f, ParticleSpacing = 0.02f, Stiffness = 70000f, Gamma = 7f,
            CflNumber = 0.4f, MaxSubsteps = 10, MaxTimeStep = 0.005f,
        };

        [Test]
        public void SpeedOfSound_IsTait()
        {
            var c = new TimeStepController(Settings(), 1000f, 1e-6f);
            Assert.That(c.SpeedOfSound, Is.EqualTo((float)Math.Sqrt(70000.0 * 7 / 1000)).Within(1e-4f)); // 22.1 m/s
        }

        [Test]
        public void AtRest_CflLimits()
        {
            var c = new TimeStepController(Settings(), 1000f, 1e-6f);
            c.ReportMotion(0f, 0f);
            c.ReportMotion(0f, 0f);
            float dt = c.StableTimeStep(out string limit);
            Assert.That(limit, Is.EqualTo("cfl"));
            Assert.That(dt, Is.EqualTo(0.4f * 0.04f / c.SpeedOfSound).Within(1e-7f));
        }

        [Test]
        public void FastFluid_ShortensTheStep()
        {
            var c = new TimeStepController(Settings(), 1000f, 1e-6f);
            float rest = c.StableTimeStep();
            c.ReportMotion(20f, 0f);
            Assert.That(c.StableTimeStep(), Is.LessThan(rest * 0.6f));
        }

        [Test]
        public void LargeAcceleration_Limits()
        {
            var c = new TimeStepController(Settings(), 1000f, 1e-6f);
            c.ReportMotion(0f, 10000f);
            float dt = c.StableTimeStep(out string limit);
            Assert.That(limit, Is.EqualTo("acceleration"));
            Assert.That(dt, Is.EqualTo(0.25f * (float)Math.Sqrt(0.04 / 10000.0)).Within(1e-7f));
        }

        [Test]
        public void HighViscosity_SetsTheExplicitLimit()
        {
            var c = new TimeStepController(Settings(), 1000f, 1f); // nu = 1 m^2/s
            // The cubic spline at 2 spacings: Lambda_max s^2 = 5.82 (ViscousStepLimitTests), so 0.172 s^2 / nu.
            Assert.That(c.ViscousTimeStep, Is.EqualTo(1.0 / ViscousStepLimit.StiffestMode(KernelFamily.CubicSpline, 0.02, 0.04)).Within(1e-8));
            Assert.That(c.ViscousTimeStep, Is.EqualTo(0.172 * 0.02 * 0.02).Within(0.01 * c.ViscousTimeStep));
        }

        /// <summary>A sub-step beyond the explicit viscous limit solves the viscosity implicitly (<see cref="ImplicitViscosity"/>)
        /// under either solver, so the limit no longer shortens the step.</summary>
        [TestCase(PressureSolver.Wcsph)]
        [TestCase(PressureSolver.Dfsph)]
        public void HighViscosity_DoesNotLimitTheStep(PressureSolver solver)
        {
            var settings = Settings();
            settings.PressureSolver = solver;
            var c = new TimeStepController(settings, 1000f, 1f);
            float dt = c.StableTimeStep(out string limit);
            Assert.That(limit, Is.Not.EqualTo("viscous"));
            Assert.That(dt, Is.GreaterThan(10.0 * c.ViscousTimeStep));
            Assert.That(ImplicitViscosity.Needed(dt, c.ViscousTimeStep), Is.True);
        }

        [Test]
        public void StaleReport_IsUsedConservatively()
        {
            var c = new TimeStepController(Settings(), 1000f, 1e-6f);
            c.ReportMotion(10f, 0f);
            c.ReportMotion(1f, 0f); // the fluid slowed down, but the newer figure may be a frame stale
            Assert.That(c.MaxSpeed, Is.EqualTo(10f));
            c.ReportMotion(float.NaN, 0f);
            Assert.That(c.MaxSpeed, Is.EqualTo(10f), "a NaN report is ignored");
        }

        [Test]
        public void Frame_IsCoveredBySubstepsThatDivideIt()
        {
            var settings = Settings();
            settings.MaxSubsteps = 100;
            var c = new TimeStepController(settings, 1000f, 1e-6f);
            var report = c.PlanFrame(1f / 60f);
            Assert.That(report.Substeps, Is.EqualTo((int)Math.Ceiling((1.0 / 60.0) / c.StableTimeStep())));
            Assert.That(report.TimeStep * report.Substeps, Is.EqualTo(1f / 60f).Within(1e-6f));
            Assert.That(report.TimeStep, Is.LessThanOrEqualTo(c.StableTimeStep()));
            Assert.That(report.Capped, Is.False);
        }

        [Test]
        public void LongFrame_IsCappedAndRunsSlowerThanRealTime()
        {
            var c = new TimeStepController(Settings(), 1000f, 1e-6f);
            var report = c.PlanFrame(0.5f);
            Assert.That(report.Capped, Is.True);
            Assert.That(report.Substeps, Is.EqualTo(10));
            Assert.That(report.TimeStep, Is.EqualTo(c.StableTimeStep()));
            Assert.That(report.SimulatedSeconds, Is.LessThan(0.5f));
            Assert.That(report.ToString(), Does.Contain("slower than real time"));
        }

        [Test]
        public void ZeroFrame_NoSubsteps()
        {
            var c = new TimeStepController(Settings(), 1000f, 1e-6f);
            Assert.That(c.PlanFrame(0f).Substeps, Is.EqualTo(0));
            Assert.That(c.PlanFrame(float.NaN).Substeps, Is.EqualTo(0));
        }

        [Test]
        public void MaxTimeStep_Caps()
        {
            var s = Settings();
            s.Stiffness = 1f;
            var c = new TimeStepController(s, 1000f, 0f);
            float dt = c.StableTimeStep(out string limit);
            Assert.That(limit, Is.EqualTo("max"));
            Assert.That(dt, Is.EqualTo(0.005f));
        }
    
        [Test]
        public void SurfaceTension_AddsTheCapillaryLimit()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes[0].Phase.SurfaceTension = 10f;
            var c = TimeStepController.ForScene(scene);
            Assert.That(c.CapillaryTimeStep, Is.EqualTo((float)Math.Sqrt(1000 * 0.02 * 0.02 * 0.02 / (2 * Math.PI * 10))).Within(1e-7f)); // 11.3 ms
            Assert.That(TimeStepController.ForScene(SimulationTestScenes.SingleWater()).CapillaryTimeStep, Is.EqualTo(float.PositiveInfinity));

            var limited = new TimeStepController(Settings(), 1000f, 1e-6f, 1e-4f);
            Assert.That(limited.StableTimeStep(out string limit), Is.EqualTo(1e-4f));
            Assert.That(limit, Is.EqualTo("capillary"));
        }

        [Test]
        public void LightPhaseNextToAViscousOne_BoundsTheViscosityAcrossPhases()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[0].Phase.Viscosity = 10f;                              // water: nu = 0.01 m^2/s
            scene.SpawnBoxes[1].Phase = new PhaseDescription("Light", 100f, 1f);    // own nu = 0.01 m^2/s
            var c = TimeStepController.ForScene(scene);
            Assert.That(c.MaxKinematicViscosity, Is.EqualTo(2f * 1f / 100f).Within(1e-7f), "2 min(mu) / rho0 of the light phase");
        }
    }
}
