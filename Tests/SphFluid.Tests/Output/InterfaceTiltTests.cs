using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Output;

namespace SphFluid.Tests.Output
{
    /// <summary>The interface tilt of layers laid out by hand on the OilAndWater container's floor (0.6 x 0.12 m, 40 x 8
    /// columns of 15 mm): flat layers read 0, a wedge reads the rise of its plane, the worst of several interfaces is
    /// reported, one liquid has no interface, and the free surface lies on all the liquids together.</summary>
    public sealed class InterfaceTiltTests
    {
        const float Spacing = 0.015f;
        static readonly Vector3 Size = new Vector3(0.6f, 0.4f, 0.12f);

        sealed class Layers
        {
            public readonly List<Vector3> Local = new List<Vector3>();
            public readonly List<float> Volumes = new List<float>();
            public readonly List<float> RestDensities = new List<float>();

            /// <summary>In every floor column, <paramref name="rows"/> particles of one liquid whose volumes add up to
            /// <paramref name="thickness"/>(u, w) times the column's area, stacked from <paramref name="firstRow"/>.</summary>
            public void Add(float restDensity, int firstRow, int rows, System.Func<float, float, float> thickness)
            {
                for (int cu = 0; cu < 40; cu++)
                    for (int cw = 0; cw < 8; cw++)
                    {
                        float u = -0.3f + (cu + 0.5f) * Spacing, w = -0.06f + (cw + 0.5f) * Spacing;
                        for (int row = firstRow; row < firstRow + rows; row++)
                        {
                            Local.Add(new Vector3(u, -0.2f + (row + 0.5f) * Spacing, w));
                            Volumes.Add(thickness(u, w) * Spacing * Spacing / rows);
                            RestDensities.Add(restDensity);
                        }
                    }
            }

            public double Tilt() => InterfaceTilt.Measure(Local.ToArray(), Volumes.ToArray(), RestDensities.ToArray(), 1, Size);
        }

        [Test]
        public void FlatLayersHaveNoTilt()
        {
            var layers = new Layers();
            layers.Add(1000f, 0, 6, (u, w) => 6 * Spacing);
            layers.Add(900f, 6, 6, (u, w) => 6 * Spacing);
            Assert.That(layers.Tilt(), Is.EqualTo(0.0).Within(1e-6), "a micrometre: the float positions' rounding");
        }

        [Test]
        public void AWedgeReadsTheRiseOfItsPlaneAcrossTheFloor()
        {
            // Water 0.1 m deep in the middle, rising 40 mm from the back wall to the front one, and 6 mm across the depth.
            var layers = new Layers();
            layers.Add(1000f, 0, 6, (u, w) => 0.1f + 0.04f * u / 0.6f + 0.006f * w / 0.12f);
            layers.Add(900f, 6, 6, (u, w) => 0.1f);
            Assert.That(layers.Tilt(), Is.EqualTo(0.046).Within(0.01 * 0.046));
        }

        [Test]
        public void TheRisesAreSignedFromTheNegativeSideOfEachAxis()
        {
            var layers = new Layers();
            layers.Add(1000f, 0, 6, (u, w) => 0.1f - 0.04f * u / 0.6f);
            layers.Add(900f, 6, 6, (u, w) => 0.1f);
            var rises = InterfaceTilt.Rises(layers.Local.ToArray(), layers.Volumes.ToArray(), layers.RestDensities.ToArray(), 1, Size);
            Assert.That(rises.Count, Is.EqualTo(1));
            Assert.That(rises[0].AlongU, Is.EqualTo(-0.04).Within(0.01 * 0.04));
            Assert.That(rises[0].AlongW, Is.EqualTo(0.0).Within(1e-6));
        }

        [Test]
        public void TheSteepestOfSeveralInterfacesIsReported()
        {
            // Heavy layer flat; the middle liquid's top (heavy + middle) rises by 30 mm along the tank.
            var layers = new Layers();
            layers.Add(1300f, 0, 4, (u, w) => 0.06f);
            layers.Add(1000f, 4, 4, (u, w) => 0.06f + 0.03f * u / 0.6f);
            layers.Add(800f, 8, 4, (u, w) => 0.06f);
            Assert.That(layers.Tilt(), Is.EqualTo(0.03).Within(0.01 * 0.03));
        }

        [Test]
        public void OneLiquidHasNoInterface()
        {
            var layers = new Layers();
            layers.Add(1000f, 0, 6, (u, w) => 0.1f + 0.04f * u / 0.6f);
            Assert.That(layers.Tilt(), Is.NaN);
        }

        [Test]
        public void TheFreeSurfaceIsThePlaneOfEveryLiquidTogether()
        {
            // Flat water under oil whose top falls 30 mm along the tank and rises 6 mm across it: the surface's plane.
            var layers = new Layers();
            layers.Add(1000f, 0, 6, (u, w) => 0.06f);
            layers.Add(900f, 6, 6, (u, w) => 0.06f - 0.03f * u / 0.6f + 0.006f * w / 0.12f);
            var surface = InterfaceTilt.SurfaceRise(layers.Local.ToArray(), layers.Volumes.ToArray(), 1, Size);
            Assert.That(surface.AlongU, Is.EqualTo(-0.03).Within(0.01 * 0.03));
            // Across the 8 columns the plane through their centres rises (n^2 - 1) / n^2 of the continuous slope's rise.
            Assert.That(surface.AlongW, Is.EqualTo(0.006 * 63 / 64).Within(0.001 * 0.006));
            Assert.That(layers.Tilt(), Is.EqualTo(0.0).Within(1e-6), "the interface between them stays flat");
        }
    }
}
