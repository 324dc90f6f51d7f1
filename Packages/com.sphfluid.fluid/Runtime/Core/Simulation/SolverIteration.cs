namespace SphFluid.Simulation
{
    /// <summary>How DFSPH's two solves iterate (FluidSettings.SolverIteration; DivergenceFreeSolver.hlsl).</summary>
    public enum SolverIteration
    {
        /// <summary>Bender and Koschier's relaxed Jacobi step, compression only: each particle adds the pressure that
        /// removes its own compression. Its iterations grow with the square of the fluid's depth in spacings.</summary>
        Jacobi = 0,

        /// <summary>The Jacobi step accelerated by Chebyshev's polynomial over the operator's eigenvalue bounds
        /// (ChebyshevBounds), with signed steps and each particle's pressure kept at or above zero. Its iterations grow
        /// with the depth itself. The divergence-free solve is always accelerated; the constant-density solve only at
        /// tolerances tight enough to pay for it (ChebyshevBounds.AcceleratesDensitySolve), the Jacobi steps above.</summary>
        Chebyshev = 1,
    }
}
