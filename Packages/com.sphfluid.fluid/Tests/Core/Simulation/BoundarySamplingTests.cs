using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// A sphere's boundary shells are weighted so that a fluid particle resting half a spacing outside the sphere sums
    /// as much boundary (delta, number density) as it would half a spacing from a flat wall of the container: without it
    /// the fluid pressed against a small sphere sank past its surface (BoundarySampling.ConvexWeightFactor).
    /// </summary>
    public sealed class BoundarySamplingTests
    {
        const float Spacing = 0.02f, Support = 0.04f;

        [Test]
        public void AFlatWallNeedsNoCorrection() =>
            Assert.That(BoundarySampling.ConvexWeightFactor(KernelFamily.CubicSpline, 200 * Spacing, Spacing, Support), Is.EqualTo(1.0).Within(0.01));

        [Test]
        public void TheSmallerTheSphereTheHeavierItsShells()
        {
            double small = BoundarySampling.ConvexWeightFactor(KernelFamily.CubicSpline, 2.25 * Spacing, Spacing, Support);
            double larger = BoundarySampling.ConvexWeightFactor(KernelFamily.CubicSpline, 5 * Spacing, Spacing, Support);
            Assert.That(larger, Is.GreaterThan(1.0));
            Assert.That(small, Is.GreaterThan(larger));
        }

        /// <summary>The sampled particles themselves: around the sphere of the sphere-wake scene (R = 2.25 spacings), the boundary
        /// sum half a spacing outside it, averaged over 200 directions, is the flat wall's at half a spacing from a face.</summary>
        [Test]
        public void ASmallSpheresShellsSumAsMuchAsAFlatWall()
        {
            float radius = 2.25f * Spacing;
            var scene = new FluidSceneDescription
            {
                Settings = new FluidSettings { ParticleSpacing = Spacing, SmoothingRadius = Support },
                Container = new ContainerDescription { Size = new Vector3(0.4f, 0.4f, 0.4f) },
                Obstacles = new List<RigidSphere> { new RigidSphere(Vector3.Zero, radius, Vector3.Zero) },
            };
            BoundaryParticle[] all = BoundarySampling.Sample(scene);

            // Half a spacing inside the floor's face, in the middle of the floor (a fluid lattice point).
            double flat = Sum(all, BoundaryParticle.ContainerOwner, new Vector3(0.5f * Spacing, -0.2f + 0.5f * Spacing, 0.5f * Spacing));
            double sphere = 0;
            const int directions = 200;
            double golden = Math.PI * (3.0 - Math.Sqrt(5.0));
            for (int p = 0; p < directions; p++)
            {
                double y = 1.0 - 2.0 * (p + 0.5) / directions, ring = Math.Sqrt(1.0 - y * y);
                var direction = new Vector3((float)(ring * Math.Cos(golden * p)), (float)y, (float)(ring * Math.Sin(golden * p)));
                sphere += Sum(all, 0u, direction * (radius + 0.5f * Spacing));
            }
            sphere /= directions;
            TestContext.Out.WriteLine($"boundary sum half a spacing out: sphere {sphere:F4}, flat wall {flat:F4}; " +
                $"curvature weight factor {BoundarySampling.ConvexWeightFactor(KernelFamily.CubicSpline, radius, Spacing, Support):F3}");
            Assert.That(sphere, Is.EqualTo(flat).Within(0.03 * flat));
        }

        /// <summary>The container's walls stand in for the fluid lattice beyond them: a fluid lattice filling the container
        /// sums, at a particle in a corner, on an edge and on a face, the lattice's own number density, whatever the kernel
        /// and support. With the walls weighed V_b delta0 (the cell's volume times the lattice sum; BoundarySampling) the
        /// Wendland C2 cases read over it in the corner by 1.13 % at 2 spacings, 0.93 % at 2.3, 0.22 % at 2.85 and 0.04 % at 4,
        /// and a DFSPH tank at rest lifted its fluid. (1e-4: the positions are single precision.)</summary>
        [TestCase(KernelFamily.CubicSpline, 2.0)]
        [TestCase(KernelFamily.WendlandC2, 2.0)]
        [TestCase(KernelFamily.WendlandC2, 2.3)]
        [TestCase(KernelFamily.WendlandC2, 2.85)]
        [TestCase(KernelFamily.WendlandC2, 4.0)]
        public void AFluidLatticeBesideTheWallsSumsTheLatticeNumberDensity(KernelFamily kind, double supportRatio)
        {
            const int cells = 8;
            float support = (float)(supportRatio * Spacing), size = cells * Spacing;
            var scene = new FluidSceneDescription
            {
                Settings = new FluidSettings { ParticleSpacing = Spacing, SmoothingRadius = support, SmoothingKernel = kind },
                Container = new ContainerDescription { Size = new Vector3(size, size, size) },
            };
            BoundaryParticle[] walls = BoundarySampling.Sample(scene);
            double delta0 = SmoothingKernels.LatticeNumberDensity(kind, Spacing, support);
            foreach (var (i, j, k) in new[] { (0, 0, 0), (cells / 2, 0, 0), (cells / 2, 0, cells / 2) })
            {
                Vector3 at = LatticePoint(i, j, k, size);
                double sum = 0;
                for (int a = 0; a < cells; a++)
                for (int b = 0; b < cells; b++)
                for (int c = 0; c < cells; c++)
                    sum += SmoothingKernels.Value(kind, Vector3.Distance(LatticePoint(a, b, c, size), at), support);
                foreach (var wall in walls)
                    sum += wall.Weight * SmoothingKernels.Value(kind, Vector3.Distance(wall.Position, at), support);
                Assert.That(sum / delta0 - 1.0, Is.EqualTo(0.0).Within(1e-4), $"{kind} at {supportRatio} spacings, lattice particle ({i}, {j}, {k})");
            }
        }

        /// <summary>DFSPH's wall constraint counts a wall particle's own body at rest (BoundarySampling.OwnNumberDensities):
        /// far from any curvature a sphere's outermost shell reads as the container's top wall layer does, delta0 less the
        /// fluid lattice beyond it, and its next shell, which fluid on the lattice cannot reach at 2 spacings, the whole delta0.</summary>
        [TestCase(KernelFamily.CubicSpline, 2.0)]
        [TestCase(KernelFamily.WendlandC2, 2.85)]
        public void ALargeSpheresShellsCountThemselvesAsAFlatWallDoes(KernelFamily kind, double supportRatio)
        {
            float support = (float)(supportRatio * Spacing);
            var scene = SphereScene(kind, support, 60 * Spacing);
            BoundaryParticle[] all = BoundarySampling.Sample(scene);
            float[] own = BoundarySampling.OwnNumberDensities(scene, all);
            double delta0 = SmoothingKernels.LatticeNumberDensity(kind, Spacing, support);
            double flat = delta0 - SmoothingKernels.FlatWallNumberDensity(kind, Spacing, support);
            double outer = OwnAtDepth(scene, all, own, 0.5f * Spacing);
            TestContext.Out.WriteLine($"{kind} at {supportRatio} spacings: outer shell {outer / delta0:F4} delta0, flat wall {flat / delta0:F4} delta0");
            Assert.That(outer / flat, Is.EqualTo(1.0).Within(0.005));
            if (supportRatio <= 2.0)
                Assert.That(OwnAtDepth(scene, all, own, 1.5f * Spacing) / delta0, Is.EqualTo(1.0).Within(1e-5));
        }

        /// <summary>The container's walls are summed on the GPU with every other wall (WallNumberDensity): their own part is 0.</summary>
        [Test]
        public void TheContainersWallsCountNothingOfTheirOwn()
        {
            var scene = SphereScene(KernelFamily.CubicSpline, Support, 3 * Spacing);
            BoundaryParticle[] all = BoundarySampling.Sample(scene);
            float[] own = BoundarySampling.OwnNumberDensities(scene, all);
            Assert.That(own.Length, Is.EqualTo(all.Length));
            for (int b = 0; b < all.Length; b++)
                if (all[b].Owner == BoundaryParticle.ContainerOwner)
                    Assert.That(own[b], Is.EqualTo(0f));
        }

        /// <summary>Why a sphere's own shells are not summed for its constraint: around the sphere-wake scene's sphere (3.5
        /// spacings), fluid spawned on the lattice outside it (more than half a spacing from its surface, as SpawnLayout
        /// leaves it) gives the outer shell's particles, with the shells summed, more than rest density (the test prints how
        /// much), which no motion of the fluid can undo; with the shells counted at rest, every particle reads at most delta0.</summary>
        [Test]
        public void FluidSpawnedAroundASphereLeavesItsShellsAtMostAtRest()
        {
            float radius = 3.46f * Spacing;
            var scene = SphereScene(KernelFamily.CubicSpline, Support, radius);
            BoundaryParticle[] all = BoundarySampling.Sample(scene);
            float[] own = BoundarySampling.OwnNumberDensities(scene, all);
            double delta0 = SmoothingKernels.LatticeNumberDensity(KernelFamily.CubicSpline, Spacing, Support);
            var fluid = new List<Vector3>();
            var offset = new Vector3(0.3f, 0.1f, 0.7f) * Spacing;
            for (int i = -8; i <= 8; i++)
            for (int j = -8; j <= 8; j++)
            for (int k = -8; k <= 8; k++)
            {
                var x = new Vector3(i, j, k) * Spacing + offset;
                if (x.Length() >= radius + 0.5f * Spacing) fluid.Add(x);
            }
            double summedLeast = double.MaxValue, summedMost = 0, countedMost = 0;
            for (int b = 0; b < all.Length; b++)
            {
                if (all[b].Owner != 0u || all[b].Position.Length() < radius - Spacing) continue;
                double fluidSum = 0;
                foreach (var x in fluid) fluidSum += SmoothingKernels.Value(KernelFamily.CubicSpline, Vector3.Distance(x, all[b].Position), Support);
                double summed = (fluidSum + Sum(all, 0u, all[b].Position)) / delta0;
                summedLeast = Math.Min(summedLeast, summed);
                summedMost = Math.Max(summedMost, summed);
                countedMost = Math.Max(countedMost, (fluidSum + own[b]) / delta0);
            }
            TestContext.Out.WriteLine($"outer shell with fluid spawned around it: shells summed {summedLeast:F3} to {summedMost:F3} delta0, counted at rest at most {countedMost:F3} delta0");
            Assert.That(summedLeast, Is.GreaterThan(1.02));
            Assert.That(countedMost, Is.LessThanOrEqualTo(1.0));
        }

        static FluidSceneDescription SphereScene(KernelFamily kind, float support, float radius) => new FluidSceneDescription
        {
            Settings = new FluidSettings { ParticleSpacing = Spacing, SmoothingRadius = support, SmoothingKernel = kind },
            Container = new ContainerDescription { Size = new Vector3(1f, 1f, 1f) * (2f * radius + 10f * Spacing) },
            Obstacles = new List<RigidSphere> { new RigidSphere(Vector3.Zero, radius, Vector3.Zero) },
        };

        /// <summary>The own number density of the sphere's particles at this depth below its surface (one value per shell).</summary>
        static double OwnAtDepth(FluidSceneDescription scene, BoundaryParticle[] all, float[] own, float depth)
        {
            float radius = scene.Obstacles[0].Radius;
            for (int b = 0; b < all.Length; b++)
                if (all[b].Owner == 0u && Math.Abs(all[b].Position.Length() - (radius - depth)) < 0.01f * Spacing)
                    return own[b];
            throw new InvalidOperationException($"no shell at depth {depth}");
        }

        static Vector3 LatticePoint(int i, int j, int k, float size) =>
            new Vector3(-0.5f * size + (i + 0.5f) * Spacing, -0.5f * size + (j + 0.5f) * Spacing, -0.5f * size + (k + 0.5f) * Spacing);

        static double Sum(BoundaryParticle[] particles, uint owner, Vector3 at)
        {
            double sum = 0;
            foreach (var b in particles)
                if (b.Owner == owner)
                    sum += b.Weight * SmoothingKernels.Value(KernelFamily.CubicSpline, Vector3.Distance(b.Position, at), Support);
            return sum;
        }
    }
}
