using System;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The resting tank of <see cref="RestingTankTests"/> under DFSPH (issue #8): at a 0.1 % density tolerance the settled
    /// tank's average compression must stay within 0.1 %, at a sub-step at least five times WCSPH's at the same resolution
    /// (DFSPH's step is bounded by the flow speed, WCSPH's by the speed of sound), and its pressure must hold the water up
    /// as hydrostatics says, measured at a tighter tolerance (<see cref="HydrostaticTolerance"/>).
    /// </summary>
    [TestFixture(SolverIteration.Jacobi)]
    [TestFixture(SolverIteration.Chebyshev)]
    public sealed class DivergenceFreeTankTests
    {
        readonly SolverIteration _iteration;

        public DivergenceFreeTankTests(SolverIteration iteration) => _iteration = iteration;

        const float Spacing = 0.025f, Floor = -0.2f;
        const double RhoG = RestingTankTests.RestDensity * 9.81;
        double _averageError, _dfsphStep, _wcsphStep, _densityIterations, _divergenceIterations, _divergenceError, _spawned, _height;
        double _densitySolveGradient, _pressureGradient;
        DiagnosticsReport _report;

        /// <summary>The density tolerance, %, of the run whose pressure is fitted. Each sub-step's solves correct up to the
        /// tolerance's compression within the step, so the pressure they apply scatters by about rho0 (tolerance s / dt^2)
        /// from its mean: at 0.1 % here (s 25 mm, dt 4.17 ms) 15 % of rho0 g. The half-second means then scatter from -9.7 %
        /// to -2.4 % over three jitter seeds (and from -0.6 % to +7.2 % over the next second), so a 3 % bound on them passed
        /// or failed by the spawn's seed. At 0.01 % the same means lie within -0.4 % and -1.3 % for every seed
        /// (<see cref="DivergenceFreeTankScatterProbe"/>).</summary>
        public const float HydrostaticTolerance = 0.01f;

        [OneTimeSetUp]
        public void SettleOneSecond()
        {
            using (var wcsph = new FluidSimulation(GpuTestDevice.Unvalidated, RestingTankTests.Tank(Spacing)))
            {
                wcsph.Step(1f / 60f);
                _wcsphStep = wcsph.LastStep.TimeStep;
            }
            var scene = RestingTankTests.Tank(Spacing);
            scene.Settings.PressureSolver = PressureSolver.Dfsph;
            scene.Settings.DensityTolerance = 0.1f;
            scene.Settings.SolverIteration = _iteration;
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            _spawned = TankMeasures.ColumnHeight(particles, Floor);
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
            sim.Particles.GetData(particles);
            _height = TankMeasures.ColumnHeight(particles, Floor);
            _report = sim.ReadDiagnostics();
            _averageError = _report.Phases[0].AverageDensityError;
            _densityIterations = _report.DensitySolveIterations;
            _divergenceIterations = _report.DivergenceSolveIterations;
            _divergenceError = _report.DivergenceError;
            scene.Settings.DensityTolerance = HydrostaticTolerance;
            (_pressureGradient, _densitySolveGradient) = PressureGradients(scene);
            TestContext.Progress.WriteLine($"DFSPH resting tank ({_iteration}), N={sim.ParticleCount}: average compression {100 * _averageError:F4} %, " +
                $"sub-step {1000 * _dfsphStep:F3} ms vs WCSPH {1000 * _wcsphStep:F3} ms ({_dfsphStep / _wcsphStep:F2} x), " +
                $"iterations per sub-step density {_densityIterations:F2} divergence {_divergenceIterations:F2}, " +
                $"divergence error {_divergenceError:F3} %/s, column {_height:F4} m at 1 s ({100 * (_height / _spawned - 1):F2} % of its spawned " +
                $"{_spawned:F4} m); at {HydrostaticTolerance} % dp/dy over the last half second {_pressureGradient:F0} Pa/m (rho0 g {RhoG:F0}: " +
                $"{100 * (-_pressureGradient / RhoG - 1):F2} %), the constant-density solve's alone {_densitySolveGradient:F0} Pa/m; {_report}");
        }

        /// <summary>The pressure both solves apply (p = q delta^2) and the constant-density solve's alone, fitted against height
        /// over a band away from the floor and the surface, each averaged over the frames of the second half of a second.</summary>
        static (double Applied, double DensitySolve) PressureGradients(FluidSceneDescription scene)
        {
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            var warmStart = new Vector2[sim.ParticleCount];
            double support = scene.Settings.SmoothingRadius;
            double applied = 0, densitySolve = 0;
            int measured = 0;
            while (sim.SimulatedTime < 1.0 - 1e-6)
            {
                sim.Step(1f / 60f);
                if (sim.SimulatedTime <= 0.5 + 1e-6) continue;
                var gradients = TankMeasures.DivergenceFreePressureGradients(sim, particles, densities, warmStart, Floor, support);
                applied += gradients.Applied;
                densitySolve += gradients.DensitySolve;
                measured++;
            }
            return (applied / measured, densitySolve / measured);
        }

        /// <summary>The tolerance bounds the density measured after the drift, not only the solve's prediction of it
        /// (FluidSimulation.DensityPredictionMargin).</summary>
        [Test]
        public void TheSettledTankIsCompressedByAtMostTheTolerance() => Assert.That(_averageError, Is.LessThanOrEqualTo(0.001));

        /// <summary>The resting tank's bar for WCSPH (RestingTankTests), here after one second: with the mirrored wall pressure the
        /// column lost 3.4 % as the rows beside the walls sank towards them.</summary>
        [Test]
        public void TheColumnKeepsItsSpawnedHeightWithinOnePercent() => Assert.That(_height, Is.EqualTo(_spawned).Within(0.01 * _spawned));

        /// <summary>
        /// Hydrostatics, the resting tank's bar for WCSPH (RestingTankTests): the pressure the two solves apply at
        /// <see cref="HydrostaticTolerance"/>, fitted over the same band away from the floor and the surface and averaged
        /// over the last half second's frames, grows with depth as rho0 g.
        /// </summary>
        [Test]
        public void ThePressureGrowsWithDepthAsRho0GWithinThreePercent() =>
            Assert.That(-_pressureGradient, Is.EqualTo(RhoG).Within(0.03 * RhoG));

        [Test]
        public void TheSubStepIsAtLeastFiveTimesWcsphs() => Assert.That(_dfsphStep, Is.GreaterThanOrEqualTo(5.0 * _wcsphStep));

        /// <summary>The walls hold the fluid without the last-resort clamp. With the fluid's own q mirrored onto the walls it caught 22
        /// particles in this second (the floor row sank towards the wall face and the column lost 2.6 % of its height in 0.25 s);
        /// with the wall particles as unknowns of the solves (DivergenceFreeSolver.hlsl, "Walls as unknowns") none.</summary>
        [Test]
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
