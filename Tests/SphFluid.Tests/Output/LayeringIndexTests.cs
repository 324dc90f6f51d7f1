using System;
using NUnit.Framework;
using SphFluid.Headless.Output;

namespace SphFluid.Tests.Output
{
    /// <summary>The pair-concordance layering index on particle sets whose answer is known by construction.</summary>
    public sealed class LayeringIndexTests
    {
        [Test]
        public void FourParticlesGiveTheHandCountedValue()
        {
            // heavy at 0, light at 1, heavy at 2, light at 3: pairs (0,1) (0,3) (2,3) ordered, (2,1) inverted.
            var heights = new float[] { 0f, 1f, 2f, 3f };
            var densities = new float[] { 1000f, 900f, 1000f, 900f };

            Assert.That(LayeringIndex.Of(heights, densities), Is.EqualTo(0.5).Within(1e-12));
        }

        [Test]
        public void TwoPerfectLayersScoreOneAndUpsideDownMinusOne()
        {
            var heights = new float[200];
            var ordered = new float[200];
            var inverted = new float[200];
            for (int i = 0; i < 200; i++)
            {
                heights[i] = i * 0.01f;
                ordered[i] = i < 120 ? 1000f : 900f;   // the heavy phase fills the lower 60 %
                inverted[i] = i < 120 ? 900f : 1000f;
            }

            Assert.That(LayeringIndex.Of(heights, ordered), Is.EqualTo(1.0));
            Assert.That(LayeringIndex.Of(heights, inverted), Is.EqualTo(-1.0));
        }

        [Test]
        public void ThreePerfectLayersScoreOneAndReversedMinusOne()
        {
            var heights = new float[300];
            var ordered = new float[300];
            var reversed = new float[300];
            float[] byLayer = { 1200f, 1000f, 800f };
            for (int i = 0; i < 300; i++)
            {
                heights[i] = i * 0.001f;
                ordered[i] = byLayer[i / 100];
                reversed[i] = byLayer[2 - i / 100];
            }

            Assert.That(LayeringIndex.Of(heights, ordered), Is.EqualTo(1.0));
            Assert.That(LayeringIndex.Of(heights, reversed), Is.EqualTo(-1.0));
        }

        [Test]
        public void SwappingTheMiddleAndTopLayersOfThreeScoresOneThird()
        {
            // Layers from the floor up: 1200, 800, 1000 (100 each). Pairs of different density: 3 x 100^2; the
            // 1200/800 and 1200/1000 pairs are ordered, the 800/1000 pairs inverted: (2 - 1) / 3.
            var heights = new float[300];
            var densities = new float[300];
            float[] byLayer = { 1200f, 800f, 1000f };
            for (int i = 0; i < 300; i++)
            {
                heights[i] = i;
                densities[i] = byLayer[i / 100];
            }

            Assert.That(LayeringIndex.Of(heights, densities), Is.EqualTo(1.0 / 3.0).Within(1e-12));
        }

        [TestCase(2)]
        [TestCase(3)]
        public void ARandomMixScoresAboutZero(int phases)
        {
            var random = new Random(7);
            var heights = new float[20000];
            var densities = new float[20000];
            for (int i = 0; i < heights.Length; i++)
            {
                heights[i] = (float)random.NextDouble();
                densities[i] = 800f + 200f * random.Next(phases);
            }

            double index = LayeringIndex.Of(heights, densities);

            // Kendall's statistic of independent samples has a standard deviation of about 0.005 at this size.
            Assert.That(index, Is.InRange(-0.02, 0.02));
        }

        [Test]
        public void PairsAtTheSameHeightAreNeitherOrderedNorInverted()
        {
            var heights = new float[] { 1f, 1f, 2f };
            var densities = new float[] { 1000f, 900f, 900f };

            // (0,1) tied; (0,2) ordered; (1,2) same density, not a pair: 1 / 2.
            Assert.That(LayeringIndex.Of(heights, densities), Is.EqualTo(0.5).Within(1e-12));
        }

        [Test]
        public void TheSortedCountAgreesWithCountingEveryPair()
        {
            // Five phases and heights on a coarse grid, so many pairs tie; checked against the definition itself.
            var random = new Random(11);
            var heights = new float[600];
            var densities = new float[600];
            for (int i = 0; i < heights.Length; i++)
            {
                int phase = random.Next(5);
                densities[i] = 700f + 100f * phase;
                heights[i] = MathF.Round((float)(random.NextDouble() * 0.5 + 0.1 * (4 - phase)) * 20f) / 20f; // heavier lower, on average
            }
            long ordered = 0, inverted = 0, pairs = 0;
            for (int i = 0; i < heights.Length; i++)
                for (int j = i + 1; j < heights.Length; j++)
                {
                    if (densities[i] == densities[j]) continue;
                    pairs++;
                    int heavier = densities[i] > densities[j] ? i : j, lighter = heavier == i ? j : i;
                    if (heights[heavier] < heights[lighter]) ordered++;
                    else if (heights[heavier] > heights[lighter]) inverted++;
                }

            double index = LayeringIndex.Of(heights, densities);

            Assert.That(index, Is.EqualTo((double)(ordered - inverted) / pairs).Within(1e-12));
            Assert.That(index, Is.InRange(0.3, 0.95), "this set is mostly, not perfectly, ordered");
        }

        [Test]
        public void OnePhaseHasNoIndex()
        {
            Assert.That(LayeringIndex.Of(new float[] { 0f, 1f }, new float[] { 1000f, 1000f }), Is.NaN);
            Assert.That(LayeringIndex.Of(new float[0], new float[0]), Is.NaN);
        }
    }
}
