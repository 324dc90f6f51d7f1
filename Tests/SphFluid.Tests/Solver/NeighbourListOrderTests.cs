using System.IO;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Sorting;

namespace SphFluid.Tests.Solver
{
    /// <summary>
    /// WCSPH's neighbour lists keep the grid walk's order (NeighbourCapacity.ListRows, SphNeighbourhood.hlsl): each pass
    /// visits a particle's neighbours row by row, fluid then walls, as the walk does, so it sums them in the same order
    /// and a run that reads the lists ends where one that walks the grid ends, to the bit. Every WCSPH figure measured on a
    /// CPU device before the lists therefore stands. The scenes move their container and a sphere (walls placed again at
    /// every frame and sub-step, lists found again before delta-SPH's rate) and shift particles (found again after each
    /// shift).
    /// </summary>
    public sealed class NeighbourListOrderTests
    {
        [TestCase(WcsphDensity.DeltaSph, KernelFamily.CubicSpline, 0f, TestName = "ListsGiveTheGridWalksRun_DeltaSph")]
        [TestCase(WcsphDensity.DeltaSph, KernelFamily.WendlandC2, 0f, TestName = "ListsGiveTheGridWalksRun_DeltaSphWendland")]
        [TestCase(WcsphDensity.Summation, KernelFamily.CubicSpline, 2f, TestName = "ListsGiveTheGridWalksRun_SummationShifting")]
        public void ListsGiveTheGridWalksRunToTheBit(WcsphDensity density, KernelFamily kernel, float shifting)
        {
            var listed = Run(density, kernel, shifting, true);
            var walked = Run(density, kernel, shifting, false);
            Assert.That(listed.Particles.Length, Is.GreaterThan(0));
            Assert.That(listed.Particles, Is.EqualTo(walked.Particles), "positions, velocities, phases and ids");
            Assert.That(listed.Densities, Is.EqualTo(walked.Densities));
            Assert.That(listed.Accelerations, Is.EqualTo(walked.Accelerations));
        }

        /// <summary>The host makes the cells (CellGrid.CellsPerSupport) and sizes the lists' row words (NeighbourCapacity.RowWords);
        /// the kernels walk and write rows by CELLS_PER_SUPPORT. Were they to differ, a walk would miss the cells at its reach,
        /// or a list's row words would overrun its entries.</summary>
        [Test]
        public void TheKernelsWalkTheCellsTheHostMakes()
        {
            string path = Path.Combine(GpuTestDevice.RepoRoot, "Packages", "com.sphfluid.fluid", "Shaders", "Include", "SphNeighbourhood.hlsl");
            var define = Regex.Match(File.ReadAllText(path), @"^#define CELLS_PER_SUPPORT (\d+)u\s*$", RegexOptions.Multiline);
            Assert.That(define.Success, Is.True, $"{path} defines CELLS_PER_SUPPORT");
            Assert.That(int.Parse(define.Groups[1].Value), Is.EqualTo(CellGrid.CellsPerSupport), "CELLS_PER_SUPPORT");
            int rowCells = 2 * CellGrid.CellsPerSupport + 1;
            Assert.That(NeighbourCapacity.ListRows(PressureSolver.Wcsph), Is.EqualTo(rowCells * rowCells),
                "NEIGHBOUR_ROW_WORDS and the walk's rows, one for each y and z the walk reaches");
        }

        static GpuState Run(WcsphDensity density, KernelFamily kernel, float shifting, bool lists)
        {
            var scene = SolverKernelTests.RandomScene(true, false, true, true, kernel);
            scene.Settings.WcsphDensity = density;
            scene.Settings.ParticleShifting = shifting;
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene) { LanesPerParticle = 1, NeighbourListsAllowed = lists };
            Assert.That(sim.ReadsNeighbourLists, Is.EqualTo(lists));
            for (int f = 0; f < 6; f++) sim.Step(1f / 60f);
            var report = sim.ReadDiagnostics();
            Assert.That(report.NanCount, Is.EqualTo(0));
            return GpuState.Read(sim);
        }
    }
}
