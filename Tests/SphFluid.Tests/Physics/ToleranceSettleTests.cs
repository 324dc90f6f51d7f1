using System;
using System.Linq;
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
    /// lost 1.45 % of the energy in a second, three times the 0.45 % of the tighter rows (Headless/figures/
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
    /// that a column compressed by 1 % throughout would give up, and close to the 0.9 % of the tolerance at which the
    /// solve stops on its prediction (FluidSimulation.DensityPredictionMargin). Each run counts from its own settled
    /// spawn: the 1 % spawn starts 0.11 % lower, as its settling solves, at a tenth of its tolerance, leave some of the
    /// jitter's packing (FluidSimulation.SettledSpawn). OilAndWater itself shows the same split: 1.09 % and 0.12 % lost
    /// by 0.05 s, then 0.20 % and 0.32 % from there to 1 s (<c>sphfluid simulate Assets/FluidDemo/Scenes/OilAndWater.unity
    /// --solver dfsph --solver-iteration chebyshev --density-tolerance 1 --diagnostics-every 0.05</c>, then the same at
    /// 0.01, on lavapipe; the energy drift is KE + PE against the first line's).</para>
    /// </summary>
    public sealed class ToleranceSettleTests
    {
        const int Frames = 18;
        const int SettleFrames = 6;

        /// <summary>The still copy under DFSPH at <paramref name="tolerance"/> %, its solves iterated by
        /// <paramref name="iteration"/>: the mechanical energy it has lost after each 60 Hz frame (the spawn's first, 0),
        /// as shares of the spawn's potential energy above the floor.</summary>
        static double[] EnergyLost(float tolerance, SolverIteration iteration)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"), RunnerPaths.Project).Description;
            var choice = new SolverChoice { Solver = PressureSolver.Dfsph, Iteration = iteration, DensityTolerance = tolerance };
            Assert.That(choice.ApplyTo(scene, $"DFSPH OilAndWater at {tolerance} %"), Is.Null);
            scene.SpawnBoxes.Single(b => b.Phase.Name == "Oil").Phase.RestDensity = 1000f;
            Assert.That(scene.Validate(), Is.Empty);

            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var gravity = (System.Numerics.Vector3)scene.Settings.Gravity;
            var particles = new Particle[sim.ParticleCount];
            var energies = new double[Frames + 1];
            double potential = 0;
            for (int frame = 0; frame <= Frames; frame++)
            {
                if (frame > 0) sim.Step(1f / 60f);
                sim.Particles.GetData(particles);
                energies[frame] = FluidEnergy.Mechanical(particles, sim.PhaseRows, gravity);
                if (frame == 0)
                    potential = FluidMeasures.Measure(0, particles, ReadOnlySpan<System.Numerics.Vector4>.Empty, sim.PhaseRows,
                        scene.Container, gravity, scene.Settings.ParticleSpacing, scene.Settings.SmoothingRadius).PotentialEnergy;
            }
            Assert.That(sim.ReadDiagnostics().ParticleCount, Is.EqualTo(sim.ParticleCount), "nothing lost");
            var lost = energies.Select(e => (energies[0] - e) / potential).ToArray();
            TestContext.Progress.WriteLine($"DFSPH ({iteration}) still OilAndWater at {tolerance} %: potential energy above the floor " +
                $"{potential:F4} J at the spawn; lost by frame: " + string.Join(" ", lost.Select(l => $"{100 * l:F3}")) + " %");
            return lost;
        }

        static double[]? _loose, _incompressible;
        static double[] Loose => _loose ??= EnergyLost(1f, SolverIteration.Chebyshev);
        static double[] Incompressible => _incompressible ??= EnergyLost(0.01f, SolverIteration.Chebyshev);

        /// <summary>The still tank at 1 % gives up no more than a column compressed by 1 % throughout would, above what
        /// the free surface's own settling costs at 0.01 %, and at least half of it: the loss is the tolerance's
        /// compression, 0.89 % measured.</summary>
        [Test]
        public void TheLooseToleranceLosesTheEnergyOfItsCompression()
        {
            double share = Loose[Frames] - Incompressible[Frames];
            Assert.That(share, Is.LessThanOrEqualTo(0.01), "the tolerance's share of the potential energy");
            Assert.That(share, Is.GreaterThanOrEqualTo(0.005), "the tolerance's share of the potential energy");
        }

        /// <summary>The loss belongs to the tolerance, not to how the solves iterate: under the Jacobi solve the still
        /// tank at 1 % loses the same by 0.3 s (1.000 % against the Chebyshev solve's 1.001 %). At that tolerance and depth
        /// both take Jacobi constant-density steps; only their divergence-free solves differ.</summary>
        [Test]
        public void TheJacobiSolveLosesTheSameAtThatTolerance()
        {
            var jacobi = EnergyLost(1f, SolverIteration.Jacobi);
            Assert.That(jacobi[Frames], Is.EqualTo(Loose[Frames]).Within(0.001), "energy lost by 0.3 s, a share of the potential energy");
        }

        /// <summary>The loss is the settle's: after the first 0.1 s neither still tank drains energy (0.05 % and 0.01 %
        /// more lost from 0.1 to 0.3 s at 1 % and 0.01 %), so the study's energy drift at a loose tolerance is one step
        /// at the start, not a leak that grows with the simulated time.</summary>
        [Test]
        public void AfterTheSettleNeitherTankDrainsEnergy()
        {
            foreach (var (name, lost) in new[] { ("1 %", Loose), ("0.01 %", Incompressible) })
                Assert.That(lost[Frames] - lost[SettleFrames], Is.InRange(-0.001, 0.001), $"{name}: energy lost from 0.1 to 0.3 s");
        }
    }
}
