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
