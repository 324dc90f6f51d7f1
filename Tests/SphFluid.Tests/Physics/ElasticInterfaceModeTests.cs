using System;
using System.Linq;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>The interface mode of two layers held in an elastic particle lattice (<see cref="ElasticInterfaceMode"/>):
    /// Lamb's without a lattice, the surface wave's closed form over an empty upper layer, and what each kernel's lattice
    /// makes of the kicked overturn and seiche that <see cref="RayleighTaylorProbe"/> and <see cref="InternalSeicheProbe"/>
    /// measure.</summary>
    public sealed class ElasticInterfaceModeTests
    {
        // The probes' layers as they kick them: seven of OilAndWater's 15 mm spacings of each liquid, in its 0.6 x 0.12 m tank.
        static readonly InternalSeiche.Tank Seiche = new(0.6, 0.12, 9.81, 0.105, 900, 0.1, 0.105, 1000, 0.05, NoSlipWalls: false);
        static readonly InternalSeiche.Tank Overturn = Seiche with { UpperDensity = 1000, UpperViscosity = 0.05, LowerDensity = 900, LowerViscosity = 0.1 };
        const double Kick = InternalSeicheProbe.KickAmplitude;

        [Test]
        public void WithoutALattice_TheModesAreLambs()
        {
            double omega = InternalSeiche.AngularFrequency(Seiche), s = InternalSeiche.GrowthRate(Overturn);
            var seiche = ElasticInterfaceMode.Modes(Seiche, 0, 0);
            var overturn = ElasticInterfaceMode.Modes(Overturn, 0, 0);
            var rocking = seiche.OrderByDescending(m => m.Likeness).First();

            Assert.That(rocking.Lambda, Is.EqualTo(omega * omega).Within(1e-4 * omega * omega));
            Assert.That(rocking.Likeness, Is.EqualTo(1).Within(1e-6));
            Assert.That(overturn[0].Lambda, Is.EqualTo(-s * s).Within(1e-4 * s * s));
            Assert.That(overturn[0].Likeness, Is.EqualTo(1).Within(1e-6));
            Assert.That(overturn[1].Lambda, Is.EqualTo(0).Within(1e-6), "a flow that moves neither the interface nor the surface stores nothing");
            Assert.That(ElasticInterfaceMode.KickedInterface(overturn, Overturn, Kick, 2), Is.EqualTo(Kick * Math.Sinh(2 * s)).Within(1e-4 * Kick));
            Assert.That(ElasticInterfaceMode.KickedInterface(seiche, Seiche, Kick, 1), Is.EqualTo(Kick * Math.Sin(omega)).Within(1e-4 * Kick));
        }

        /// <summary>With next to no upper liquid the interface is the lower layer's free surface (the lower layer the
        /// shallower, so that the slow root is its wave), and a weak lattice must add to omega^2 what the surface wave's closed
        /// form gives, its first-order excess (<see cref="SurfaceSeiche.ElasticExcess"/>): the strain energy of the potential
        /// flow, which in one liquid does not slip.</summary>
        [Test]
        public void OverAnEmptyUpperLayer_AWeakLatticeAddsTheSurfaceWavesExcess()
        {
            const double weak = 1e-4;
            var (axis, diagonal) = ElasticInterfaceMode.ModulusRatios(KernelFamily.WendlandC2, 0.015, 2.85 * 0.015);
            var tank = Seiche with { UpperDepth = 0.2, UpperDensity = 1e-6, LowerDepth = 0.1 };
            double free = ElasticInterfaceMode.Modes(tank, 0, 0).OrderByDescending(m => m.Likeness).First().Lambda;
            var held = ElasticInterfaceMode.Modes(tank, weak * axis, weak * diagonal).OrderByDescending(m => m.Likeness).First();
            double surface = SurfaceSeiche.ElasticExcess(Math.PI / tank.Length, tank.LowerDepth, axis, diagonal);

            Assert.That(held.Likeness, Is.GreaterThan(0.999));
            Assert.That((held.Lambda / free - 1) / weak, Is.EqualTo(surface).Within(0.001 * surface));
        }

        /// <summary>
        /// What each lattice makes of the probes' kicked starts (flat layers given Lamb's flow for 15 mm sinh(s t) or
        /// sin(omega t)), printed every 0.1 s to 2 s beside Lamb's: where both moduli hold (Wendland C2 at 2.85 spacings,
        /// the cubic spline at 2) every mode of the overturn rocks (lowest lambda above 0), so it cannot grow from a small
        /// start and the kick carries it to a few millimetres; at 3.5 spacings (c' below 0) it grows, slower than Lamb's;
        /// at 3 (c44 below 0) the lattice gives way to short shear waves and the model predicts nothing.
        /// </summary>
        [TestCase(KernelFamily.WendlandC2, 2.85, 3.369, 3.727)]
        [TestCase(KernelFamily.CubicSpline, 2.0, 4.309, 5.646)]
        [TestCase(KernelFamily.WendlandC2, 3.5, -0.773, 1.083)]
        [TestCase(KernelFamily.WendlandC2, 3.0, double.NaN, double.NaN)]
        public void EachLatticesKickedOverturnAndSeiche(KernelFamily kind, double support, double overturnLowest, double seicheLowest)
        {
            var (axis, diagonal) = ElasticInterfaceMode.ModulusRatios(kind, 0.015, support * 0.015);
            string lattice = $"{kind} at {support} spacings: C44 = {axis:F5} p, C' = {diagonal:F5} p";
            if (double.IsNaN(overturnLowest))
            {
                TestContext.Progress.WriteLine($"{lattice}: C44 below 0, the lattice gives way to short shear waves; no elastic prediction");
                Assert.That(axis, Is.LessThan(0));
                return;
            }
            foreach (var (tank, name, lowest) in new[] { (Overturn, "overturn", overturnLowest), (Seiche, "seiche", seicheLowest) })
            {
                var modes = ElasticInterfaceMode.Modes(tank, axis, diagonal);
                var lamb = ElasticInterfaceMode.Modes(tank, 0, 0);
                string Series(ElasticInterfaceMode.Mode[] m) =>
                    string.Join(" ", Enumerable.Range(0, 21).Select(i => (1000 * ElasticInterfaceMode.KickedInterface(m, tank, Kick, 0.1 * i)).ToString("F1")));
                string rocks = modes[0].Lambda > 0 ? $"{2 * Math.PI / Math.Sqrt(modes[0].Lambda):F2} s" : $"grows at {Math.Sqrt(-modes[0].Lambda):F3}/s";
                TestContext.Progress.WriteLine($"{lattice}: {name}: lowest modes (lambda 1/s^2 / likeness to Lamb's) " +
                    $"{string.Join(", ", modes.Take(4).Select(m => $"{m.Lambda:F3} / {m.Likeness:F2}"))} (Lamb's {InternalSeiche.InternalRootSquared(tank):F3}); " +
                    $"the lowest {rocks}; kicked, mm at 0, 0.1 .. 2 s: {Series(modes)}; Lamb's: {Series(lamb)}");
                Assert.That(modes[0].Lambda, Is.EqualTo(lowest).Within(0.001));
                Assert.That(modes.Sum(m => m.Share), Is.EqualTo(1).Within(1e-6));
            }
        }
    }
}
