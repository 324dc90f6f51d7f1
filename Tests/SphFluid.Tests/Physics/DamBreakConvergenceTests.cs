using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The dam break of <see cref="DamBreakCollapse"/> under WCSPH as the product ships it, against Martin and Moyce's
    /// front. Its agreement leans on Monaghan's artificial viscosity (the setting's 0.02): at the column's speed of
    /// sound (18.7 m/s, the default stiffness) it is, by the usual equivalence nu = alpha c h / 10 with h half the support,
    /// 310 to 470 times water's kinematic viscosity at these spacings. Without it the front leads the paper by 7.0 and
    /// 8.0 % at the last measurement, and by 9.7 % at a / s = 24, where DFSPH, which has none, leads by 10.7 %
    /// (<see cref="DamBreakResolutionProbe"/>); with it the lead grows as the spacing shrinks the viscosity, 3.0 % at 16
    /// and 3.6 % at 24. So the bar checks the shipped configuration at these resolutions, not a converged front.
    /// </summary>
    public sealed class DamBreakConvergenceTests : DamBreakCollapse
    {
        protected override void Configure(FluidSettings settings) { }

        /// <summary>
        /// Early on (T up to 2.5) both resolutions lead the paper by 5 to 12 %, and no finer resolution brings them
        /// closer (a / s = 12 leads more than 8): the simulated column is released all at once at t = 0, the
        /// experiment's was not, so that lead is not asserted. By the last measurement the front has run four column
        /// widths, the two resolutions agree to 1 % and lie within 2.5 % of the paper, whose figures carry a reading
        /// error of about 2 %.
        /// </summary>
        [TestCase(8)]
        [TestCase(12)]
        public void AtTheLastMeasurementTheFrontIsWithinFivePerCentOfMartinAndMoyce(int perWidth)
        {
            var last = Measured[Measured.Length - 1];
            Assert.That(Fronts[perWidth][Measured.Length - 1], Is.EqualTo(last.Z).Within(0.05 * last.Z));
        }
    }
}
