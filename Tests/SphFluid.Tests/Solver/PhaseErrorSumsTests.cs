using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// The per-phase error sums of DFSPH's error pass (DivergenceFreeConvergence.hlsl's StoreGroupErrors), on which each solve stops.
    /// One fold sums up to sixteen phases; a scene with more takes a second. A column of twenty layers of the same water,
    /// each its own phase, against the same column as one phase: the same particles make the same errors, so each group's
    /// sums over the twenty phases must add up to its one-phase sum, a phase the group holds no particle of must sum to
    /// zero, and the phases of the second fold must carry their share.
    /// </summary>
    public sealed class PhaseErrorSumsTests
    {
        const int Layers = 20, FirstFold = 16;

        static FluidSceneDescription Column(bool phasePerLayer)
        {
            var settings = SolverScenes.Coarse(0.02f);
            settings.PressureSolver = PressureSolver.Dfsph;
            settings.MaxSolverIterations = 1;
            settings.XsphEpsilon = 0f;
            float spacing = settings.ParticleSpacing, height = Layers * spacing;
            var boxes = Enumerable.Range(0, Layers).Select(k =>
            {
                var water = SolverScenes.Water(0.1f);
                if (phasePerLayer) water.Name = $"Water {k}";
                return SolverScenes.Box($"Layer {k}", water, new Vector3(0f, -0.5f * height + (k + 0.5f) * spacing, 0f),
                    new Vector3(0.16f, spacing, 0.16f), seed: k + 1);
            }).ToArray();
            return SolverScenes.Scene(settings, new Vector3(0.16f, height, 0.16f), boxes);
        }

        [TestCase(1)]
        [TestCase(8)]
        public void TwentyPhasesSumToWhatOnePhaseSums(int lanes)
        {
            var rng = new SolverScenes.Rng(77);
            using var one = new FluidSimulation(GpuTestDevice.Shared, Column(false)) { LanesPerParticle = lanes };
            using var twenty = new FluidSimulation(GpuTestDevice.Shared, Column(true)) { LanesPerParticle = lanes };
            Assert.That(one.PhaseRows.Count, Is.EqualTo(1));
            Assert.That(twenty.PhaseRows.Count, Is.EqualTo(Layers));
            var spawned = new Particle[twenty.ParticleCount];
            twenty.Particles.GetData(spawned);
            for (int i = 0; i < spawned.Length; i++)
                spawned[i].Velocity = rng.InBox(new Vector3(0.3f)); // every error pass has compressing particles to sum
            twenty.SetParticles(spawned);
            one.SetParticles(spawned.Select(p => new Particle(p.Position, p.Velocity, 0, p.Id)).ToArray());
            const float dt = 0.001f;
            one.StepFixed(1, dt);
            twenty.StepFixed(1, dt);

            var sortedOne = new Particle[one.ParticleCount];
            var sorted = new Particle[twenty.ParticleCount];
            one.Particles.GetData(sortedOne);
            twenty.Particles.GetData(sorted);
            Assert.That(sorted.Select(p => p.Id), Is.EqualTo(sortedOne.Select(p => p.Id)), "both columns sorted alike");
            int groups = twenty.SolverPartialGroups;
            Assert.That(one.SolverPartialGroups, Is.EqualTo(groups));
            var sumsOne = new float[one.SolverPartials.Count];
            var sums = new float[twenty.SolverPartials.Count];
            one.SolverPartials.GetData(sumsOne);
            twenty.SolverPartials.GetData(sums);

            // The phases whose particles each group's threads hold (lanes threads a particle, ParticleThreads a group).
            var held = new bool[Layers, groups];
            for (int i = 0; i < sorted.Length; i++)
                held[sorted[i].Phase, i * lanes / (int)FluidSimulation.ParticleThreads] = true;
            double secondFold = 0;
            for (int g = 0; g < groups; g++)
            {
                double total = 0;
                for (int k = 0; k < Layers; k++)
                {
                    float sum = sums[k * groups + g];
                    if (!held[k, g])
                        Assert.That(sum, Is.EqualTo(0f), $"group {g}: phase {k}, of which it holds no particle");
                    total += sum;
                    if (k >= FirstFold) secondFold += sum;
                }
                Assert.That(sumsOne[g], Is.GreaterThan(0f), $"group {g}: some particle compresses");
                Assert.That(total, Is.EqualTo(sumsOne[g]).Within(1e-3).Percent, $"group {g}: its twenty phases' sums against its one");
            }
            TestContext.Progress.WriteLine($"{lanes} lane(s), {groups} groups: phases {FirstFold} to {Layers - 1} sum {secondFold:G4} of {sumsOne.Take(groups).Sum():G4}");
            Assert.That(secondFold, Is.GreaterThan(0.0), "the phases past the first fold carry their errors");
        }
    }
}
