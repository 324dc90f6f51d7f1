using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    public sealed class SpawnLayoutTests
    {
        [Test]
        public void Count_IsLatticePointsPerAxis()
        {
            // 0.05 / 0.02 = 2.5 points: 3 (150 cells of 8.3e-6 m^3 for 125 of 8e-6) is closer in volume than 2 (100).
            var settings = new FluidSettings { ParticleSpacing = 0.02f, SmoothingRadius = 0.04f };
            var box = new FluidBlock("B", SimulationTestScenes.Water(), Vector3.Zero, new Vector3(0.2f, 0.1f, 0.05f));
            SpawnLayout.CountPerAxis(settings, box, out int nx, out int ny, out int nz);
            Assert.That(new[] { nx, ny, nz }, Is.EqualTo(new[] { 10, 5, 3 }));
            Assert.That(SpawnLayout.Count(settings, box), Is.EqualTo(150L));
        }

        [Test]
        public void Generate_GivesTheCountsOfEveryBox()
        {
            var scene = SimulationTestScenes.OilOnWater();
            var particles = SpawnLayout.Generate(scene);
            Assert.That(particles.Length, Is.EqualTo(25 * 6 * 25 * 2));
            Assert.That(SpawnLayout.TotalCount(scene), Is.EqualTo(particles.Length));
            int water = 0, oil = 0;
            foreach (var p in particles) { if (p.Phase == 0) water++; else oil++; }
            Assert.That(water, Is.EqualTo(25 * 6 * 25));
            Assert.That(oil, Is.EqualTo(25 * 6 * 25));
        }

        [Test]
        public void Generate_PutsEveryParticleInsideItsBoxAndTheContainer()
        {
            var scene = SimulationTestScenes.OilOnWater();
            var rotation = Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(1f, 1f, 0f)), 0.4f);
            scene.SpawnBoxes[0].Rotation = rotation;
            scene.SpawnBoxes[0].Size = new Vector3(0.2f, 0.1f, 0.2f);
            scene.SpawnBoxes[0].Center = new Vector3(0.05f, -0.1f, 0f);
            scene.SpawnBoxes[0].Jitter = 0.5f;
            scene.SpawnBoxes[1].Jitter = 0.5f;
            scene.SpawnBoxes[1].Center = new Vector3(0f, 0.1f, 0f); // clear of the tilted box: overlapping boxes are refused
            scene.Settings.Gravity = Vector3.Zero; // the lattice itself, before HydrostaticSpawn lowers it along gravity
            var particles = SpawnLayout.Generate(scene);
            int index = 0;
            foreach (var box in scene.SpawnBoxes)
            {
                long count = SpawnLayout.Count(scene.Settings, box);
                var inverse = Quaternion.Conjugate(Quaternion.Normalize(box.Rotation));
                for (long k = 0; k < count; k++, index++)
                {
                    var local = Vector3.Transform(particles[index].Position - box.Center, inverse);
                    var half = box.Size * 0.5f + new Vector3(1e-5f);
                    Assert.That(Math.Abs(local.X) <= half.X && Math.Abs(local.Y) <= half.Y && Math.Abs(local.Z) <= half.Z, Is.True,
                        $"particle {index} of box {box.Name} at local {local} is outside half-size {box.Size * 0.5f}");
                    var q = scene.Container.ToLocal(particles[index].Position);
                    var c = scene.Container.Size * 0.5f;
                    Assert.That(Math.Abs(q.X) <= c.X && Math.Abs(q.Y) <= c.Y && Math.Abs(q.Z) <= c.Z, Is.True,
                        $"particle {index} is outside the container");
                }
            }
        }

        [Test]
        public void Generate_GivesIdsInOrderAndTheInitialVelocity()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes[0].InitialVelocity = new Vector3(0.5f, 0f, -1f);
            var particles = SpawnLayout.Generate(scene);
            for (int i = 0; i < particles.Length; i++)
            {
                Assert.That(particles[i].Id, Is.EqualTo((uint)i));
                Assert.That(particles[i].Velocity, Is.EqualTo(new Vector3(0.5f, 0f, -1f)));
            }
        }

        [Test]
        public void Generate_SameSeedSameParticles_OtherSeedOtherJitter()
        {
            var a = SpawnLayout.Generate(SimulationTestScenes.OilOnWater());
            var b = SpawnLayout.Generate(SimulationTestScenes.OilOnWater());
            Assert.That(b, Is.EqualTo(a));
            var other = SimulationTestScenes.OilOnWater();
            other.SpawnBoxes[0].Seed = 42;
            var c = SpawnLayout.Generate(other);
            Assert.That(c[0].Position, Is.Not.EqualTo(a[0].Position));
        }

        [Test]
        public void Generate_ZeroJitter_IsARegularLatticeCentredInTheBox()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes[0].Jitter = 0f;
            var particles = SpawnLayout.Generate(scene);
            var box = scene.SpawnBoxes[0];
            Assert.That(particles[0].Position.X, Is.EqualTo(box.Center.X - box.Size.X * 0.5f + 0.01f).Within(1e-5f));
            Assert.That(particles[1].Position.X - particles[0].Position.X, Is.EqualTo(0.02f).Within(1e-5f));
        }

        [Test]
        public void PhaseTable_OneRowPerPhaseName_MassAtRestDensity()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes.Add(new FluidBlock("MoreWater", SimulationTestScenes.Water(), new Vector3(0f, 0.1f, 0f), new Vector3(0.1f, 0.1f, 0.1f)));
            var table = scene.BuildPhaseTable();
            Assert.That(table.Length, Is.EqualTo(2));
            double delta0 = scene.RestNumberDensity();
            Assert.That(table[0].RestDensity, Is.EqualTo(1000f));
            Assert.That(table[1].RestDensity, Is.EqualTo(900f));
            Assert.That(table[0].ParticleMass * delta0, Is.EqualTo(1000.0).Within(1e-3));
            Assert.That(table[1].ParticleMass * delta0, Is.EqualTo(900.0).Within(1e-3));
            Assert.That(table[1].Viscosity, Is.EqualTo(0.05f));
            var particles = SpawnLayout.Generate(scene);
            Assert.That(particles[particles.Length - 1].Phase, Is.EqualTo(0u), "a box of an existing phase shares its row");
        }

        [Test]
        public void PhaseTable_ExplicitMassIsKept()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes[0].Phase.ParticleMass = 0.123f;
            Assert.That(scene.BuildPhaseTable()[0].ParticleMass, Is.EqualTo(0.123f));
        }

        [Test]
        public void TheSpawnIsLoweredIntoHydrostaticEquilibrium()
        {
            // One box resting on the container floor: a particle at height y above the box bottom moves down by
            // the compression of the fluid below it, integral_0^y (1 - (1 + rho0 g (H - y') / k)^(-1/gamma)) dy'.
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes.RemoveAt(1);
            var box = scene.SpawnBoxes[0];
            box.Jitter = 0f;
            var flat = SimulationTestScenes.OilOnWater();
            flat.SpawnBoxes.RemoveAt(1);
            flat.SpawnBoxes[0].Jitter = 0f;
            flat.Settings.Gravity = Vector3.Zero;
            var lowered = SpawnLayout.Generate(scene);
            var lattice = SpawnLayout.Generate(flat);
            double g = 9.81, k = scene.Settings.Stiffness, gamma = scene.Settings.Gamma, rho0 = box.Phase.RestDensity;
            double bottom = box.Center.Y - 0.5 * box.Size.Y, height = box.Size.Y;
            double deepest = 0;
            for (int i = 0; i < lattice.Length; i++)
            {
                double y = lattice[i].Position.Y - bottom, expected = 0;
                const int n = 20000;
                for (int step = 0; step < n; step++)
                {
                    double yy = (step + 0.5) * y / n;
                    expected += (1 - Math.Pow(1 + rho0 * g * (height - yy) / k, -1 / gamma)) * y / n;
                }
                Assert.That(lattice[i].Position.Y - lowered[i].Position.Y, Is.EqualTo(expected).Within(1e-6), $"particle {i} at {y:F3} m");
                Assert.That(lowered[i].Position.X, Is.EqualTo(lattice[i].Position.X), "only along gravity");
                deepest = Math.Max(deepest, expected);
            }
            Assert.That(deepest, Is.GreaterThan(1e-5), "the test scene compresses measurably");
        }

        [Test]
        public void TheCountLeavesOutWhatASphereDisplaces()
        {
            // What the inspector, the runner and the health check count must be what Generate spawns.
            var scene = SimulationTestScenes.SingleWater();
            scene.Obstacles.Add(new RigidSphere { Center = new Vector3(0f, -0.19f, 0f), Radius = 0.04f });
            var box = scene.SpawnBoxes[0];

            int spawned = SpawnLayout.Generate(scene).Length;

            Assert.That(SpawnLayout.TotalCount(scene), Is.EqualTo(spawned));
            Assert.That(SpawnLayout.SpawnedCount(scene, box), Is.EqualTo((long)spawned));
            Assert.That(SpawnLayout.Count(scene.Settings, box), Is.GreaterThan((long)spawned), "the lattice holds the displaced points");
        }

        // The count tests only the lattice points near each sphere, the walk every point: the two must agree to the point,
        // for turned boxes, any jitter and spheres that overlap each other or reach past the box.
        [Test]
        public void TheCountOfPointsNearTheSpheresIsTheWalks()
        {
            var random = new Random(20261207);
            float Between(float lo, float hi) => lo + (float)random.NextDouble() * (hi - lo);
            Vector3 Around(float reach) => new Vector3(Between(-reach, reach), Between(-reach, reach), Between(-reach, reach));
            int compared = 0, displacing = 0;
            for (int n = 0; n < 60; n++)
            {
                var scene = SimulationTestScenes.SingleWater();
                var box = scene.SpawnBoxes[0];
                box.Center = Around(0.05f);
                box.Size = new Vector3(Between(0.08f, 0.2f), Between(0.08f, 0.2f), Between(0.08f, 0.2f));
                box.Rotation = Quaternion.Normalize(new Quaternion(Around(1f), Between(-1f, 1f)));
                box.Jitter = n % 4 == 0 ? 0f : Between(0f, 0.5f);
                box.Seed = random.Next();
                int spheres = 1 + n % 3;
                for (int m = 0; m < spheres; m++)
                    scene.Obstacles.Add(new RigidSphere { Center = box.Center + Around(0.12f), Radius = Between(0.005f, 0.08f), Name = "S" + m });
                if (scene.Validate().Count > 0) continue;

                int walked = SpawnLayout.Generate(scene).Length;

                Assert.That(SpawnLayout.SpawnedCount(scene, box), Is.EqualTo((long)walked), $"case {n}");
                compared++;
                if (walked < SpawnLayout.Count(scene.Settings, box)) displacing++;
            }
            Assert.That(compared, Is.GreaterThanOrEqualTo(40), "scenes compared");
            Assert.That(displacing, Is.GreaterThanOrEqualTo(30), "scenes whose spheres displace points");
        }

        [Test]
        public void ASubmergedSphereCarriesTheFluidAboveIt()
        {
            // A particle above a submerged sphere moves down by the compression of the fluid between the sphere's top
            // and itself only: the sphere displaces the fluid below that, so there is none to compress. Every other
            // particle is lowered as in a box without a sphere.
            var scene = SimulationTestScenes.SingleWater();
            var box = scene.SpawnBoxes[0];
            box.Jitter = 0f;
            var sphere = new RigidSphere { Center = new Vector3(0.01f, -0.19f, -0.005f), Radius = 0.04f };
            scene.Obstacles.Add(sphere);
            var flat = SimulationTestScenes.SingleWater();
            flat.SpawnBoxes[0].Jitter = 0f;
            flat.Obstacles.Add(sphere);
            flat.Settings.Gravity = Vector3.Zero;
            var lowered = SpawnLayout.Generate(scene);
            var lattice = SpawnLayout.Generate(flat);
            Assert.That(lowered.Length, Is.EqualTo(lattice.Length));
            double g = 9.81, k = scene.Settings.Stiffness, gamma = scene.Settings.Gamma, rho0 = box.Phase.RestDensity;
            double bottom = box.Center.Y - 0.5 * box.Size.Y, top = box.Center.Y + 0.5 * box.Size.Y;
            int carried = 0;
            for (int i = 0; i < lattice.Length; i++)
            {
                var x = lattice[i].Position;
                double from = bottom;
                double dx = x.X - sphere.Center.X, dz = x.Z - sphere.Center.Z, r2 = (double)sphere.Radius * sphere.Radius;
                if (dx * dx + dz * dz < r2 && x.Y > sphere.Center.Y)
                {
                    from = sphere.Center.Y + Math.Sqrt(r2 - dx * dx - dz * dz);
                    carried++;
                }
                double expected = 0;
                const int n = 4000;
                for (int step = 0; step < n; step++)
                {
                    double y = from + (step + 0.5) * (x.Y - from) / n;
                    expected += (1 - Math.Pow(1 + rho0 * g * (top - y) / k, -1 / gamma)) * (x.Y - from) / n;
                }
                Assert.That(x.Y - lowered[i].Position.Y, Is.EqualTo(expected).Within(1e-6), $"particle {i} at {x}");
            }
            Assert.That(carried, Is.GreaterThan(4), "particles rest on the sphere");
        }

        [Test]
        public void UnderDfsphTheSpawnStaysOnTheLatticeWithTheSamePressures()
        {
            // DFSPH holds every particle at the rest density: the first solve would expand a spawn compressed for the Tait fluid within one sub-step.
            var tait = SimulationTestScenes.OilOnWater();
            var incompressible = SimulationTestScenes.OilOnWater();
            incompressible.Settings.PressureSolver = PressureSolver.Dfsph;
            var flat = SimulationTestScenes.OilOnWater();
            flat.Settings.Gravity = Vector3.Zero;
            var lowered = SpawnLayout.Generate(tait, out double[] taitPressures);
            var kept = SpawnLayout.Generate(incompressible, out double[] pressures);
            var lattice = SpawnLayout.Generate(flat);
            Assert.That(kept.Length, Is.EqualTo(lattice.Length));
            for (int i = 0; i < kept.Length; i++)
            {
                Assert.That(kept[i].Position, Is.EqualTo(lattice[i].Position), $"particle {i}");
                Assert.That(pressures[i], Is.EqualTo(taitPressures[i]), $"particle {i}'s hydrostatic pressure");
            }
            Assert.That(pressures.Max(), Is.GreaterThan(100.0), "the test scene has a column to weigh");
            Assert.That(lowered.Zip(lattice, (a, b) => b.Position.Y - a.Position.Y).Max(), Is.GreaterThan(1e-5f), "WCSPH's spawn is lowered");
        }

        [Test]
        public void NoParticleIsSpawnedInsideASphereObstacle()
        {
            var scene = SimulationTestScenes.OilOnWater();
            var without = SpawnLayout.Generate(scene).Length;
            var sphere = new RigidSphere(scene.SpawnBoxes[0].Center, 0.05f, Vector3.Zero);
            scene.Obstacles.Add(sphere);
            var particles = SpawnLayout.Generate(scene);
            Assert.That(particles.Length, Is.LessThan(without));
            foreach (var p in particles)
                Assert.That(Vector3.Distance(p.Position, sphere.Center), Is.GreaterThanOrEqualTo(sphere.Radius + 0.5f * scene.Settings.ParticleSpacing - 1e-3f));
            for (int i = 0; i < particles.Length; i++) Assert.That(particles[i].Id, Is.EqualTo((uint)i), "ids stay 0..N-1");
        }

        [Test]
        public void RestNumberDensity_MatchesTheCubicSplineLatticeSum()
        {
            // For H = 2 s the lattice neighbours within H are at squared distances 0,1,2,3 (in s^2) with 1,6,12,8
            // points (those at 4 s^2 lie on the support's edge, where W = 0). Hand-evaluated spline:
            // W = 8/(pi H^3) {1, 1/4, 2 (1 - sqrt(2)/2)^3, 2 (1 - sqrt(3)/2)^3}.
            double s = 0.02, h = 0.04;
            double sigma = 8.0 / (Math.PI * h * h * h);
            double expected = sigma * (1.0 + 6 * 0.25 + 12 * 2 * Math.Pow(1 - Math.Sqrt(2) / 2, 3) + 8 * 2 * Math.Pow(1 - Math.Sqrt(3) / 2, 3));
            Assert.That(SmoothingKernels.LatticeNumberDensity(KernelFamily.CubicSpline, s, h), Is.EqualTo(expected).Within(1e-9 * expected));
            Assert.That(SmoothingKernels.LatticeNumberDensity(KernelFamily.CubicSpline, s, h) * s * s * s, Is.EqualTo(1.0).Within(1e-4),
                "the spline sums to 1 / s^3 on its lattice");
        }

        [Test]
        public void RestNumberDensity_MatchesTheWendlandLatticeSum()
        {
            // The same neighbours at H = 2 s (q = 0, 1/2, sqrt(2)/2, sqrt(3)/2), with w(q) = (1 - q)^4 (1 + 4 q).
            double s = 0.02, h = 0.04;
            double sigma = 21.0 / (2.0 * Math.PI * h * h * h);
            Func<double, double> w = q => Math.Pow(1 - q, 4) * (1 + 4 * q);
            double expected = sigma * (w(0) + 6 * w(0.5) + 12 * w(Math.Sqrt(2) / 2) + 8 * w(Math.Sqrt(3) / 2));
            Assert.That(SmoothingKernels.LatticeNumberDensity(KernelFamily.WendlandC2, s, h), Is.EqualTo(expected).Within(1e-9 * expected));
        }

        // The hydrostatic gradient a resting tank settles to is off by this factor's distance from 1. Each kernel at the
        // supports it is allowed (FluidSettings.MaxCubicSplineSupportRatio): the cubic spline recovers 1.0201 at 2 spacings
        // and 0.9904 at 2.25; Wendland C2 0.9501 at 2 spacings (its support is too narrow there), 0.9908 at 2.85 (the
        // RestingTank scene's), 0.9975 at 3 and 0.9989 at 4.
        [TestCase(KernelFamily.CubicSpline, 2.0, 0.021)]
        [TestCase(KernelFamily.CubicSpline, 2.25, 0.01)]
        [TestCase(KernelFamily.WendlandC2, 2.0, 0.05)]
        [TestCase(KernelFamily.WendlandC2, 2.85, 0.0093)]
        [TestCase(KernelFamily.WendlandC2, 3.0, 0.0026)]
        [TestCase(KernelFamily.WendlandC2, 4.0, 0.0012)]
        public void TheKernelRecoversALinearPressureGradientOnTheLattice(KernelFamily kind, double supportRatio, double tolerance)
        {
            double reproduction = SmoothingKernels.LatticeGradientReproduction(kind, 1.0, supportRatio);
            TestContext.Progress.WriteLine($"{kind}, support {supportRatio} spacings: lattice number density " +
                $"{SmoothingKernels.LatticeNumberDensity(kind, 1.0, supportRatio):F5} / s^3, linear-gradient reproduction {reproduction:F4}");
            Assert.That(reproduction, Is.EqualTo(1.0).Within(tolerance));
        }

        const double DepthSpacing = 0.02;

        static Particle[] Spread(Vector3 from, Vector3 to) => new[]
        {
            new Particle(from, Vector3.Zero, 0, 0), new Particle(0.5f * (from + to), Vector3.Zero, 0, 1), new Particle(to, Vector3.Zero, 0, 2),
        };

        [Test]
        public void TheDepthIsTheExtentAlongGravityAndOneSpacing()
        {
            var particles = Spread(new Vector3(-0.3f, -0.1f, 0f), new Vector3(0.3f, 0.2f, 0.05f));
            Assert.That(SpawnLayout.Depth(particles, new Vector3(0f, -9.81f, 0f), DepthSpacing), Is.EqualTo(0.3 + DepthSpacing).Within(1e-6));
            Assert.That(SpawnLayout.Depth(particles, new Vector3(9.81f, 0f, 0f), DepthSpacing), Is.EqualTo(0.6 + DepthSpacing).Within(1e-6));
        }

        [Test]
        public void WithoutGravityTheDepthIsTheLargestExtent()
        {
            var particles = Spread(new Vector3(0f, 0f, -0.2f), new Vector3(0.1f, 0.05f, 0.2f));
            Assert.That(SpawnLayout.Depth(particles, Vector3.Zero, DepthSpacing), Is.EqualTo(0.4 + DepthSpacing).Within(1e-6));
            Assert.That(SpawnLayout.Depth(Array.Empty<Particle>(), Vector3.Zero, DepthSpacing), Is.EqualTo(DepthSpacing));
        }
    }
}
