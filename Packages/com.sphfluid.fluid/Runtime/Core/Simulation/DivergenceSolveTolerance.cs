namespace SphFluid.Simulation
{
    /// <summary>
    /// The average rate of density change that ends DFSPH's divergence-free solve at a sub-step:
    /// <see cref="FluidSettings.DivergenceTolerance"/> at sub-steps of <see cref="ReferenceStep"/> and longer, and at a
    /// shorter one the density change a sub-step that the setting allows over the reference step.
    /// <para>What the divergence-free solve leaves is a density drift over the coming sub-step, which the next
    /// constant-density solve takes up. Held to a rate a second, the drift allowed a sub-step shrank with the sub-step,
    /// and finer particles, whose gravity wave shortens the step, paid for a drift far below the one the scene was
    /// validated with: at OilAndWater's 1M spacing (1.39 ms sub-steps) 10 %/s allowed 0.014 % a sub-step against
    /// 0.042 % at the scene's own 4.17 ms, and the divergence-free rounds rose from about 2 to 9 a sub-step
    /// (Headless/docs/accuracy-for-time.md, "What would close it"). Bender and Koschier's own implementation (SPlisHSPlasH,
    /// the code of "Divergence-Free SPH for Incompressible and Viscous Fluids") holds this solve to a density change a
    /// time step. The reference is a 60 Hz frame in four sub-steps, the step OilAndWater runs under DFSPH, so it runs
    /// as before. It is not tied to the density tolerance, so a loose one (1 %) does not loosen the drift a sub-step,
    /// and a user's tighter divergence tolerance stays that much tighter at every step.</para>
    /// </summary>
    public static class DivergenceSolveTolerance
    {
        /// <summary>The sub-step, in seconds, over which the setting's rate is the density change a sub-step allowed.</summary>
        public const float ReferenceStep = 1f / 240f;

        /// <summary>The solve's stop rate at a sub-step of <paramref name="dt"/> seconds, as a fraction of the rest density
        /// a second (the setting is in per cent a second); the setting's own rate where no step is set yet.</summary>
        public static float At(FluidSettings settings, float dt)
        {
            float rate = 0.01f * settings.DivergenceTolerance;
            if (!(dt > 0f) || dt >= ReferenceStep) return rate;
            return rate * ReferenceStep / dt;
        }
    }
}
