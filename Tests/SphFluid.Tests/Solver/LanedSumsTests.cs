using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Reference;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// The laned neighbour loops (NeighbourLanes.hlsl): the same particles, stepped with 2 and 8 threads per particle, give
    /// the densities, accelerations, velocity corrections and delta-SPH rates of one thread per particle to 1e-5 of each
    /// quantity's scale, only the order of the sums differing. On lavapipe, a CPU device, the simulation takes one lane by
    /// itself (NeighbourLanes.For), so there every other GPU test checks the one-lane path against the reference; this one
    /// sets the lanes by hand. Under WCSPH one lane reads the neighbour lists and more lanes walk the grid
    /// (NeighbourCapacity.InUse), so the same comparison holds WCSPH's lists to the grid walk. The rule itself is tested in
    /// the package's Core tests (NeighbourLanesTests). Each laned kernel is covered: DensityPressure (summation), DensityRate
    /// and ContinuityDensity (delta-SPH), WallPressure and Forces (both), NonPressureForces (DFSPH), Normals and Rotations
    /// (tension and the strain rate's stress), ParticleShift (shifting), FindNeighbours (DFSPH's lists), Drift (DFSPH's wall
    /// contact); DFSPH's factor,
    /// error and correction passes are held to the double-precision reference with 8 lanes in DivergenceFreeKernelTests,
    /// and their stop decision here.
    /// </summary>
    public sealed class LanedSumsTests
    {
        const double Tolerance = 1e-5;

        [Test]
        public void TheDeviceChoosesTheLanesAndALaneCountIsChecked()
        {
            using var sim = new FluidSimulation(GpuTestDevice.Shared, SolverKernelTests.RandomScene(false, false, false, false));
            Assert.That(sim.LanesPerParticle, Is.EqualTo(NeighbourLanes.For(sim.ParticleCount, GpuTestDevice.Shared.RunsOnCpu)));
            var error = Assert.Throws<ArgumentOutOfRangeException>(() => sim.LanesPerParticle = 3);
            Assert.That(error!.Message, Does.Contain("lanes per particle must be 1, 2, 4 or 8"));
        }

        [TestCase(WcsphDensity.Summation, PressureSolver.Wcsph, 2, TestName = "LanedSums_Summation_TwoLanes")]
        [TestCase(WcsphDensity.Summation, PressureSolver.Wcsph, 8, TestName = "LanedSums_Summation_EightLanes")]
        [TestCase(WcsphDensity.DeltaSph, PressureSolver.Wcsph, 8, TestName = "LanedSums_DeltaSph_EightLanes")]
        [TestCase(WcsphDensity.Summation, PressureSolver.Dfsph, 8, TestName = "LanedSums_Dfsph_EightLanes")]
        public void LanesGiveTheSumsOfOneThread(WcsphDensity density, PressureSolver solver, int lanes)
        {
            var one = Forces(density, solver, 1, out var oneRates);
            var many = Forces(density, solver, lanes, out var manyRates);
            int n = one.Particles.Length;
            var oneById = one.IndexById();
            var manyById = many.IndexById();
            Assert.That(ReferenceComparison.Max(n, k => Math.Abs(one.Accelerations[oneById[k]].Y)), Is.GreaterThan(1.0), "the case must have forces");
            ReferenceComparison.Compare("density", Tolerance, n, k => one.Densities[oneById[k]].X, k => many.Densities[manyById[k]].X);
            ReferenceComparison.Compare("pressure", Tolerance, n, k => one.Densities[oneById[k]].W, k => many.Densities[manyById[k]].W);
            ReferenceComparison.CompareVectors("acceleration", Tolerance, n, k => Of(one.Accelerations[oneById[k]]), k => Of(many.Accelerations[manyById[k]]));
            ReferenceComparison.CompareVectors("velocity correction", Tolerance, n, k => Of(one.Corrections[oneById[k]]), k => Of(many.Corrections[manyById[k]]));
            if (density == WcsphDensity.DeltaSph)
            {
                ReferenceComparison.Compare("continuity term", Tolerance, n, k => oneRates[oneById[k]].X, k => manyRates[manyById[k]].X);
                ReferenceComparison.Compare("diffusion term", Tolerance, n, k => oneRates[oneById[k]].Y, k => manyRates[manyById[k]].Y);
            }
        }

        /// <summary>The passes that only some scenes run, laned as the others: the colour-field normals of surface tension and
        /// the rotations of the strain rate's viscous stress (both in Forces.hlsl), and the accelerations they feed, with 2
        /// and 8 lanes against one, under either solver.</summary>
        [TestCase(PressureSolver.Wcsph, 2, TestName = "LanedSums_NormalsAndRotations_TwoLanes")]
        [TestCase(PressureSolver.Wcsph, 8, TestName = "LanedSums_NormalsAndRotations_EightLanes")]
        [TestCase(PressureSolver.Dfsph, 8, TestName = "LanedSums_NormalsAndRotations_Dfsph_EightLanes")]
        public void LanesGiveTheNormalsAndRotationsOfOneThread(PressureSolver solver, int lanes)
        {
            var one = TensionAndStrainRate(solver, 1, out var oneNormals, out var oneRotations);
            var many = TensionAndStrainRate(solver, lanes, out var manyNormals, out var manyRotations);
            int n = one.Particles.Length;
            var oneById = one.IndexById();
            var manyById = many.IndexById();
            Assert.That(ReferenceComparison.Max(n, k => Of(oneNormals[oneById[k]]).Length()), Is.GreaterThan(0.1), "the case must have surfaces");
            Assert.That(ReferenceComparison.Max(n, k => Of(oneRotations[oneById[k]]).Length()), Is.GreaterThan(0.1), "the case must turn");
            ReferenceComparison.CompareVectors("normal", Tolerance, n, k => Of(oneNormals[oneById[k]]), k => Of(manyNormals[manyById[k]]));
            ReferenceComparison.CompareVectors("rotation", Tolerance, n, k => Of(oneRotations[oneById[k]]), k => Of(manyRotations[manyById[k]]));
            ReferenceComparison.CompareVectors("acceleration", Tolerance, n, k => Of(one.Accelerations[oneById[k]]), k => Of(many.Accelerations[manyById[k]]));
        }

        /// <summary>Particle shifting's pass (Shifting.hlsl), laned as the others: the two-phase blob with shifting at A = 0.5
        /// (DamBreak's effect) stepped once with 2 and 8 lanes, its shifts against one lane's.</summary>
        [TestCase(2, TestName = "LanedSums_Shifts_TwoLanes")]
        [TestCase(8, TestName = "LanedSums_Shifts_EightLanes")]
        public void LanesGiveTheShiftsOfOneThread(int lanes)
        {
            var one = Shifts(1, out var oneShifts);
            var many = Shifts(lanes, out var manyShifts);
            int n = one.Particles.Length;
            var oneById = one.IndexById();
            var manyById = many.IndexById();
            Assert.That(ReferenceComparison.Max(n, k => Of(oneShifts[oneById[k]]).Length()), Is.GreaterThan(1e-6), "the case must shift");
            ReferenceComparison.CompareVectors("shift", Tolerance, n, k => Of(oneShifts[oneById[k]]), k => Of(manyShifts[manyById[k]]));
        }

        /// <summary>DFSPH's drift (DivergenceFreeDrift.hlsl), laned for its wall contact: the noisy blob, whose particles are
        /// under-dense or crowd the walls, drifted once over 2 ms with 2 and 8 lanes, its velocities and positions against
        /// one lane's; the contact must have changed velocities for the case to count.</summary>
        [TestCase(2, TestName = "LanedSums_Drift_TwoLanes")]
        [TestCase(8, TestName = "LanedSums_Drift_EightLanes")]
        public void LanesGiveTheDriftOfOneThread(int lanes)
        {
            var one = Drifted(1, out var before);
            var many = Drifted(lanes, out _);
            int n = one.Particles.Length;
            var oneById = one.IndexById();
            var manyById = many.IndexById();
            double changed = ReferenceComparison.Max(n, k => (one.Particles[oneById[k]].Velocity - before[k].Velocity).Length());
            Assert.That(changed, Is.GreaterThan(0.05), "the wall contact must change velocities (m/s)");
            ReferenceComparison.CompareVectors("velocity", Tolerance, n, k => Of(one.Particles[oneById[k]].Velocity), k => Of(many.Particles[manyById[k]].Velocity));
            ReferenceComparison.CompareVectors("position", Tolerance, n, k => Of(one.Particles[oneById[k]].Position), k => Of(many.Particles[manyById[k]].Position));
        }

        /// <summary>
        /// The solves' stop decision with lanes. The fold (FoldSolveErrors) sums one error sum per thread group of the laned
        /// error pass, lanes times as many groups as particles fill, and only each particle's first lane adds its error: a
        /// wrong group count or a lane counted twice moves the average it compares with the tolerance, and so the
        /// iterations. A column
        /// of water collapsing across a box (DFSPH at 0.01 % and 1 %/s, 4 cm spacing) runs 20 frames with 1 and with 8 lanes: the mean
        /// iterations of each solve agree within 15 % (the flows part by rounding only; measured: 2.1 and 13.6 with either).
        /// </summary>
        [Test]
        public void LanedSolvesStopWhereOneLaneStops()
        {
            var one = CollapsingColumn(1);
            var eight = CollapsingColumn(8);
            TestContext.Progress.WriteLine($"1 lane: {one}");
            TestContext.Progress.WriteLine($"8 lanes: {eight}");
            Assert.That(one.DivergenceSolveIterations, Is.GreaterThan(5f), "a solve must iterate well past its minimum of two");
            Assert.That(eight.DensitySolveIterations, Is.EqualTo(one.DensitySolveIterations).Within(15).Percent);
            Assert.That(eight.DivergenceSolveIterations, Is.EqualTo(one.DivergenceSolveIterations).Within(15).Percent);
            Assert.That(eight.DensitySolvesCutOff, Is.EqualTo(one.DensitySolvesCutOff).Within(0.05f));
        }

        /// <summary>
        /// DFSPH's neighbour search with lanes (NeighbourLists.hlsl's ListOwnerInLanes): 2 and 8 lanes list, for every fluid
        /// and wall owner, the neighbours one lane lists, lane by lane instead of in the walk's order, and mark the same
        /// owners as too crowded for a list. The block of DivergenceFreeKernelTests squeezed to 0.75 of its spacing, so that
        /// some of its particles have more neighbours than a list's entries and the others fewer.
        /// </summary>
        [TestCase(2, TestName = "LanedSearch_TwoLanes")]
        [TestCase(8, TestName = "LanedSearch_EightLanes")]
        public void LanesListTheNeighboursOfOneThread(int lanes)
        {
            var one = ListedNeighbours(1);
            var many = ListedNeighbours(lanes);
            Assert.That(many.Length, Is.EqualTo(one.Length));
            int crowded = 0, listed = 0, reordered = 0;
            for (int owner = 0; owner < one.Length; owner++)
            {
                if (one[owner] == null)
                {
                    crowded++;
                    Assert.That(many[owner], Is.Null, $"owner {owner} has more neighbours than a list holds");
                    continue;
                }
                listed++;
                Assert.That(many[owner], Is.EquivalentTo(one[owner]), $"owner {owner}'s neighbours");
                if (!many[owner]!.SequenceEqual(one[owner]!)) reordered++;
            }
            TestContext.Progress.WriteLine($"{lanes} lanes: {listed} owners listed ({reordered} in another order), {crowded} too crowded");
            Assert.That(crowded, Is.GreaterThan(0), "some owners walk the grid");
            Assert.That(listed, Is.GreaterThan(crowded), "most owners read a list");
            Assert.That(reordered, Is.GreaterThan(0), "the lanes wrote the lists, not one thread (which keeps the walk's order)");
        }

        /// <summary>Each owner's listed neighbours as its entries stand ("f" and a fluid neighbour's id, "w" and a wall
        /// particle's sorted index), or null where the owner walks the grid.</summary>
        static string[]?[] ListedNeighbours(int lanes)
        {
            var scene = DivergenceFreeKernelTests.Block(false);
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene) { LanesPerParticle = lanes };
            sim.SetParticles(DivergenceFreeKernelTests.Compressed(scene, sim.ParticleCount, 0.75f));
            Assert.That(sim.ReadsNeighbourLists, Is.True);
            int owners = sim.ParticleCount + sim.BoundaryCount, capacity = sim.NeighbourListCapacity;
            var counts = new uint[owners];
            var entries = new uint[owners * capacity];
            sim.NeighbourCounts.GetData(counts);
            sim.NeighbourLists.GetData(entries);
            var ids = GpuState.Read(sim).Particles;
            var listed = new string[]?[owners];
            for (int o = 0; o < owners; o++)
            {
                if (counts[o] == uint.MaxValue) continue;
                int fluid = (int)(counts[o] & 0xFFFF), walls = (int)(counts[o] >> 16);
                Assert.That(fluid + walls, Is.LessThanOrEqualTo(capacity), $"owner {o}'s count");
                for (int k = 0; k < fluid; k++)
                    if (entries[k * owners + o] >= sim.ParticleCount)
                        Assert.Fail($"owner {o}'s fluid entry {k} is {entries[k * owners + o]}, past the {sim.ParticleCount} particles");
                for (int k = capacity - walls; k < capacity; k++)
                    if (entries[k * owners + o] >= sim.BoundaryCount)
                        Assert.Fail($"owner {o}'s wall entry {k} is {entries[k * owners + o]}, past the {sim.BoundaryCount} wall particles");
                var found = new List<string>();
                for (int k = 0; k < fluid; k++) found.Add("f" + ids[(int)entries[k * owners + o]].Id);
                for (int k = capacity - walls; k < capacity; k++) found.Add("w" + entries[k * owners + o]);
                listed[o] = found.ToArray();
            }
            return listed;
        }

        static DiagnosticsReport CollapsingColumn(int lanes)
        {
            var settings = SolverScenes.Coarse(0.04f);
            settings.PressureSolver = PressureSolver.Dfsph;
            settings.DensityTolerance = 0.01f;
            settings.DivergenceTolerance = 1f;
            var container = new Vector3(0.64f, 0.32f, 0.16f);
            var water = new Vector3(0.24f, 0.28f, 0.16f);
            var scene = SolverScenes.Scene(settings, container, SolverScenes.Box("Water", SolverScenes.Water(),
                new Vector3(0.5f * (water.X - container.X), 0.5f * (water.Y - container.Y), 0f), water));
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene) { LanesPerParticle = lanes };
            sim.ReadDiagnostics();
            for (int f = 0; f < 20; f++) sim.Step(1f / 60f);
            var report = sim.ReadDiagnostics();
            Assert.That(report.NanCount, Is.EqualTo(0));
            Assert.That(report.ParticleCount, Is.EqualTo(sim.ParticleCount));
            return report;
        }

        static Double3 Of(Vector4 v) => new Double3(v.X, v.Y, v.Z);
        static Double3 Of(Vector3 v) => new Double3(v.X, v.Y, v.Z);

        /// <summary>The noisy two-phase blob under DFSPH in its turning container, drifted once over 2 ms with
        /// <paramref name="lanes"/> threads per particle; <paramref name="before"/> by particle id.</summary>
        static GpuState Drifted(int lanes, out Particle[] before)
        {
            var scene = SolverKernelTests.RandomScene(true, false, false, false);
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene) { LanesPerParticle = lanes };
            var input = SolverKernelTests.RandomParticles(scene, sim.ParticleCount, 2468);
            before = new Particle[input.Length];
            foreach (var p in input) before[p.Id] = p;
            sim.SetParticles(input);
            sim.Drift(0.002f);
            return GpuState.Read(sim);
        }

        /// <summary>The noisy two-phase blob with shifting at A = 0.5 (every shift below the cap), one WCSPH sub-step of
        /// 0.5 ms with <paramref name="lanes"/> threads per particle.</summary>
        static GpuState Shifts(int lanes, out Vector4[] shifts)
        {
            var scene = SolverKernelTests.RandomScene(true, false, false, false);
            scene.Settings.ParticleShifting = 0.5f;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene) { LanesPerParticle = lanes };
            Assert.That(sim.Plan.Shifting, Is.True);
            sim.SetParticles(SolverKernelTests.RandomParticles(scene, sim.ParticleCount, 4242));
            sim.StepFixed(1, 0.0005f);
            shifts = new Vector4[sim.ParticleCount];
            sim.Shifts.GetData(shifts);
            return GpuState.Read(sim);
        }

        /// <summary>The noisy two-phase blob with tension, the strain rate's stress at 20 Pa s and a turning container, its
        /// forces computed with <paramref name="lanes"/> threads per particle.</summary>
        static GpuState TensionAndStrainRate(PressureSolver solver, int lanes, out Vector4[] normals, out Vector4[] rotations)
        {
            var scene = SolverKernelTests.RandomScene(true, true, true, false);
            scene.Settings.PressureSolver = solver;
            scene.Settings.ViscousStress = ViscousStress.StrainRate;
            foreach (var box in scene.SpawnBoxes) box.Phase.Viscosity = 20f;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene) { LanesPerParticle = lanes };
            Assert.That(sim.Plan.SurfaceTension && sim.Plan.StrainRateViscosity, Is.True, "both passes run");
            sim.SetParticles(SolverKernelTests.RandomParticles(scene, sim.ParticleCount, 4321));
            sim.ComputeForces();
            normals = new Vector4[sim.ParticleCount];
            rotations = new Vector4[sim.ParticleCount];
            sim.Normals.GetData(normals);
            sim.Rotations.GetData(rotations);
            return GpuState.Read(sim);
        }

        /// <summary>The noisy two-phase blob of SolverKernelTests (XSPH on, a turning container), its forces computed with
        /// <paramref name="lanes"/> threads per particle.</summary>
        static GpuState Forces(WcsphDensity density, PressureSolver solver, int lanes, out Vector2[] rates)
        {
            var scene = SolverKernelTests.RandomScene(true, false, true, false);
            scene.Settings.WcsphDensity = density;
            scene.Settings.PressureSolver = solver;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene) { LanesPerParticle = lanes };
            var input = SolverKernelTests.RandomParticles(scene, sim.ParticleCount, 1357);
            sim.SetParticles(input);
            sim.ComputeForces();
            rates = new Vector2[sim.ParticleCount];
            if (density == WcsphDensity.DeltaSph) sim.DensityRates.GetData(rates);
            return GpuState.Read(sim);
        }
    }
}
