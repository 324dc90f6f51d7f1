using System.Linq;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>What choosing DFSPH changes outside the GPU: validation, the time step and the plan (issue #8).</summary>
    public sealed class PressureSolverChoiceTests
    {
        [Test]
        public void AnUndefinedSolverIsRefusedNamingTheFieldAndItsValues()
        {
            var settings = new FluidSettings { PressureSolver = (PressureSolver)7 };
            var errors = settings.Validate();
            Assert.That(errors.Select(e => e.Field), Has.Member("Settings.PressureSolver"));
            Assert.That(errors.Single(e => e.Field == "Settings.PressureSolver").Message,
                Is.EqualTo("FluidSettings: PressureSolver must be one of 0 (Wcsph), 1 (Dfsph) (was 7)"));
        }

        [Test]
        public void TheSpeedOfSoundRuleDoesNotConstrainADivergenceFreeScene()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.Settings.Stiffness = 10f; // c = 0.26 m/s: far below a fall through the tank
            Assert.That(scene.Validate().Select(e => e.Field), Has.Member("Settings.Gravity"));
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            Assert.That(scene.Validate(), Is.Empty);
        }

        static FluidSettings Settings(PressureSolver solver) => new FluidSettings
        {
            SmoothingRadius = 0.04f, ParticleSpacing = 0.02f, Stiffness = 70000f, Gamma = 7f,
            CflNumber = 0.4f, MaxSubsteps = 10, MaxTimeStep = 0.005f, PressureSolver = solver,
        };

        [Test]
        public void DivergenceFreeStep_IsTheVelocityCflWithoutTheSpeedOfSound()
        {
            var c = new TimeStepController(Settings(PressureSolver.Dfsph), 1000f, 1e-6f);
            c.ReportMotion(0f, 1000f);
            c.ReportMotion(0f, 1000f);
            Assert.That(c.StableTimeStep(out string limit), Is.EqualTo(0.005f), "at rest: MaxTimeStep, whatever the acceleration");
            Assert.That(limit, Is.EqualTo("max"));
            c.ReportMotion(8f, 1000f);
            Assert.That(c.StableTimeStep(out limit), Is.EqualTo(0.4f * 0.04f / 8f).Within(1e-7f));
            Assert.That(limit, Is.EqualTo("cfl"));
            var report = c.PlanFrame(1f / 60f);
            Assert.That(report.PressureSolver, Is.EqualTo(PressureSolver.Dfsph));
            Assert.That(report.ToString(), Does.EndWith(", DFSPH"));
        }

        /// <summary>A wall or obstacle faster than the fluid sets DFSPH's CFL (TimeStepController.BoundarySpeed): fluid at
        /// rest around a sphere started at 8 m/s would otherwise take MaxTimeStep, and the sphere would cross its
        /// neighbours within a sub-step. WCSPH's step keeps the speed of sound and is not changed by it.</summary>
        [Test]
        public void DivergenceFreeStep_TakesTheFastestWallIntoTheCfl()
        {
            var c = new TimeStepController(Settings(PressureSolver.Dfsph), 1000f, 1e-6f);
            c.ReportMotion(0.5f, 10f);
            c.BoundarySpeed = 8f;
            Assert.That(c.StableTimeStep(out string limit), Is.EqualTo(0.4f * 0.04f / 8f).Within(1e-7f));
            Assert.That(limit, Is.EqualTo("cfl"));
            var wcsph = new TimeStepController(Settings(PressureSolver.Wcsph), 1000f, 1e-6f);
            float before = wcsph.StableTimeStep();
            wcsph.BoundarySpeed = 8f;
            Assert.That(wcsph.StableTimeStep(), Is.EqualTo(before));
        }

        /// <summary>A fluid at rest under gravity plans DFSPH's step with its longest gravity wave, sqrt(g H), until it moves
        /// faster (TimeStepController.GravityWaveSpeed): at 4.17 ms OilAndWater's slice at 1M particles' spacing, 83
        /// spacings deep, reached 56 % compression in 0.05 s from rest, and was calm at 2.38 ms. WCSPH keeps the speed of
        /// sound, which is faster.</summary>
        [Test]
        public void DivergenceFreeStep_TakesTheGravityWaveIntoTheCfl()
        {
            var c = new TimeStepController(Settings(PressureSolver.Dfsph), 1000f, 1e-6f);
            c.GravityWaveSpeed = 4f;
            Assert.That(c.StableTimeStep(out string limit), Is.EqualTo(0.4f * 0.04f / 4f).Within(1e-7f));
            Assert.That(limit, Is.EqualTo("gravity wave"));
            c.ReportMotion(8f, 10f);
            Assert.That(c.StableTimeStep(out limit), Is.EqualTo(0.4f * 0.04f / 8f).Within(1e-7f));
            Assert.That(limit, Is.EqualTo("cfl"));
            var wcsph = new TimeStepController(Settings(PressureSolver.Wcsph), 1000f, 1e-6f);
            float before = wcsph.StableTimeStep();
            wcsph.GravityWaveSpeed = 4f;
            Assert.That(wcsph.StableTimeStep(), Is.EqualTo(before));
        }

        [Test]
        public void AContainersFastestWallIsItsCornerTurning()
        {
            var container = new ContainerDescription
            {
                Size = new System.Numerics.Vector3(0.6f, 0.8f, 0f), Velocity = new System.Numerics.Vector3(1f, 0f, 0f),
                AngularVelocity = new System.Numerics.Vector3(0f, 0f, 2f),
            };
            Assert.That(container.FastestWallSpeed, Is.EqualTo(1f + 2f * 0.5f).Within(1e-6f));
        }

        [Test]
        public void ThePlanDispatchesOnlyTheChosenSolversPasses()
        {
            var scene = SimulationTestScenes.OilOnWater();
            var wcsph = PipelinePlanner.Plan(scene, false);
            Assert.That(wcsph.SubstepPasses, Does.Contain(PassNames.Forces).And.Contain(PassNames.DensityPressure)
                .And.Not.Contain(PassNames.DensitySolve).And.Not.Contain(PassNames.FindNeighbours));
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            var dfsph = PipelinePlanner.Plan(scene, false);
            Assert.That(dfsph.PressureSolver, Is.EqualTo(PressureSolver.Dfsph));
            Assert.That(dfsph.SubstepPasses, Is.EqualTo(new[]
            {
                PassNames.NonPressureForces, PassNames.PredictVelocity, PassNames.DensitySolve, PassNames.Drift,
                PassNames.Sort, PassNames.FindNeighbours, PassNames.DensityFactor, PassNames.DivergenceSolve,
            }));
            Assert.That(dfsph.ToString(), Does.Contain("solver: DFSPH"));
        }

        /// <summary>A viscous liquid whose explicit limit falls below the step the scene may take gets the implicit viscosity
        /// solve: under DFSPH after its constant-density solve, under WCSPH after each half kick, with the half step split
        /// around it; a liquid whose limit the step cannot reach gets none.</summary>
        [Test]
        public void AViscousLiquidPlansTheViscositySolve()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            foreach (var box in scene.SpawnBoxes)
                if (box.Phase.Name == "Oil") box.Phase.Viscosity = 100f;
            var dfsph = PipelinePlanner.Plan(scene, false);
            Assert.That(dfsph.ImplicitViscosity, Is.True);
            Assert.That(dfsph.SubstepPasses[3], Is.EqualTo(PassNames.ViscositySolve));
            Assert.That(dfsph.ToString(), Does.Contain("viscosity: implicit"));
            scene.Settings.PressureSolver = PressureSolver.Wcsph;
            var wcsph = PipelinePlanner.Plan(scene, false);
            Assert.That(wcsph.ImplicitViscosity, Is.True);
            Assert.That(wcsph.SubstepPasses, Is.EqualTo(new[]
            {
                PassNames.HalfKick, PassNames.ViscositySolve, PassNames.HalfDrift, PassNames.Sort, PassNames.DensityPressure,
                PassNames.WallPressure, PassNames.Forces, PassNames.FullStep, PassNames.ViscositySolve,
            }));
            foreach (var box in scene.SpawnBoxes)
                box.Phase.Viscosity = 0.001f;
            var water = PipelinePlanner.Plan(scene, false);
            Assert.That(water.ImplicitViscosity, Is.False);
            Assert.That(water.SubstepPasses, Does.Not.Contain(PassNames.ViscositySolve).And.Contains(PassNames.HalfStep));
        }
    }
}
