namespace SphFluid.Simulation
{
    /// <summary>The kernel family that every SPH sum of the solver uses (FluidSettings.SmoothingKernel; the equations are in
    /// Shaders/Include/SphKernels.hlsl). Both have compact support H, twice the neighbour grid's cell.</summary>
    public enum KernelFamily
    {
        /// <summary>The cubic B-spline (Monaghan and Lattanzio, "A refined particle method for astrophysical problems"): the
        /// cheapest at H = 2 spacings, where it sums to the lattice density to 1e-5. Above 2.25 spacings its particles pair up
        /// (FluidSettings.MaxCubicSplineSupportRatio), so it is allowed only up to there.</summary>
        CubicSpline = 0,

        /// <summary>Wendland's C2 function (Wendland, "Piecewise polynomial, positive definite and compactly supported radial
        /// functions of minimal degree"), which has no pairing instability at any support (Dehnen and Aly, "Improving
        /// convergence in SPH simulations without pairing instability"): the kernel for supports wider than 2.25 spacings.
        /// At 2.8 to 2.9 spacings the spawn lattice is stable under pressure (LatticeStability), so a tank at rest stays at
        /// rest; the cubic spline's lattice at 2 spacings is not.</summary>
        WendlandC2 = 1,
    }
}
