namespace SphFluid.Simulation
{
    /// <summary>Which viscous stress the physical viscosity discretises (FluidSettings.ViscousStress).</summary>
    public enum ViscousStress
    {
        /// <summary>mu times the Laplacian of the velocity, in the pair form of Morris, Fox &amp; Zhu, "Modeling low Reynolds
        /// number incompressible flows using SPH": the cheapest, and the same as the Newtonian stress for an incompressible
        /// flow, but its pair forces also brake a rigid rotation, so a viscous liquid spun in a closed box loses its spin to
        /// the viscosity instead of to its walls.</summary>
        Laplacian = 0,

        /// <summary>The Newtonian stress 2 mu D, D the strain rate: Morris's pair term twice over on the velocity difference
        /// less the pair's mean rigid rotation, with each particle's rotation from a velocity gradient corrected for the
        /// particle distribution (SphViscosity.hlsl, SphVelocityGradient.hlsl). A rigid rotation gets no force, so angular momentum is kept;
        /// it costs one more pass over the neighbours each sub-step and halves the explicit viscous step limit.</summary>
        StrainRate = 1,
    }
}
