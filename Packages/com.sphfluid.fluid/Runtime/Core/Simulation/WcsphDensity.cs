namespace SphFluid.Simulation
{
    /// <summary>How the weakly compressible solver finds each particle's density (FluidSettings.WcsphDensity).</summary>
    public enum WcsphDensity
    {
        /// <summary>Summation density: the kernel sum over the fluid and boundary neighbours, every sub-step. A particle
        /// short of neighbours (a free surface, a splash) is under-dense and has no pressure.</summary>
        Summation = 0,

        /// <summary>delta-SPH (Antuono, Colagrossi, Marrone &amp; Molteni, "Free-surface flows solved by means of SPH schemes
        /// with numerical diffusive terms"): each particle carries its number density, integrated with the continuity
        /// equation plus a diffusive term, and starts at the hydrostatic density (SphDensityDiffusion.hlsl).</summary>
        DeltaSph = 1,
    }
}
