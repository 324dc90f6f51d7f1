using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Output;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// Where the mechanical energy goes that DFSPH loses at a loose density tolerance. On an H200 the study's 1 % rows
    /// lost 1.45 % of the energy in a second, about three times the 0.45 to 0.54 % of the tighter rows (Headless/figures/
    /// OilAndWater-study-h200.md). The spawn explains it. DFSPH spawns on the lattice at rest density, so under gravity
    /// the fluid first settles until the constant-density solve's tolerance holds it. A column compressed by a
    /// fraction e throughout lowers its centre of mass by e, so it gives up e of its potential energy above the floor.
    /// The pressure solve takes that fall's kinetic energy away; there is no elastic store. WCSPH's rows never pay
    /// this: their spawn is already lowered to the Tait compression (HydrostaticSpawn).
    /// <para>OilAndWater's still copy (the oil at the water's rest density, so nothing should move) isolates the
    /// settle. Measured on lavapipe at 4 160 particles, each figure a share of the spawn's potential energy above the
    /// floor (14.08 J): at 1 % the tank lost 1.09 % by 0.05 s, rang back to 0.85 % by 0.083 s and held 1.00 % at 0.3 s.
    /// At 0.01 % it lost 0.11 %, the free surface's own settling: the top layers have fewer neighbours than the bulk,
    /// so their summed density reads as expansion and they sink. So the tolerance's share is 0.89 %, inside the 1 %
    /// that a column compressed by 1 % throughout would give up. The compression the tank is left with gave up 0.65 %
    /// of it (<see cref="CompressionEnergy"/>); by the particles' layer heights in an export, the rest is mostly the top
    /// layers settling further, which their summed density cannot show. Each run counts from its own settled spawn:
    /// the 1 % spawn starts 0.11 % lower, as its settling solves, at a tenth of its tolerance, leave some of the
    /// jitter's packing (FluidSimulation.SettledSpawn). OilAndWater itself shows the same split: 1.09 % and 0.12 % lost
    /// by 0.05 s, then 0.20 % and 0.32 % from there to 1 s (<c>sphfluid simulate Assets/FluidDemo/Scenes/OilAndWater.unity
    /// --solver dfsph --solver-iteration chebyshev --density-tolerance 1 --diagnostics-every 0.05</c>, then the same at
    /// 0.01, on lavapipe; the energy drift is KE + PE against the first line's).</para>
    /// </summary>
    [Category(TestProcesses.LongRuns)]
    public sealed class ToleranceSettleTests
    {
        const int Frames = 18;
        const int SettleFrames = 6;

        /// <summary>What the still copy lost: <see cref="Lost"/> the mechanical energy after each 60 Hz frame (the spawn's
        /// first, 0), <see cref="Compression"/> the potential energy its compression gave up from the spawn to the last
        /// frame (<see cref="CompressionEnergy"/>), both shares of the spawn's potential energy above the floor.</summary>
        sealed record Settle(double[] Lost, double Compression);

        /// <summary>The still copy under DFSPH at <paramref name="tolerance"/> %, its solves iterated by
        /// <paramref name="iteration"/>, for <see cref="Frames"/> frames.</summary>
        static Settle Run(float tolerance, SolverIteration iteration)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            var choice = new SolverChoice { Solver = PressureSolver.Dfsph, Iteration = iteration, DensityTolerance = tolerance };
            Assert.That(choice.ApplyTo(scene, $"DFSPH OilAndWater at {tolerance} %"), Is.Null);
            scene.SpawnBoxes.Single(b => b.Phase.Name == "Oil").Phase.RestDensity = 1000f;
            Assert.That(scene.Validate(), Is.Empty);

            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var gravity = (Vector3)scene.Settings.Gravity;
            var frame = new GravityFrame(scene.Container, gravity);
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            var energies = new double[Frames + 1];
            double potential = 0, compression = 0;
            for (int f = 0; f <= Frames; f++)
            {
                if (f > 0) sim.Step(1f / 60f);
                sim.Particles.GetData(particles);
                energies[f] = FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity);
                if (f == 0)
                    potential = FluidMeasures.Measure(0, particles, ReadOnlySpan<Vector4>.Empty, sim.PhaseRows,
                        scene.Container, gravity, scene.Settings.ParticleSpacing, scene.Settings.SmoothingRadius).PotentialEnergy;
                if (f == 0 || f == Frames)
                {
                    sim.Densities.GetData(densities);
                    double e = CompressionEnergy(particles, densities, sim.PhaseRows, frame, gravity.Length(), scene.Settings.ParticleSpacing);
                    compression = f == 0 ? -e : compression + e;
                }
            }
            Assert.That(sim.ReadDiagnostics().ParticleCount, Is.EqualTo(sim.ParticleCount), "nothing lost");
            var settle = new Settle(energies.Select(e => (energies[0] - e) / potential).ToArray(), compression / potential);
            TestContext.Progress.WriteLine($"DFSPH ({iteration}) still OilAndWater at {tolerance} %: potential energy above the floor " +
                $"{potential:F4} J at the spawn; lost by frame: " + string.Join(" ", settle.Lost.Select(l => $"{100 * l:F3}")) +
                $" %; given up by its compression since the spawn {100 * settle.Compression:F3} %");
            return settle;
        }

        /// <summary>
        /// The potential energy a fluid at rest on the floor gives up by being compressed, J: the compression of the fluid
        /// below each particle lowers it. The fluid is cut into horizontal layers one spacing thick from the floor; a
        /// layer compressed by e (its particles' mean of max(0, 1 - rho0 / rho), the summed density read as a volume)
        /// shortens by e times its thickness, and a particle drops by the shortening of every layer below it and of
        /// its own below it. Expansion counts as none: the free surface's summed density reads the missing fluid above
        /// as expansion that is not there.
        /// </summary>
        static double CompressionEnergy(Particle[] particles, Vector4[] densities, IReadOnlyList<PhaseProperties> phases,
            GravityFrame frame, float g, float spacing)
        {
            int layers = 1 + (int)Math.Floor(frame.Extent / spacing);
            var sum = new double[layers];
            var count = new int[layers];
            int Layer(Particle p) => Math.Clamp((int)Math.Floor(frame.HeightOf(p.Position) / spacing), 0, layers - 1);
            for (int i = 0; i < particles.Length; i++)
            {
                int k = Layer(particles[i]);
                sum[k] += Math.Max(0.0, 1.0 - phases[(int)particles[i].Phase].RestDensity / densities[i].X);
                count[k]++;
            }
            var below = new double[layers + 1]; // shortening of the layers under each layer's bottom, m
            for (int k = 0; k < layers; k++)
                below[k + 1] = below[k] + (count[k] > 0 ? sum[k] / count[k] : 0.0) * spacing;
            double energy = 0;
            foreach (var p in particles)
            {
                int k = Layer(p);
                double within = frame.HeightOf(p.Position) - k * spacing;
                double drop = below[k] + (below[k + 1] - below[k]) * Math.Clamp(within / spacing, 0.0, 1.0);
                energy += phases[(int)p.Phase].ParticleMass * g * drop;
            }
            return energy;
        }

        static Settle? _loose, _incompressible;
        static Settle Loose => _loose ??= Run(1f, SolverIteration.Chebyshev);
        static Settle Incompressible => _incompressible ??= Run(0.01f, SolverIteration.Chebyshev);

        /// <summary>The still tank at 1 % gives up no more than a column compressed by 1 % throughout would, above what
        /// the free surface's own settling costs at 0.01 %, and at least half of it: 0.89 % measured.</summary>
        [Test]
        public void TheLooseToleranceLosesTheEnergyOfItsCompression()
        {
            double share = Loose.Lost[Frames] - Incompressible.Lost[Frames];
            Assert.That(share, Is.LessThanOrEqualTo(0.01), "the tolerance's share of the potential energy");
            Assert.That(share, Is.GreaterThanOrEqualTo(0.005), "the tolerance's share of the potential energy");
        }

        /// <summary>Most of that share is the compression the tank is left with: the potential energy its measured
        /// compression gave up (<see cref="CompressionEnergy"/>) is at least 0.6 of the energy lost and no more than it
        /// (0.73 measured: 0.653 % of 0.891 %). The rest is mostly the top layers settling further, which their summed
        /// density cannot show.</summary>
        [Test]
        public void TheMeasuredCompressionAccountsForMostOfTheLoss()
        {
            double lost = Loose.Lost[Frames] - Incompressible.Lost[Frames];
            double compression = Loose.Compression - Incompressible.Compression;
            Assert.That(compression, Is.InRange(0.6 * lost, lost), "potential energy given up by the measured compression, a share");
        }

        /// <summary>The loss belongs to the tolerance, not to how the solves iterate: under the Jacobi solve the still
        /// tank at 1 % loses the same by 0.3 s (1.000 % against the Chebyshev solve's 1.001 %). At that tolerance and depth
        /// both take Jacobi constant-density steps; only their divergence-free solves differ.</summary>
        [Test]
        public void TheJacobiSolveLosesTheSameAtThatTolerance()
        {
            var jacobi = Run(1f, SolverIteration.Jacobi);
            Assert.That(jacobi.Lost[Frames], Is.EqualTo(Loose.Lost[Frames]).Within(0.001), "energy lost by 0.3 s, a share of the potential energy");
        }

        /// <summary>The loss is the settle's: after the first 0.1 s neither still tank drains energy (0.05 % and 0.01 %
        /// more lost from 0.1 to 0.3 s at 1 % and 0.01 %), so the study's energy drift at a loose tolerance is one step
        /// at the start, not a leak that grows with the simulated time.</summary>
        [Test]
        public void AfterTheSettleNeitherTankDrainsEnergy()
        {
            foreach (var (name, run) in new[] { ("1 %", Loose), ("0.01 %", Incompressible) })
                Assert.That(run.Lost[Frames] - run.Lost[SettleFrames], Is.InRange(-0.001, 0.001), $"{name}: energy lost from 0.1 to 0.3 s");
        }
    }
}
