using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    public sealed class PipelinePlannerTests
    {
        [Test]
        public void SinglePhase_NoMultiphaseVariant()
        {
            var plan = PipelinePlanner.Plan(SimulationTestScenes.SingleWater(), false);
            Assert.That(plan.Multiphase, Is.False);
            Assert.That(plan.Keywords, Has.No.Member(SolverKeywords.Multiphase));
        }

        [Test]
        public void TwoPhases_MultiphaseVariant()
        {
            var plan = PipelinePlanner.Plan(SimulationTestScenes.OilOnWater(), false);
            Assert.That(plan.PhaseCount, Is.EqualTo(2));
            Assert.That(plan.Keywords, Has.Member(SolverKeywords.Multiphase));
        }

        [Test]
        public void NoObstacles_NoObstaclePass()
        {
            var plan = PipelinePlanner.Plan(SimulationTestScenes.OilOnWater(), false);
            Assert.That(plan.FramePasses, Has.No.Member(PassNames.PlaceBoundary), "walls at rest are placed once, not every frame");
            Assert.That(plan.Keywords, Has.No.Member(SolverKeywords.Obstacles));
            var scene = SimulationTestScenes.OilOnWater();
            scene.Obstacles.Add(new RigidSphere(Vector3.Zero, 0.05f, Vector3.Zero));
            plan = PipelinePlanner.Plan(scene, false);
            Assert.That(plan.FramePasses, Has.Member(PassNames.PlaceBoundary), "moving spheres re-place their boundary particles");
            Assert.That(plan.Keywords, Has.Member(SolverKeywords.Obstacles));
        }

        [Test]
        public void ZeroTension_NoTensionOrNormalsPass()
        {
            var plan = PipelinePlanner.Plan(SimulationTestScenes.OilOnWater(), false);
            Assert.That(plan.SurfaceTension, Is.False);
            Assert.That(plan.SubstepPasses, Has.No.Member(PassNames.Normals));
            Assert.That(plan.Keywords, Has.No.Member(SolverKeywords.SurfaceTension));
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[1].Phase.SurfaceTension = 0.03f;
            plan = PipelinePlanner.Plan(scene, false);
            Assert.That(plan.SubstepPasses, Has.Member(PassNames.Normals));
            Assert.That(plan.Keywords, Has.Member(SolverKeywords.SurfaceTension));
        }

        [Test]
        public void ZeroXsph_NoXsphVariant()
        {
            var scene = SimulationTestScenes.OilOnWater();
            Assert.That(PipelinePlanner.Plan(scene, false).Keywords, Has.Member(SolverKeywords.Xsph));
            scene.Settings.XsphEpsilon = 0f;
            Assert.That(PipelinePlanner.Plan(scene, false).Keywords, Has.No.Member(SolverKeywords.Xsph));
        }

        [Test]
        public void ZeroShifting_NoShiftPasses()
        {
            var scene = SimulationTestScenes.OilOnWater();
            var plan = PipelinePlanner.Plan(scene, false);
            Assert.That(plan.Shifting, Is.False);
            Assert.That(plan.SubstepPasses, Has.No.Member(PassNames.ParticleShift).And.No.Member(PassNames.ApplyShift));
            scene.Settings.ParticleShifting = 2f;
            plan = PipelinePlanner.Plan(scene, false);
            Assert.That(plan.Shifting, Is.True);
            Assert.That(plan.SubstepPasses, Is.EqualTo(new[]
            {
                PassNames.HalfStep, PassNames.Sort, PassNames.DensityPressure, PassNames.WallPressure, PassNames.Forces,
                PassNames.FullStep, PassNames.ParticleShift, PassNames.ApplyShift,
            }));
        }

        /// <summary>The strain rate's viscous stress runs its Rotations pass before the forces, under either solver, and only
        /// where some phase is viscous.</summary>
        [Test]
        public void LaplacianOrInviscid_NoRotationsPass()
        {
            var scene = SimulationTestScenes.OilOnWater();
            var plan = PipelinePlanner.Plan(scene, false);
            Assert.That(plan.StrainRateViscosity, Is.False);
            Assert.That(plan.SubstepPasses, Has.No.Member(PassNames.Rotations));
            scene.Settings.ViscousStress = ViscousStress.StrainRate;
            plan = PipelinePlanner.Plan(scene, false);
            Assert.That(plan.StrainRateViscosity, Is.True);
            Assert.That(plan.SubstepPasses, Is.EqualTo(new[]
            {
                PassNames.HalfStep, PassNames.Sort, PassNames.DensityPressure, PassNames.WallPressure, PassNames.Rotations,
                PassNames.Forces, PassNames.FullStep,
            }));
            Assert.That(plan.ToString(), Does.Contain("viscous stress: strain rate"));
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            Assert.That(PipelinePlanner.Plan(scene, false).SubstepPasses.Take(2),
                Is.EqualTo(new[] { PassNames.Rotations, PassNames.NonPressureForces }));
            foreach (var box in scene.SpawnBoxes) box.Phase.Viscosity = 0f;
            plan = PipelinePlanner.Plan(scene, false);
            Assert.That(plan.StrainRateViscosity, Is.False, "no viscosity, no rotations");
            Assert.That(plan.SubstepPasses, Has.No.Member(PassNames.Rotations));
        }

        [Test]
        public void UnmovedContainer_NoTransformUpload()
        {
            var scene = SimulationTestScenes.OilOnWater();
            Assert.That(PipelinePlanner.Plan(scene, false).UploadContainerTransform, Is.False);
            Assert.That(PipelinePlanner.Plan(scene, false).FramePasses, Has.No.Member(PassNames.UploadContainer));
            Assert.That(PipelinePlanner.Plan(scene, true).FramePasses, Has.Member(PassNames.UploadContainer));
        }

        [Test]
        public void Passes_AreInPipelineOrder_AndToStringNamesThem()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[0].Phase.SurfaceTension = 0.07f;
            scene.Obstacles.Add(new RigidSphere(Vector3.Zero, 0.05f, Vector3.Zero));
            var plan = PipelinePlanner.Plan(scene, true);
            Assert.That(plan.SubstepPasses, Is.EqualTo(new[]
            {
                PassNames.HalfStep, PassNames.Sort, PassNames.DensityPressure, PassNames.WallPressure, PassNames.Normals,
                PassNames.Forces, PassNames.FullStep,
            }));
            string text = plan.ToString();
            Assert.That(text, Does.Contain("MULTIPHASE SURFACE_TENSION XSPH OBSTACLES"));
            Assert.That(text, Does.Contain("HalfStep > Sort > DensityPressure > WallPressure > Normals > Forces > FullStep"));
        }
    }
}
