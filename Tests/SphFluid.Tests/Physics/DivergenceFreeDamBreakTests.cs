using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The dam break of <see cref="DamBreakCollapse"/> under DFSPH at its default tolerances (0.1 %, 10 %/s) and the
    /// column's cubic spline at 2 spacings. Its two resolutions agree within 4.0 % at every measured time, but at the
    /// paper's last measurement (T = 3.35) the front leads Martin and Moyce by 12.2 % at a / s = 8 and 10.2 % at 12 (at
    /// 3fdb52d, whose divergence-free solve is held a sub-step below 1/240 s; 13.5 and 9.8 % and within 4.4 % at 29c0008; 10.3 and 11.9 % at d4df871, 12.7 and 9.6 % before the DFSPH spawn was settled there), where WCSPH as shipped comes within 2.5 %. DFSPH has no artificial viscosity; WCSPH without its own leads by 7.0 and
    /// 8.0 %, and refined to a / s = 24 the two close on each other, DFSPH at 10.7 % and WCSPH without it at 9.7 %
    /// (<see cref="DamBreakResolutionProbe"/>): the lead is the nearly inviscid fluid's on slip walls, which the
    /// experiment's floor and gate did not give it. A tenth of the CFL number (8.6 and 8.1 %), a tenth of both tolerances
    /// (10.2 and 13.0 %) or no XSPH (9.1 and 11.0 %) leave it (hand edits of this fixture's settings, at e6e1d57). What is
    /// checked is what holds for any fluid here and that the front is not behind the paper's.
    /// </summary>
    public sealed class DivergenceFreeDamBreakTests : DamBreakCollapse
    {
        protected override void Configure(FluidSettings settings) => settings.PressureSolver = PressureSolver.Dfsph;

        [TestCase(8)]
        [TestCase(12)]
        public void AtTheLastMeasurementTheFrontIsNotBehindMartinAndMoyce(int perWidth)
        {
            TestContext.Progress.WriteLine($"DFSPH dam break a/s = {perWidth}: the front leads Martin and Moyce by {100 * LastLead(perWidth):F1} % at T = 3.35");
            Assert.That(LastLead(perWidth), Is.GreaterThanOrEqualTo(0.0));
        }
    }
}
