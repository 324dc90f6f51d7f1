using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The SurfaceTension setting is a surface tension in N/m: droplets fitted to Laplace's law
    /// (<see cref="LaplaceDroplets"/>) make the sigma asked for away from where <see cref="SurfaceLayerShare"/> was
    /// measured (5 mm spacings, rest density 1000 kg/m^3): at twice the density within 10 % (1.085 N/m asked 1 on
    /// lavapipe, by the droplets' RMS radii as the shares were measured; 1.121 by the radii of the balls they fill). At
    /// twice the spacing they make 1.26 N/m (<c>LaplacePressureProbe</c>'s 10 mm fixture; known-limits.md), and at the
    /// share's own 1000 kg/m^3 0.828 N/m (the probe, 2026-12-04): the shares do not hold sigma across densities, because
    /// the surface force propels the droplets and they are sampled at a different stage of it (<see cref="DropletDriftProbe"/>,
    /// known-limits.md).
    /// </summary>
    public sealed class LaplaceLawTests
    {
        [Test]
        public void AtTwiceTheDensity_TheTensionIsTheOneAskedFor()
        {
            const float sigma = 1f;
            var fit = LaplaceDroplets.Measure(KernelFamily.WendlandC2, 2.85f, 0.005f, 2000f, sigma, 10, 14, 20);
            TestContext.Progress.WriteLine($"Wendland C2 at 2.85 spacings of 5 mm, rho0 2000 kg/m^3, sigma asked {sigma} N/m: {fit}");
            Assert.That(fit.Sigma, Is.EqualTo(sigma).Within(10).Percent);
        }

        /// <summary>The measurement runs without the validation layer; this short run gives its kernel variants one with it
        /// (GpuTestDevice.VariantsFolderVariable).</summary>
        [Test]
        public void ADroplet_StepsUnderTheValidationLayer()
        {
            using var sim = new FluidSimulation(GpuTestDevice.Shared, LaplaceDroplets.Scene(KernelFamily.CubicSpline, 2f, 0.005f, 1000f, 1f, 6));
            for (int frame = 0; frame < 3; frame++) sim.Step(1f / 60f);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            foreach (var p in particles)
                Assert.That(float.IsFinite(p.Position.X) && float.IsFinite(p.Position.Y) && float.IsFinite(p.Position.Z), Is.True);
        }
    }
}
