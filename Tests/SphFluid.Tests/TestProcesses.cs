namespace SphFluid.Tests
{
    /// <summary>
    /// Headless/test.sh runs this suite as two processes at once, one on each of CI's two cores: the tests of
    /// <see cref="LongRuns"/> in one, every other test in the other. The category holds the suite's longest runs (OilAndWater's
    /// layering under DFSPH's Jacobi solve and under WCSPH, the three liquids' layering, OilAndWater at the top of DFSPH's
    /// band and SphereWake, the loose-tolerance runs, the column depths of the iteration scaling, the viscous wave's two
    /// pairs of sloshing tanks, the DFSPH step's energy and the viscous step), chosen so that the two processes end
    /// together; a test joins it or leaves it to keep them even. The layering under the Chebyshev solve (six minutes) runs
    /// by name only: with it the suite ran past its 20-minute goal.
    /// <para>The balance moves as the runs get cheaper. At 17c930b this process ran 17.9 minutes and the rest 16.1, so DFSPH's
    /// two dam breaks went back to the rest. At b890371 it ran 7.5 minutes and the rest 15.2 (a clean clone's CI run, 947 s
    /// in all): DFSPH's layering had fallen from about ten minutes to four and a half. WCSPH's two layering runs (122 and
    /// 95 s there) then came here from the rest, where they had gone at fb7739b, when this category was OilAndWater's three
    /// layering runs and ended three minutes after the other. At d66b9b9 this process ended at 954 s and the rest at 1071 s
    /// (a clean clone's CI run), so the DFSPH step's energy and the viscous step's tests (31 and 25 s) came here.</para>
    /// </summary>
    public static class TestProcesses
    {
        /// <summary>The NUnit category of the process that runs the suite's longest runs.</summary>
        public const string LongRuns = "LongRuns";
    }
}
