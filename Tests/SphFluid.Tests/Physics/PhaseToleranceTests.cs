using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// DFSPH's density tolerance holds for every phase, not only on average over all particles (issue #8: "DFSPH at
    /// 0.1 % average density error", per phase as the study reports it). A tank of water 32 spacings deep whose bottom two
    /// spacings are a phase of their own, the same water by another name: the deepest layer is the most compressed, and
    /// while the solves stopped on the average over all particles it sat at 0.163 % under a 0.1 % tolerance (the water
    /// above at 0.092 %); held per phase, 0.097 % (the water 0.085 %). Averaged over every third frame from 0.5 to 1 s.
    /// </summary>
    public sealed class PhaseToleranceTests
    {
        const float Spacing = 0.0125f, Depth = 0.4f, Layer = 2f * Spacing, Tolerance = 0.1f;

        double[] _averageCompression = new double[0];
        string[] _names = new string[0];
        float[] _inverseCounts = new float[0];
        DiagnosticsReport _last = null!;

        [OneTimeSetUp]
        public void SettleTheLayeredTank()
        {
            var settings = new FluidSettings
            {
                ParticleSpacing = Spacing, SmoothingRadius = 2f * Spacing, MaxSubsteps = 200, PressureSolver = PressureSolver.Dfsph,
                DensityTolerance = Tolerance, SolverIteration = SolverIteration.Chebyshev,
            };
            var container = new Vector3(0.25f, Depth + 0.1f, 6 * Spacing);
            float floor = -0.5f * container.Y;
            var bottom = SolverScenes.Water(viscosity: 0.001f);
            bottom.Name = "Bottom";
            var scene = SolverScenes.Scene(settings, container,
                SolverScenes.Box("Bottom", bottom, new Vector3(0f, floor + 0.5f * Layer, 0f), new Vector3(container.X, Layer, container.Z)),
                SolverScenes.Box("Water", SolverScenes.Water(viscosity: 0.001f), new Vector3(0f, floor + Layer + 0.5f * (Depth - Layer), 0f),
                    new Vector3(container.X, Depth - Layer, container.Z)));
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            _inverseCounts = sim.PhaseRows.Select(row => row.InverseParticleCount).ToArray();
            int frame = 0, samples = 0;
            while (sim.SimulatedTime < 1.0 - 1e-6)
            {
                sim.Step(1f / 60f);
                if (++frame < 30 || frame % 3 != 0) continue;
                _last = sim.ReadDiagnostics();
                if (samples++ == 0)
                {
                    _averageCompression = new double[_last.Phases.Count];
                    _names = _last.Phases.Select(p => p.Name).ToArray();
                }
                for (int k = 0; k < _last.Phases.Count; k++) _averageCompression[k] += _last.Phases[k].AverageDensityError;
            }
            for (int k = 0; k < _averageCompression.Length; k++) _averageCompression[k] /= samples;
            TestContext.Progress.WriteLine($"Layered tank, N={sim.ParticleCount}, sub-step {1000 * sim.LastStep.TimeStep:F2} ms, average compression from 0.5 to 1 s: " +
                string.Join(", ", _names.Select((n, k) => $"{n} {100 * _averageCompression[k]:F4} %")) +
                $"; iterations a sub-step at 1 s: {_last.DensitySolveIterations:F2} + {_last.DivergenceSolveIterations:F2}");
        }

        [Test]
        public void EveryPhaseIsCompressedByAtMostTheTolerance()
        {
            Assert.That(_names, Is.EqualTo(new[] { "Bottom", "Water" }));
            for (int k = 0; k < _names.Length; k++)
                Assert.That(_averageCompression[k], Is.LessThanOrEqualTo(0.01 * Tolerance), $"{_names[k]}'s average compression");
        }

        /// <summary>The solves weigh each phase's error sum by its own particle count (the phase table's
        /// InverseParticleCount): 240 particles in the bottom layer, 3 600 above.</summary>
        [Test]
        public void EachPhaseIsAveragedOverItsOwnParticles()
        {
            Assert.That(_last.Phases.Select(p => p.Count), Is.EqualTo(new[] { 240, 3600 }));
            for (int k = 0; k < _inverseCounts.Length; k++)
                Assert.That(_inverseCounts[k], Is.EqualTo(1.0 / _last.Phases[k].Count).Within(1e-9), _names[k]);
        }

        [Test]
        public void NothingIsLostOrClamped()
        {
            Assert.That(_last.NanCount, Is.EqualTo(0));
            Assert.That(_last.OutsideCount, Is.EqualTo(0));
            Assert.That(_last.ClampHits, Is.EqualTo(0));
        }
    }
}
