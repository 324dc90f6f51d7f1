using System.Numerics;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The sloshing tank of <see cref="SurfaceSeicheTests"/> under other solvers, kernels and resolutions: a measurement
    /// run by name, `bash Headless/test.sh --filter FullyQualifiedName~SurfaceSeicheProbe`, which CI does not run.
    /// Fixtures: DFSPH as <c>--solver dfsph</c> runs the scene (the cubic spline at 2 spacings); DFSPH with Wendland C2 at
    /// 2.85 spacings relaxed to 0.3 (OilAndWater's DFSPH kernel); WCSPH with the cubic spline at 2 spacings; and the tank
    /// narrowed to 0.1 m across at the scene's spacing and at half of it ("8 times the particles", tilted by two of its
    /// spacings, the same swing), under each solver, for the convergence of the period with resolution.
    /// </summary>
    [Explicit("a measurement, not a check: run it by name")]
    [TestFixture("dfsph")]
    [TestFixture("dfsph, Wendland C2 relaxed")]
    [TestFixture("cubic spline")]
    [TestFixture("narrow")]
    [TestFixture("narrow, 8 times the particles")]
    [TestFixture("dfsph, narrow")]
    [TestFixture("dfsph, narrow, 8 times the particles")]
    public sealed class SurfaceSeicheProbe
    {
        readonly string _configuration;

        public SurfaceSeicheProbe(string configuration) => _configuration = configuration;

        [Test]
        public void TheSurfaceSloshesAtTheStandingWavePeriod()
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("RestingTank"), RunnerPaths.Project).Description;
            if (_configuration.StartsWith("dfsph")) new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, "DFSPH RestingTank");
            var s = scene.Settings;
            if (_configuration.Contains("Wendland C2 relaxed"))
            {
                s.SmoothingKernel = KernelFamily.WendlandC2;
                s.SmoothingRadius = 2.85f * s.ParticleSpacing;
                s.SolverRelaxation = 0.3f;
            }
            if (_configuration == "cubic spline")
            {
                s.SmoothingKernel = KernelFamily.CubicSpline;
                s.SmoothingRadius = 2f * s.ParticleSpacing;
            }
            if (_configuration.Contains("narrow"))
            {
                scene.Container.Size = new Vector3(scene.Container.Size.X, scene.Container.Size.Y, 0.1f);
                var water = scene.SpawnBoxes[0];
                water.Size = new Vector3(water.Size.X, water.Size.Y, 0.1f);
            }
            int tilt = 1;
            if (Regex.IsMatch(_configuration, "8 times the particles$"))
            {
                ParticleScaling.ScaleBy(scene, 8);
                tilt = 2;
            }
            SurfaceSeicheTests.TiltSurface(scene, tilt);
            var slosh = SurfaceSeicheTests.Run(scene, $"RestingTank ({_configuration}), tilted by {tilt} spacing(s)", 1.5);
            Assert.That(slosh.Report.NanCount, Is.EqualTo(0));
        }
    }
}
