using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Reference;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// The DFSPH kernels against the double-precision CPU reference (ReferenceSph.DivergenceFreeSubstep): one sub-step
    /// with one correction per solve (MaxSolverIterations = 1, no warm start yet) on a small compressed block with random
    /// velocities resting on the floor, so that the walls' boundary particles take part. The q each solve applied and the
    /// velocities and positions after the sub-step must match to 1e-4 of each quantity's scale. The two-phase block also takes
    /// a relaxed Jacobi step (SolverRelaxation 0.355, the cubic spline's 1 / lambda_max), so the constant reaches the kernels,
    /// and its boxes are 3.9 spacings tall, so their 4 rows stand for 2.5 % less than s^3 and the walls count at a rest number
    /// density other than the lattice's (PhaseProperties.WallWeightScale, SphBoundary.hlsl's WallWeight). A third block is
    /// squeezed to 75 % of its spacing, so that inside it a particle has more neighbours than its list holds and walks the
    /// grid (SphNeighbourhood.hlsl) while those at its edges read their lists: both paths in one solve. The laned cases
    /// walk each neighbourhood with 8 threads (NeighbourLanes.hlsl), which a GPU gives a small scene and lavapipe never
    /// chooses by itself: the factor, error and correction passes and the solve's indirect group counts with lanes.
    /// </summary>
    public sealed class DivergenceFreeKernelTests
    {
        const double Tolerance = 1e-4;

        internal static FluidSceneDescription Block(bool multiphase, bool chebyshev = false, bool sphere = false, float densityTolerance = 0.001f)
        {
            var settings = SolverScenes.Coarse(0.02f);
            settings.PressureSolver = PressureSolver.Dfsph;
            settings.MaxSolverIterations = chebyshev ? ChebyshevRounds : 1;
            if (chebyshev)
            {
                // The tightest tolerances, so that no solve stops before its last round (a looser density tolerance
                // still stops none in the squeezed block, whose compression is far above it).
                settings.SolverIteration = SolverIteration.Chebyshev;
                settings.DensityTolerance = densityTolerance;
                settings.DivergenceTolerance = 0.01f;
            }
            settings.XsphEpsilon = multiphase ? 0.3f : 0f;
            settings.SolverRelaxation = multiphase ? 0.355f : 1f;
            var size = new Vector3(0.16f, 0.16f, 0.16f);
            float height = multiphase ? 0.078f : 0.08f;
            var half = new Vector3(0.16f, height, 0.16f);
            var scene = SolverScenes.Scene(settings, size,
                SolverScenes.Box("A", SolverScenes.Water(0.1f), new Vector3(0f, -0.08f + 0.5f * height, 0f), half),
                SolverScenes.Box("B", multiphase ? SolverScenes.Oil(0.02f) : SolverScenes.Water(0.1f), new Vector3(0f, 0.08f - 0.5f * height, 0f), half));
            // Off the lattice's symmetry, clear of the squeezed particles (the spawn leaves half a spacing around it), and
            // 5 mm above the floor, so that its particles and the floor's reach each other (SphBoundary.hlsl's CountsInWallSum).
            if (sphere) scene.Obstacles = new List<RigidSphere> { new RigidSphere(new Vector3(0.013f, -0.04f, 0.009f), 0.035f, Vector3.Zero) };
            return scene;
        }

        /// <summary>Compressed to <paramref name="squeeze"/> of the spacing towards the floor's centre line and scattered, with
        /// random velocities: every solve has work, and the drift stays clear of the clamp (a discontinuity tested on its own).</summary>
        internal static Particle[] Compressed(FluidSceneDescription scene, int count, float squeeze, float drop = 0f, float sink = 0f)
        {
            var rng = new SolverScenes.Rng(4242);
            var spawn = SpawnLayout.Generate(scene);
            var particles = new Particle[count];
            for (int i = 0; i < count; i++)
            {
                var x = spawn[i].Position;
                x = new Vector3(squeeze * x.X, -0.08f - drop + squeeze * (x.Y + 0.08f), squeeze * x.Z) + rng.InBox(new Vector3(0.002f));
                particles[i] = new Particle(x, rng.InBox(new Vector3(0.3f)) - new Vector3(0f, sink, 0f), spawn[i].Phase, spawn[i].Id);
            }
            return particles;
        }

        [TestCase(false, 0.97f, 1, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_SinglePhase")]
        [TestCase(true, 0.97f, 1, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_TwoPhasesXsphRelaxed")]
        [TestCase(false, 0.75f, 1, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_CrowdedPastTheNeighbourLists")]
        [TestCase(true, 0.97f, 8, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_TwoPhasesEightLanes")]
        [TestCase(false, 0.75f, 8, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_CrowdedEightLanes")]
        public void OneIterationOfEachSolveMatchesReference(bool multiphase, float squeeze, int lanes) =>
            MatchesReference(Block(multiphase), multiphase, squeeze, lanes, 1);

        /// <summary>A sphere's wall particles as unknowns: their own shells count at rest (BoundarySampling.OwnNumberDensities),
        /// the container's walls and the fluid are summed.</summary>
        [TestCase(1, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_AroundASphere")]
        [TestCase(8, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_AroundASphereEightLanes")]
        public void OneIterationAroundASphereMatchesReference(int lanes) =>
            MatchesReference(Block(false, sphere: true), false, 0.97f, lanes, 1);

        /// <summary>The block at its spacing, lowered by 0.3 spacings and sinking at 0.5 m/s: its bottom row starts within a
        /// quarter spacing of the floor (0.2 of a spacing), partly above rest density, where the drift's wall contact acts
        /// whatever the density (DivergenceFreeSolver.hlsl's DIVERGENCE_CONTACT_GAP).</summary>
        [TestCase(1, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_WithinTheContactGap")]
        [TestCase(8, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_WithinTheContactGapEightLanes")]
        public void WithinTheContactGapMatchesReference(int lanes)
        {
            var scene = Block(false);
            float spacing = scene.Settings.ParticleSpacing;
            MatchesReference(scene, false, 1f, lanes, 1, drop: 0.3f * spacing, sink: 0.5f);
        }

        /// <summary>Two particles at one place: a pair without a direction takes one from the particles' ids
        /// (SphPressureForce.hlsl's PairDirection), which the correction reads for such a pair only, since it takes its
        /// neighbours' positions from the solve's own buffer (_SolverParticles) rather than from the particles.</summary>
        [TestCase(1, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_TwoParticlesAtOnePlace")]
        [TestCase(8, TestName = "Dfsph_OneIterationOfEachSolveMatchesReference_TwoParticlesAtOnePlaceEightLanes")]
        public void TwoParticlesAtOnePlaceMatchReference(int lanes) =>
            MatchesReference(Block(false), false, 0.97f, lanes, 1, atOnePlace: true);

        /// <summary>Three rounds: the first takes d_0 = z_0 / theta, the next two carry the last step (beta_k d_{k-1}), and
        /// the projection keeps each particle's summed q at or above zero (DivergenceFreeSolver.hlsl's Chebyshev acceleration).</summary>
        const int ChebyshevRounds = 3;

        /// <summary>At a density tolerance of 0.5 %, past the crossover for the block's 8 spacings
        /// (ChebyshevBounds.AcceleratesDensitySolve), the constant-density solve takes the Jacobi steps while the
        /// divergence-free solve is accelerated.</summary>
        [TestCase(true, 0.97f, 1, 0.001f, TestName = "Dfsph_ThreeChebyshevRoundsOfEachSolveMatchReference_TwoPhasesXsphRelaxed")]
        [TestCase(false, 0.75f, 8, 0.001f, TestName = "Dfsph_ThreeChebyshevRoundsOfEachSolveMatchReference_CrowdedEightLanes")]
        [TestCase(false, 0.75f, 1, 0.5f, TestName = "Dfsph_ThreeChebyshevRoundsOfEachSolveMatchReference_CrowdedJacobiConstantDensity")]
        public void ThreeChebyshevRoundsOfEachSolveMatchReference(bool multiphase, float squeeze, int lanes, float densityTolerance)
        {
            var scene = Block(multiphase, chebyshev: true, densityTolerance: densityTolerance);
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, scene))
            {
                Assert.That(sim.SolveRounds, Is.EqualTo(new[] { ChebyshevRounds, ChebyshevRounds }), "every round is recorded");
                Assert.That(sim.AcceleratesDensitySolve, Is.EqualTo(densityTolerance < 0.1f), "the constant-density solve's steps");
            }
            MatchesReference(scene, multiphase, squeeze, lanes, ChebyshevRounds);
        }

        static void MatchesReference(FluidSceneDescription scene, bool multiphase, float squeeze, int lanes, int iterations,
            float drop = 0f, float sink = 0f, bool atOnePlace = false)
        {
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene) { LanesPerParticle = lanes };
            Assert.That(sim.PhaseRows[0].WallWeightScale, multiphase ? Is.EqualTo(0.08 / 0.078).Within(1e-4) : Is.EqualTo(1.0).Within(1e-6));
            var input = Compressed(scene, sim.ParticleCount, squeeze, drop, sink);
            if (atOnePlace)
                input[6].Position = input[5].Position; // ids above 0, so that a direction signed by a lost id (0) differs
            sim.SetParticles(input);
            var counts = new uint[sim.ParticleCount + sim.BoundaryCount];
            sim.NeighbourCounts.GetData(counts);
            int walking = 0;
            for (int i = 0; i < sim.ParticleCount; i++) if (counts[i] == uint.MaxValue) walking++;
            TestContext.Progress.WriteLine($"squeezed to {squeeze}: {walking} of {sim.ParticleCount} particles have more neighbours than the {sim.NeighbourListCapacity} entries of a list");
            if (squeeze < 0.9f)
                Assert.That(walking, Is.GreaterThan(0).And.LessThan(sim.ParticleCount), "some particles walk the grid, the others read their lists");
            else
                Assert.That(walking, Is.EqualTo(0), "every particle reads its list");
            var before = GpuState.Read(sim);
            var start = before.ByIdParticles(input);
            const float dt = 0.001f;
            var expected = new ReferenceSph(scene).DivergenceFreeSubstep(start, dt, sim.Plan.Xsph, iterations, out var densityQ, out var divergenceQ, out var wallQ);

            sim.StepFixed(1, dt);
            var after = GpuState.Read(sim);
            var byId = after.IndexById();
            var warm = new Vector2[sim.ParticleCount];
            sim.WarmStart.GetData(warm);
            int n = input.Length;
            Assert.That(ReferenceComparison.Max(n, i => densityQ[i]), Is.GreaterThan(0.0), "the constant-density solve must have work");
            Assert.That(ReferenceComparison.Max(n, i => divergenceQ[i]), Is.GreaterThan(0.0), "the divergence-free solve must have work");
            Assert.That(ReferenceComparison.Max(wallQ.Length, b => wallQ[b]), Is.GreaterThan(0.0), "the wall particles must push too");
            if (scene.Obstacles.Count > 0)
            {
                var owners = BoundarySampling.Sample(scene);
                Assert.That(ReferenceComparison.Max(wallQ.Length, b => owners[b].Owner == 0u ? wallQ[b] : 0.0), Is.GreaterThan(0.0),
                    "the sphere's particles must push too");
            }
            ReferenceComparison.Compare("constant-density q", Tolerance, n, i => densityQ[i], i => warm[i].X);
            ReferenceComparison.Compare("divergence-free q", Tolerance, n, i => divergenceQ[i], i => warm[i].Y);
            ReferenceComparison.CompareVectors("displacement", Tolerance, n, i => new Double3(expected[i].Position) - new Double3(start[i].Position),
                i => new Double3(after.Particles[byId[i]].Position) - new Double3(start[i].Position));
            ReferenceComparison.CompareVectors("velocity", Tolerance, n, i => new Double3(expected[i].Velocity), i => new Double3(after.Particles[byId[i]].Velocity));
        }
    }
}
