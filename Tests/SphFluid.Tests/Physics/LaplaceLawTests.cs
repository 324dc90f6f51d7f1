using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The SurfaceTension setting is a surface tension in N/m: droplets fitted to Laplace's law
    /// (<see cref="LaplaceDroplets"/>) make the sigma asked for away from where <see cref="SurfaceLayerShare"/> was
    /// measured (5 mm spacings, rest density 1000 kg/m^3). At twice the density the tension is within 10 % of it (1.085
    /// N/m asked 1 on lavapipe). At twice the spacing it is not: 1.26 N/m, so this test holds it within 30 %, the gap a
    /// share that depended on the spacing as well would have to close (known-limits.md). Akinci et al.'s cohesion, which
    /// the continuum surface force replaced, made 3.9 times the tension at twice the spacing.
    /// </summary>
    public sealed class LaplaceLawTests
    {
        [Test]
        public void AtTwiceTheSpacing_TheTensionIsWithin30PercentOfTheOneAskedFor()
        {
            const float sigma = 1f;
            var fit = LaplaceDroplets.Measure(KernelFamily.CubicSpline, 2f, 0.01f, 1000f, sigma, 10, 14, 20);
            TestContext.Progress.WriteLine($"cubic spline at 2 spacings of 10 mm, sigma asked {sigma} N/m: {fit}");
            Assert.That(fit.Sigma, Is.EqualTo(sigma).Within(30).Percent);
        }

        [Test]
        public void AtTwiceTheDensity_TheTensionIsTheOneAskedFor()
        {
            const float sigma = 1f;
            var fit = LaplaceDroplets.Measure(KernelFamily.WendlandC2, 2.85f, 0.005f, 2000f, sigma, 10, 14, 20);
            TestContext.Progress.WriteLine($"Wendland C2 at 2.85 spacings of 5 mm, rho0 2000 kg/m^3, sigma asked {sigma} N/m: {fit}");
            Assert.That(fit.Sigma, Is.EqualTo(sigma).Within(10).Percent);
        }
    }
}
