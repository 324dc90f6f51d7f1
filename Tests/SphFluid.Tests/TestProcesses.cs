namespace SphFluid.Tests
{
    /// <summary>
    /// Headless/test.sh runs this suite as two processes at once, one on each of CI's two cores: the tests of
    /// <see cref="LongDfsphRuns"/> in one, every other test in the other. The category holds DFSPH's longest runs (OilAndWater
    /// layering under the scene's Jacobi solve, OilAndWater at the top of DFSPH's band and SphereWake, the loose-tolerance runs
    /// and the column depths of the iteration scaling), chosen so that the two processes end together; a test joins it or
    /// leaves it to keep them even. The layering under the Chebyshev solve (six minutes) runs by name only: with it the
    /// suite ran past its 20-minute goal. Without it, and with SphereWake and the top of the band here, this process ran
    /// 17.9 minutes and the rest 16.1 (a clean clone of 17c930b), so DFSPH's two dam breaks (the scene's and the column's
    /// against Martin and Moyce, half a minute together) went back to the rest.
    /// <para>At fb7739b the category was OilAndWater's three layering runs, WCSPH's among them, and that process ended three
    /// minutes after the other (17.7 minutes against 14.4 in a clean clone's CI run). WCSPH's run (3 min 19 s there) now
    /// runs with the rest, and LooseToleranceTests and SolverIterationScalingTests (about a minute each with their
    /// fixtures' runs) here; a run of as much work then took 1099 s against 1187 (README, the test command).</para>
    /// </summary>
    public static class TestProcesses
    {
        /// <summary>The NUnit category of the process that runs DFSPH's longest runs.</summary>
        public const string LongDfsphRuns = "LongDfsphRuns";
    }
}
