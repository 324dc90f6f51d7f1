using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// Where the wall contact starts to act (FluidSimulation.WallContactNumberDensity): WCSPH at a particle's place at rest
    /// beside a flat wall, DFSPH a quarter spacing closer (DivergenceFreeSolver.hlsl), read off the walls' part of the
    /// lattice's number density as the particle nears the wall.
    /// </summary>
    public sealed class WallContactThresholdTests
    {
        const float Spacing = 0.01f;

        static FluidSettings Settings(KernelFamily kind, double supportRatio, PressureSolver solver) => new FluidSettings
        {
            ParticleSpacing = Spacing, SmoothingRadius = (float)(supportRatio * Spacing), SmoothingKernel = kind, PressureSolver = solver,
        };

        /// <summary>A particle a whole spacing closer stands on the first wall row: its walls are the lattice's other half
        /// and the row itself, so the two halves sum to the lattice's number density.</summary>
        [TestCase(KernelFamily.CubicSpline, 2.0)]
        [TestCase(KernelFamily.WendlandC2, 2.85)]
        public void OneSpacingCloserTheWallsAreTheRestOfTheLattice(KernelFamily kind, double supportRatio)
        {
            double support = supportRatio * Spacing;
            double atRest = SmoothingKernels.FlatWallNumberDensity(kind, Spacing, support);
            double onTheRow = SmoothingKernels.FlatWallNumberDensity(kind, Spacing, support, Spacing);
            double lattice = SmoothingKernels.LatticeNumberDensity(kind, Spacing, support);
            Assert.That(atRest + onTheRow, Is.EqualTo(lattice).Within(1e-9 * lattice));
        }

        [TestCase(KernelFamily.CubicSpline, 2.0)]
        [TestCase(KernelFamily.WendlandC2, 2.85)]
        [TestCase(KernelFamily.WendlandC2, 2.9)]
        public void WcsphActsAtThePlaceAtRest_DfsphAQuarterSpacingCloser(KernelFamily kind, double supportRatio)
        {
            double support = supportRatio * Spacing;
            double wcsph = FluidSimulation.WallContactNumberDensity(Settings(kind, supportRatio, PressureSolver.Wcsph));
            double dfsph = FluidSimulation.WallContactNumberDensity(Settings(kind, supportRatio, PressureSolver.Dfsph));
            Assert.That(wcsph, Is.EqualTo(SmoothingKernels.FlatWallNumberDensity(kind, Spacing, support)).Within(1e-6 * wcsph));
            Assert.That(dfsph, Is.EqualTo(SmoothingKernels.FlatWallNumberDensity(kind, Spacing, support, 0.25 * Spacing)).Within(1e-6 * dfsph));
            Assert.That(dfsph, Is.GreaterThan(wcsph));
        }
    }
}
