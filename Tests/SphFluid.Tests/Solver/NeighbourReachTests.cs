using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Sorting;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// The neighbour walk (the 5 x 5 x 5 cells of h/2 about a particle's own, SphNeighbourhood.hlsl) must find every particle within h:
    /// the lists FindNeighbours makes from it hold exactly the fluid and wall particles a search of all pairs finds. The
    /// container is rotated (the grid's cells are not the world's axes) and holds a sphere, and the particles stand off
    /// the lattice, some of them in pairs across a cell's faces, edges and corners, where a walk that reached one cell
    /// too few, or a grid whose transform rounded a particle into the wrong cell, would lose a neighbour. DFSPH's lists
    /// are also found in eight lanes an owner, as on a GPU's small scenes, and the fluid is also held in one corner of a
    /// large container, where a wall particle that wrongly learned it had no fluid in reach would lose its neighbours.
    /// </summary>
    public sealed class NeighbourReachTests
    {
        // Pairs this close to h, relative in r^2, may round either way between the GPU and the CPU.
        const float RoundingBand = 1e-5f;

        [TestCase(PressureSolver.Wcsph, 1, false, TestName = "TheWalkFindsEveryPairWithinTheSupport_GridWalkOrder")]
        [TestCase(PressureSolver.Dfsph, 1, false, TestName = "TheWalkFindsEveryPairWithinTheSupport_DfsphOrder")]
        [TestCase(PressureSolver.Dfsph, 8, false, TestName = "TheWalkFindsEveryPairWithinTheSupport_DfsphOrderInEightLanes")]
        [TestCase(PressureSolver.Wcsph, 1, true, TestName = "TheWalkFindsEveryPairWithinTheSupport_GridWalkOrder_FluidInACorner")]
        [TestCase(PressureSolver.Dfsph, 8, true, TestName = "TheWalkFindsEveryPairWithinTheSupport_DfsphOrderInEightLanes_FluidInACorner")]
        public void TheWalkFindsEveryPairWithinTheSupport(PressureSolver solver, int lanes, bool fluidInACorner)
        {
            var scene = SolverKernelTests.RandomScene(true, false, false, true);
            scene.Settings.PressureSolver = solver;
            // Room to scatter the particles at about the lattice's density (no list overflows): a container 1.25 times the
            // scene's, or, for a corner, one 2.5 times it whose low corner's eighth they fill, so that most wall particles
            // have no fluid in reach and search nothing (FluidWithinReach, SphNeighbourhood.hlsl).
            var region = scene.Container.Size * 1.25f;
            scene.Container.Size = fluidInACorner ? 2f * region : region;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene) { LanesPerParticle = lanes };
            Assert.That(sim.ReadsNeighbourLists, Is.True);
            var input = Scattered(scene, region, sim.ParticleCount);
            PlacePairsAcrossCellBoundaries(input, scene);
            sim.SetParticles(input);

            var fluid = new Particle[sim.ParticleCount];
            var walls = new BoundaryParticle[sim.BoundaryCount];
            var counts = new uint[sim.ParticleCount + sim.BoundaryCount];
            sim.Particles.GetData(fluid);
            sim.BoundaryParticles.GetData(walls);
            sim.NeighbourCounts.GetData(counts);
            float h2 = scene.Settings.SmoothingRadius * scene.Settings.SmoothingRadius;

            int pairs = 0, wallPairs = 0, lonelyWalls = 0;
            for (int owner = 0; owner < counts.Length; owner++)
            {
                Assert.That(counts[owner], Is.Not.EqualTo(uint.MaxValue), $"owner {owner} overflows its list");
                bool fluidOwner = owner < fluid.Length;
                var x = fluidOwner ? fluid[owner].Position : walls[owner - fluid.Length].Position;
                var (fluidLow, fluidHigh) = Within(x, fluid.Length, j => fluid[j].Position, h2);
                var (wallLow, wallHigh) = fluidOwner ? Within(x, walls.Length, b => walls[b].Position, h2) : (0, 0);
                uint found = counts[owner] & 0xFFFFu, foundWalls = counts[owner] >> 16;
                Assert.That((int)found, Is.InRange(fluidLow, fluidHigh), $"fluid neighbours of owner {owner}");
                Assert.That((int)foundWalls, Is.InRange(wallLow, wallHigh), $"wall neighbours of owner {owner}");
                pairs += (int)found;
                wallPairs += (int)foundWalls;
                if (!fluidOwner && counts[owner] == 0) lonelyWalls++;
            }
            TestContext.Progress.WriteLine($"{solver} in {lanes} lane(s): {counts.Length} owners, {pairs} fluid and {wallPairs} wall neighbours, " +
                $"as a search of all pairs finds; {lonelyWalls} of {walls.Length} wall particles with no fluid neighbour");
            Assert.That(wallPairs, Is.GreaterThan(fluid.Length / (fluidInACorner ? 4 : 1)), "the particles reach the container's and the sphere's walls");
            if (fluidInACorner)
                Assert.That(lonelyWalls, Is.GreaterThan(walls.Length / 2), "most of the large container's walls have no fluid neighbour");
        }

        /// <summary>The spawn's particles moved to independent uniform places (outside the sphere) in the box of size
        /// <paramref name="region"/> at the container's low corner: pairs at every distance and every place in a cell,
        /// which a lattice, even a jittered one, does not give.</summary>
        static Particle[] Scattered(FluidSceneDescription scene, Vector3 region, int count)
        {
            var rng = new SolverScenes.Rng(11);
            var spawn = SpawnLayout.Generate(scene);
            var inner = 0.5f * region - new Vector3(scene.Settings.ParticleSpacing);
            var centre = 0.5f * (region - scene.Container.Size); // the region's centre, in the container's frame
            var sphere = scene.Obstacles[0];
            var particles = new Particle[count];
            for (int i = 0; i < count; i++)
            {
                Vector3 position;
                do position = scene.Container.Position + Vector3.Transform(centre + rng.InBox(inner), scene.Container.Rotation);
                while ((position - sphere.Center).Length() < sphere.Radius + scene.Settings.ParticleSpacing);
                particles[i] = new Particle(position, Vector3.Zero, spawn[i].Phase, spawn[i].Id);
            }
            return particles;
        }

        /// <summary>
        /// The first particles in pairs that only a walk reaching its full support finds: in each pair the owner stands
        /// 0.9968 h from the nearest face, edge or corner of the cell the walk's reach away (two cells of h/2), and its
        /// partner 0.9985 h away in that cell, beyond it.
        /// </summary>
        static void PlacePairsAcrossCellBoundaries(Particle[] particles, FluidSceneDescription scene)
        {
            var c = scene.Container;
            var grid = CellGrid.ForSupport(c.Position, c.Rotation, c.Size, scene.Settings.SmoothingRadius);
            const int reach = CellGrid.CellsPerSupport; // cells to h, and so the cells the walk reaches each side
            const int first = CellGrid.MarginCells + reach; // owners whose partners stay within the container
            // Owners a support apart, as many per h^3 as the walk's lists hold with the scattered particles around them.
            Assert.That(Matrix4x4.Invert(Matrix4x4.Transpose(grid.WorldToGrid), out var gridToWorld), Is.True);
            var directions = new[]
            {
                new Vector3(0, -1, 0), new Vector3(0, 0, 1), new Vector3(-1, 0, 0), // faces
                new Vector3(0, -1, -1), new Vector3(-1, 1, 0), new Vector3(1, 0, -1), // edges
                new Vector3(-1, -1, -1), new Vector3(1, 1, 1), new Vector3(1, -1, 1), // corners
            };
            int pairs = 0;
            for (int z = first; z <= first + reach; z += reach)
            for (int y = first; y <= first + 2 * reach; y += reach)
            for (int x = first; x <= first + 2 * reach; x += reach, pairs++)
            {
                var u = directions[pairs % directions.Length];
                var axes = new Vector3(MathF.Abs(u.X), MathF.Abs(u.Y), MathF.Abs(u.Z));
                // To the cell the reach away, along each axis of u, in cells; less the reach's cells but one between.
                float gap = reach * 0.9968f / MathF.Sqrt(axes.X + axes.Y + axes.Z) - (reach - 1);
                // In the cell: gap from the face u points through, the middle along the axes u does not cross.
                var inCell = new Vector3(0.5f) * (Vector3.One - axes) + axes * (0.5f * (Vector3.One + u) - u * gap);
                var owner = new Vector3(x, y, z) + inCell;
                var partner = owner + reach * 0.9985f * Vector3.Normalize(u);
                particles[2 * pairs] = Moved(particles[2 * pairs], Vector3.Transform(owner, gridToWorld));
                particles[2 * pairs + 1] = Moved(particles[2 * pairs + 1], Vector3.Transform(partner, gridToWorld));
            }
            Assert.That(2 * pairs, Is.LessThan(particles.Length));
        }

        static Particle Moved(Particle p, Vector3 position) => new Particle(position, Vector3.Zero, p.Phase, p.Id);

        /// <summary>How many of <paramref name="count"/> particles lie within h of <paramref name="x"/>, at least and at most
        /// (those within the rounding band of h counted only in the second).</summary>
        static (int low, int high) Within(Vector3 x, int count, System.Func<int, Vector3> position, float h2)
        {
            int low = 0, high = 0;
            for (int j = 0; j < count; j++)
            {
                var r = x - position(j);
                float r2 = Vector3.Dot(r, r);
                if (r2 < h2 * (1f - RoundingBand)) low++;
                if (r2 < h2 * (1f + RoundingBand)) high++;
            }
            return (low, high);
        }
    }
}
