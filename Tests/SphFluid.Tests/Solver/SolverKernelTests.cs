using System;
using System.Collections.Generic;
using System.Numerics;
using System.Linq;
using NUnit.Framework;
using SphFluid.Reference;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// Every solver kernel against the double-precision CPU reference (ReferenceSph) on small random
    /// cases: density, pressure, normals, accelerations (pressure, viscosity, tension, gravity, container
    /// and obstacle penalties) and XSPH after ComputeForces, and positions/velocities after one sub-step
    /// (half step, clamp, re-sort, forces, full step). Relative error &lt;= 1e-4 of each quantity's scale.
    /// </summary>
    public sealed class SolverKernelTests
    {
        const double Tolerance = 1e-4;

        /// <summary>A compressed, noisy blob (spacing 0.85 s, random velocities), partly pushed into the walls.</summary>
        internal static FluidSceneDescription RandomScene(bool multiphase, bool tension, bool xsph, bool obstacle,
            KernelFamily kernel = KernelFamily.CubicSpline)
        {
            var settings = SolverScenes.Coarse(0.02f);
            settings.SmoothingKernel = kernel;
            if (kernel == KernelFamily.WendlandC2) settings.SmoothingRadius = 3f * settings.ParticleSpacing;
            settings.XsphEpsilon = xsph ? 0.3f : 0f;
            var size = new Vector3(0.16f, 0.16f, 0.16f);
            // The oil's explicit mass, 3 % above the 7.2 g its lattice cell derives, puts its rest number density 3 % below the
            // lattice's: the walls then count at a different rest number density for each phase (WallWeightScale about 0.97 and 1).
            var oil = SolverScenes.Oil(0.02f, tension ? 0.3f : 0f);
            oil.ParticleMass = 1.03f * 900f * 0.02f * 0.02f * 0.02f;
            var boxes = new List<FluidBlock>
            {
                SolverScenes.Box("A", SolverScenes.Water(0.1f, tension ? 0.5f : 0f), new Vector3(0f, -0.04f, 0f), new Vector3(0.16f, 0.08f, 0.16f)),
                SolverScenes.Box("B", multiphase ? oil : SolverScenes.Water(0.1f, tension ? 0.5f : 0f),
                    new Vector3(0f, 0.04f, 0f), new Vector3(0.16f, 0.08f, 0.16f)),
            };
            var scene = SolverScenes.Scene(settings, size, boxes.ToArray());
            scene.Container.Rotation = Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(1f, 2f, 0.5f)), 0.3f);
            scene.Container.Position = new Vector3(0.01f, -0.02f, 0.03f);
            scene.Container.Velocity = new Vector3(0.1f, 0f, -0.05f);
            scene.Container.AngularVelocity = new Vector3(0f, 0.7f, 0.2f);
            foreach (var box in scene.SpawnBoxes)
            {
                box.Center = scene.Container.Position + Vector3.Transform(box.Center, scene.Container.Rotation);
                box.Rotation = scene.Container.Rotation;
            }
            if (obstacle) scene.Obstacles.Add(new RigidSphere(new Vector3(0.02f, 0f, 0f), 0.03f, new Vector3(0.2f, 0f, 0f)));
            return scene;
        }

        internal static Particle[] RandomParticles(FluidSceneDescription scene, int count, ulong seed)
        {
            var rng = new SolverScenes.Rng(seed);
            var spawn = SpawnLayout.Generate(scene);
            var particles = new Particle[count];
            var rotation = Quaternion.Normalize(scene.Container.Rotation);
            for (int i = 0; i < count; i++)
            {
                // Compress towards the centre and scatter: pressures well above zero, some particles in the wall zone.
                var local = Vector3.Transform(spawn[i].Position - scene.Container.Position, Quaternion.Conjugate(rotation));
                local = local * 0.9f + rng.InBox(new Vector3(0.006f));
                // Some particles in the wall's penalty zone (beyond H = 0.07), none near the clamp (0.0798): the clamp
                // is a discontinuity (a particle a rounding error either side keeps or loses its outward velocity)
                // and is tested on its own.
                if (i % 17 == 0) local.X = rng.Range(0.071f, 0.078f);
                var position = scene.Container.Position + Vector3.Transform(local, rotation);
                foreach (var o in scene.Obstacles)
                {
                    var d = position - o.Center;
                    float keep = o.Radius + 0.25f * scene.Settings.ParticleSpacing; // inside the penalty zone, outside the clamp
                    if (d.Length() < keep) position = o.Center + Vector3.Normalize(d) * (keep + rng.Range(0f, 0.004f));
                }
                var velocity = rng.InBox(new Vector3(0.5f));
                particles[i] = new Particle(position, velocity, spawn[i].Phase, spawn[i].Id);
            }
            return particles;
        }

        [TestCase(false, false, false, false, TestName = "Kernels_MatchReference_SinglePhase")]
        [TestCase(true, false, true, false, TestName = "Kernels_MatchReference_TwoPhasesXsph")]
        [TestCase(true, true, true, true, TestName = "Kernels_MatchReference_AllEffects")]
        [TestCase(false, true, false, true, TestName = "Kernels_MatchReference_SinglePhaseTensionObstacle")]
        [TestCase(true, true, true, true, KernelFamily.WendlandC2, TestName = "Kernels_MatchReference_AllEffectsWendlandC2")]
        public void ForcePassesMatchReference(bool multiphase, bool tension, bool xsph, bool obstacle,
            KernelFamily kernel = KernelFamily.CubicSpline)
        {
            var scene = RandomScene(multiphase, tension, xsph, obstacle, kernel);
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, scene))
            {
                var input = RandomParticles(scene, sim.ParticleCount, 12345);
                sim.SetParticles(input);
                Assert.That(sim.Plan.Multiphase, Is.EqualTo(multiphase));
                if (multiphase) Assert.That(sim.PhaseRows[1].WallWeightScale, Is.InRange(0.96, 0.975), "the oil's walls count at its own rest, 3 % below the lattice's");
                Assert.That(sim.Plan.SurfaceTension, Is.EqualTo(tension));

                var gpu = GpuState.Read(sim);
                var referenceSph = new ReferenceSph(scene);
                var byIdParticles = gpu.ByIdParticles(input);
                var reference = referenceSph.Evaluate(byIdParticles);
                var byId = gpu.IndexById();

                Compare("number density", input.Length, i => reference.NumberDensity[i], i => gpu.Densities[byId[i]].Z);
                Compare("density", input.Length, i => reference.Density[i], i => gpu.Densities[byId[i]].X);
                Compare("pressure", input.Length, i => reference.Pressure[i], i => gpu.Densities[byId[i]].Y);
                Assert.That(Max(input.Length, i => reference.Pressure[i]), Is.GreaterThan(100.0), "the case must be compressed");
                if (tension)
                    CompareVectors("normal", input.Length, i => reference.Normal[i], i => gpu.Normals[byId[i]]);
                CompareVectors("acceleration", input.Length, i => reference.Acceleration[i], i => gpu.Accelerations[byId[i]]);
                // Outside a step the force pass runs at dt = 0: the wall contact acts on the half-step velocity itself.
                var corrections = referenceSph.VelocityCorrections(byIdParticles, reference, 0.0, xsph);
                Assert.That(Enumerable.Range(0, input.Length).Count(i => (corrections[i] - (xsph ? reference.Xsph[i] : Double3.Zero)).Length() > 0),
                    Is.GreaterThan(0), "some particles below rest density must be moving into a wall");
                CompareVectors("velocity correction (XSPH, wall contact)", input.Length, i => corrections[i], i => gpu.Corrections[byId[i]]);
            }
        }

        [TestCase(false, TestName = "Substep_MatchesReference_SinglePhase")]
        [TestCase(true, TestName = "Substep_MatchesReference_AllEffects")]
        [TestCase(true, KernelFamily.WendlandC2, TestName = "Substep_MatchesReference_AllEffectsWendlandC2")]
        public void SubstepMatchesReference(bool all, KernelFamily kernel = KernelFamily.CubicSpline)
        {
            var scene = RandomScene(all, all, all, all, kernel);
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, scene))
            {
                var input = RandomParticles(scene, sim.ParticleCount, 777);
                sim.SetParticles(input);
                var before = GpuState.Read(sim);
                var referenceSph = new ReferenceSph(scene);
                var start = before.ByIdParticles(input);
                var startState = referenceSph.Evaluate(start);
                const float dt = 0.0005f;
                var expected = referenceSph.Substep(start, startState, dt, sim.Plan.Xsph, out _);

                sim.StepFixed(1, dt);
                var after = GpuState.Read(sim);
                var byId = after.IndexById();
                int n = input.Length;
                CompareVectors("position", n, i => new Double3(expected[i].Position) - new Double3(start[i].Position),
                    i => new Vector4(after.Particles[byId[i]].Position - start[i].Position, 0f));
                CompareVectors("velocity", n, i => new Double3(expected[i].Velocity), i => new Vector4(after.Particles[byId[i]].Velocity, 0f));
            }
        }

        /// <summary>Particle shifting (ParticleShifting.hlsl) against ReferenceSph.Shifts: the shift of every particle and
        /// the state after a sub-step with it, two phases (the interface rule) in a container with a free surface; at A = 0.5
        /// every shift is below the cap, at A = 4 most are capped.</summary>
        [TestCase(0.5f, TestName = "Shifting_MatchesReference_Uncapped")]
        [TestCase(4f, TestName = "Shifting_MatchesReference_Capped")]
        public void ShiftingMatchesReference(float coefficient)
        {
            var scene = RandomScene(true, false, false, false);
            scene.Settings.ParticleShifting = coefficient;
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, scene))
            {
                var input = RandomParticles(scene, sim.ParticleCount, 4242);
                sim.SetParticles(input);
                Assert.That(sim.Plan.Shifting, Is.True);
                var referenceSph = new ReferenceSph(scene);
                var start = GpuState.Read(sim).ByIdParticles(input);
                var startState = referenceSph.Evaluate(start);
                const float dt = 0.0005f;
                var shifted = referenceSph.Substep(start, startState, dt, false, out var next);
                var unshifted = ReferenceWithoutShifting(scene).Substep(start, startState, dt, false, out _);
                var shifts = referenceSph.Shifts(unshifted, next, dt);

                sim.StepFixed(1, dt);
                var after = GpuState.Read(sim);
                var gpuShifts = new Vector4[sim.ParticleCount];
                sim.Shifts.GetData(gpuShifts);
                var byId = after.IndexById();
                int n = input.Length;
                Assert.That(Max(n, i => shifts[i].Length()), Is.GreaterThan(1e-4 * scene.Settings.ParticleSpacing), "the case must shift");
                CompareVectors("shift", n, i => shifts[i], i => gpuShifts[byId[i]]);
                CompareVectors("position", n, i => new Double3(shifted[i].Position) - new Double3(start[i].Position),
                    i => new Vector4(after.Particles[byId[i]].Position - start[i].Position, 0f));
            }
        }

        /// <summary>The strain rate's viscous stress (ViscousStress.StrainRate) against ReferenceSph: the Rotations pass's
        /// Omega, the accelerations after the force pass and the state after a sub-step, with every effect (two phases,
        /// tension, XSPH, an obstacle) and with none (no keyword variant), walls with friction in a spinning container. Both phases at 20 Pa s, so that the viscous force, and in it the rotation
        /// term the Laplacian form lacks, is well above the tolerance of the pressure's scale.</summary>
        [TestCase(KernelFamily.CubicSpline, true, TestName = "Kernels_MatchReference_StrainRate")]
        [TestCase(KernelFamily.WendlandC2, true, TestName = "Kernels_MatchReference_StrainRateWendlandC2")]
        [TestCase(KernelFamily.CubicSpline, false, TestName = "Kernels_MatchReference_StrainRateSinglePhase")]
        public void StrainRatePassesMatchReference(KernelFamily kernel, bool all)
        {
            var scene = RandomScene(all, all, all, all, kernel);
            scene.Settings.ViscousStress = ViscousStress.StrainRate;
            foreach (var box in scene.SpawnBoxes) box.Phase.Viscosity = 20f;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            var input = RandomParticles(scene, sim.ParticleCount, 2468);
            sim.SetParticles(input);
            Assert.That(sim.Plan.StrainRateViscosity, Is.True);
            Assert.That(sim.Plan.Runs(PassNames.Rotations), Is.True);
            int n = input.Length;
            var gpu = GpuState.Read(sim);
            var rotations = new Vector4[n];
            sim.Rotations.GetData(rotations);
            var referenceSph = new ReferenceSph(scene);
            var start = gpu.ByIdParticles(input);
            var reference = referenceSph.Evaluate(start);
            var byId = gpu.IndexById();

            CompareVectors("rotation", n, i => reference.Rotation[i], i => rotations[byId[i]]);
            var laplacianScene = new FluidSceneDescription
            {
                Settings = scene.Settings.Clone(), SpawnBoxes = scene.SpawnBoxes, Container = scene.Container, Obstacles = scene.Obstacles,
            };
            laplacianScene.Settings.ViscousStress = ViscousStress.Laplacian;
            var laplacian = new ReferenceSph(laplacianScene).Evaluate(start);
            double scale = Max(n, i => reference.Acceleration[i].Length());
            double stressShare = Max(n, i => (reference.Acceleration[i] - laplacian.Acceleration[i]).Length()) / scale;
            TestContext.Out.WriteLine($"the strain rate's stress moves the accelerations by up to {stressShare:E2} of their scale");
            Assert.That(stressShare, Is.GreaterThan(100 * Tolerance), "the case must tell the two stresses apart");
            CompareVectors("acceleration", n, i => reference.Acceleration[i], i => gpu.Accelerations[byId[i]]);

            const float dt = 0.0005f;
            Assert.That(TimeStepController.ForScene(scene).ViscousTimeStep, Is.GreaterThan(dt), "the sub-step is within the explicit limit");
            var expected = referenceSph.Substep(start, reference, dt, sim.Plan.Xsph, out _);
            sim.StepFixed(1, dt);
            var after = GpuState.Read(sim);
            byId = after.IndexById();
            CompareVectors("position", n, i => new Double3(expected[i].Position) - new Double3(start[i].Position),
                i => new Vector4(after.Particles[byId[i]].Position - start[i].Position, 0f));
            CompareVectors("velocity", n, i => new Double3(expected[i].Velocity), i => new Vector4(after.Particles[byId[i]].Velocity, 0f));
        }

        static ReferenceSph ReferenceWithoutShifting(FluidSceneDescription scene)
        {
            var settings = scene.Settings.Clone();
            settings.ParticleShifting = 0f;
            return new ReferenceSph(new FluidSceneDescription
            {
                Settings = settings, SpawnBoxes = scene.SpawnBoxes, Container = scene.Container, Obstacles = scene.Obstacles,
            });
        }

        static double Max(int n, Func<int, double> f)
        {
            double m = 0;
            for (int i = 0; i < n; i++) m = Math.Max(m, Math.Abs(f(i)));
            return m;
        }

        static void Compare(string what, int n, Func<int, double> expected, Func<int, float> actual)
        {
            double scale = Math.Max(Max(n, expected), 1e-30);
            double worst = 0;
            int worstAt = -1;
            for (int i = 0; i < n; i++)
            {
                double e = Math.Abs(actual(i) - expected(i)) / scale;
                if (e > worst) { worst = e; worstAt = i; }
            }
            TestContext.Out.WriteLine($"{what}: scale {scale:G4}, worst relative error {worst:E2}");
            Assert.That(worst, Is.LessThanOrEqualTo(Tolerance),
                $"{what}: particle id {worstAt} expected {(worstAt >= 0 ? expected(worstAt) : 0):G8} got {(worstAt >= 0 ? actual(worstAt) : 0):G8} (scale {scale:G4})");
        }

        static void CompareVectors(string what, int n, Func<int, Double3> expected, Func<int, Vector4> actual)
        {
            double scale = Math.Max(Max(n, i => expected(i).Length()), 1e-30);
            double worst = 0;
            int worstAt = -1;
            for (int i = 0; i < n; i++)
            {
                var a = actual(i);
                var d = new Double3(a.X, a.Y, a.Z) - expected(i);
                double e = Math.Max(Math.Abs(d.X), Math.Max(Math.Abs(d.Y), Math.Abs(d.Z))) / scale;
                if (e > worst) { worst = e; worstAt = i; }
            }
            TestContext.Out.WriteLine($"{what}: scale {scale:G4}, worst relative component error {worst:E2}");
            Assert.That(worst, Is.LessThanOrEqualTo(Tolerance),
                $"{what}: particle id {worstAt} expected {(worstAt >= 0 ? expected(worstAt).ToString() : "")} got {(worstAt >= 0 ? actual(worstAt).ToString() : "")} (scale {scale:G4})");
        }
    }

    /// <summary>A blocking read-back of the solver's per-particle buffers (sorted order).</summary>
    public sealed class GpuState
    {
        public readonly Particle[] Particles;
        public readonly Vector4[] Densities, Normals, Accelerations, Corrections;

        GpuState(int n)
        {
            Particles = new Particle[n];
            Densities = new Vector4[n];
            Normals = new Vector4[n];
            Accelerations = new Vector4[n];
            Corrections = new Vector4[n];
        }

        public static GpuState Read(FluidSimulation sim)
        {
            var s = new GpuState(sim.ParticleCount);
            sim.Particles.GetData(s.Particles);
            sim.Densities.GetData(s.Densities);
            sim.Normals.GetData(s.Normals);
            sim.Accelerations.GetData(s.Accelerations);
            sim.VelocityCorrections.GetData(s.Corrections);
            return s;
        }

        /// <summary>slot of particle id k.</summary>
        public int[] IndexById()
        {
            var index = new int[Particles.Length];
            for (int j = 0; j < Particles.Length; j++) index[Particles[j].Id] = j;
            return index;
        }

        /// <summary>The particles in id order, as the GPU holds them (positions exactly as the kernels saw them).</summary>
        public Particle[] ByIdParticles(Particle[] input)
        {
            var result = new Particle[Particles.Length];
            foreach (var p in Particles) result[p.Id] = p;
            return result;
        }
    }
}
