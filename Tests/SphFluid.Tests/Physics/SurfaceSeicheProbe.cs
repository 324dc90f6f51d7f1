using NUnit.Framework;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The sloshing tank of <see cref="SurfaceSeicheTests"/> under other solvers, kernels and resolutions: a
    /// measurement run by name, `bash Headless/test.sh --filter FullyQualifiedName~SurfaceSeicheProbe`, which CI does
    /// not run. Fixtures (<see cref="SloshingTankConfiguration"/>): DFSPH as <c>--solver dfsph</c> runs the scene (the
    /// cubic spline at 2 spacings); DFSPH with Wendland C2 at 2.85 spacings relaxed to 0.3 (OilAndWater's DFSPH
    /// kernel); WCSPH with the cubic spline at 2 spacings; and the tank narrowed to 0.1 m across at the scene's spacing
    /// and at half of it (tilted by two of its spacings, the same swing), under each solver, for the convergence of the
    /// period with resolution. The fixtures in the narrow tank with one or two changes each ("no XSPH", "free-slip", "max
    /// step S ms", "loose solves", "tight solves", "chebyshev") take each solver's own damping of the wave apart
    /// (Headless/docs/physics.md, "What damps the wave").
    /// </summary>
    [Explicit("a measurement, not a check: run it by name")]
    [TestFixture("dfsph")]
    [TestFixture("dfsph, Wendland C2 relaxed")]
    [TestFixture("cubic spline")]
    [TestFixture("narrow")]
    [TestFixture("narrow, half the spacing")]
    [TestFixture("narrow, max step 0.5 ms")]
    [TestFixture("dfsph, narrow")]
    [TestFixture("dfsph, narrow, half the spacing")]
    [TestFixture("dfsph, narrow, no XSPH")]
    [TestFixture("dfsph, narrow, free-slip")]
    [TestFixture("dfsph, narrow, max step 2 ms")]
    [TestFixture("dfsph, narrow, max step 1 ms")]
    [TestFixture("dfsph, narrow, max step 0.5 ms")]
    [TestFixture("dfsph, narrow, no XSPH, max step 1 ms")]
    [TestFixture("dfsph, narrow, no XSPH, max step 0.5 ms")]
    [TestFixture("narrow, no XSPH")]
    [TestFixture("narrow, no XSPH, max step 0.5 ms")]
    [TestFixture("dfsph, narrow, loose solves")]
    [TestFixture("dfsph, narrow, tight solves")]
    [TestFixture("dfsph, narrow, chebyshev")]
    public sealed class SurfaceSeicheProbe
    {
        readonly string _configuration;

        public SurfaceSeicheProbe(string configuration) => _configuration = configuration;

        [Test]
        public void TheSurfaceSloshesAtTheStandingWavePeriod()
        {
            var scene = SloshingTankConfiguration.Load(_configuration);
            // Two of the finer lattice's spacings, the same swing.
            int tilt = SloshingTankConfiguration.HalvesTheSpacing(_configuration) ? 2 : 1;
            SurfaceSeicheTests.TiltSurface(scene, tilt);
            var slosh = SurfaceSeicheTests.Run(scene, $"RestingTank ({_configuration}), tilted by {tilt} spacing(s)", 1.5, highestDecay: 10);
            Assert.That(slosh.Report.NanCount, Is.EqualTo(0));
        }
    }
}
