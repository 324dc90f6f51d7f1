namespace SphFluid.Simulation
{
    /// <summary>How the fluid resists compression: the choice between a cheap step and an accurate one.</summary>
    public enum PressureSolver
    {
        /// <summary>Weakly compressible SPH: pressure from the Tait equation of state. One pass per sub-step, but the
        /// step is bounded by the artificial speed of sound and the density error follows the stiffness.</summary>
        Wcsph = 0,

        /// <summary>Divergence-free SPH (Bender and Koschier, "Divergence-Free Smoothed Particle Hydrodynamics"):
        /// iterative constant-density and divergence-free solves to a chosen tolerance. Several passes per
        /// sub-step, but the step is bounded by the flow speed only.</summary>
        Dfsph = 1,
    }
}
