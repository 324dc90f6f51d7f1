using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// SurfaceLayerShare, the measured share of the Laplace pressure the particles' surface force makes, which the shader
    /// divides out: every support a scene may choose gets a share in (0, 1], from the measurements around it. The tension
    /// it gives is held to Laplace's law on the GPU (LaplaceLawTests).
    /// </summary>
    public sealed class SurfaceLayerShareTests
    {
        [Test]
        public void EveryAllowedSupportHasAShareOfOneAtMost()
        {
            for (double ratio = FluidSettings.MinSupportRatio; ratio <= FluidSettings.MaxCubicSplineSupportRatio + 1e-9; ratio += 0.05)
                Assert.That(SurfaceLayerShare.For(KernelFamily.CubicSpline, ratio), Is.GreaterThan(0.0).And.LessThanOrEqualTo(1.0), $"cubic spline at {ratio}");
            for (double ratio = FluidSettings.MinSupportRatio; ratio <= FluidSettings.MaxSupportRatio + 1e-9; ratio += 0.05)
                Assert.That(SurfaceLayerShare.For(KernelFamily.WendlandC2, ratio), Is.GreaterThan(0.0).And.LessThanOrEqualTo(1.0), $"Wendland C2 at {ratio}");
        }

        [Test]
        public void BetweenMeasuredSupportsTheShareIsInterpolated()
        {
            double low = SurfaceLayerShare.For(KernelFamily.CubicSpline, 2.0), high = SurfaceLayerShare.For(KernelFamily.CubicSpline, 2.25);
            Assert.That(SurfaceLayerShare.For(KernelFamily.CubicSpline, 2.125), Is.EqualTo(0.5 * (low + high)).Within(1e-12));
            Assert.That(SurfaceLayerShare.For(KernelFamily.CubicSpline, 1.5), Is.EqualTo(low), "held below the table");
        }
    }
}
