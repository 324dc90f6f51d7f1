#ifndef SPHFLUID_SPH_VISCOSITY_SOLVE_INCLUDED
#define SPHFLUID_SPH_VISCOSITY_SOLVE_INCLUDED

#include "FluidConstants.hlsl"

// The viscous force of SphViscosity.hlsl taken implicitly (backward Euler), so that a DFSPH sub-step may be longer than
// the explicit force's limit, 1 / (nu Lambda_max) (ViscousStepLimit.cs): a liquid of 100 Pa s held OilAndWater to
// steps 6.5 times shorter than its flow's own. Weiler, Koschier, Brand & Bender 2018, "A physically consistent implicit
// viscosity solver for SPH fluids", solve their own viscosity operator implicitly; this solve keeps the Morris form the
// explicit force uses, so that either converges to the same viscosity as the step shrinks. The new velocities x solve
//   m_i x_i + dt sum_j c_ij (x_i - x_j) + dt sum_b c_ib (x_i - v_b) = m_i v*_i        (each component alone)
// with v* the velocity every other force and the constant-density solve's pressure have given (the solve runs between
// that solve and the drift) and c = ViscosityCoupling >= 0, the same for i, j as for
// j, i. The matrix M + dt L (L a weighted graph Laplacian, walls adding to its diagonal) is symmetric positive definite;
// its exact solution keeps the fluid's momentum, which only walls with friction change. Divided by its diagonal row by
// row, m_i + dt sum c, the residual is the Jacobi step
//   z_i = ((v*_i - x_i) + dt F_i(x) / m_i) / (1 + dt sum c / m_i),   F_i(x) the viscous force at the velocities x,
// and the diagonally scaled operator's eigenvalues lie in [1 / (1 + beta), 2) by Gershgorin, beta = dt sum c / m_i:
// about 1 / (1 + beta) for a long wave, near 2 for the stiffest. Chebyshev acceleration over [a, b]
// (DivergenceFreeSolver.hlsl's ChebyshevWeights, the steps d_k = beta_k d_{k-1} + gamma_k z_k, x += d_k) takes every
// wave's error down by at least 2 / (c^-K + c^K) in K rounds, c = (sqrt(b / a) - 1) / (sqrt(b / a) + 1), so the rounds
// grow as sqrt(beta) where an explicit viscosity needs sub-steps in proportion to beta. The host sets [a, b] and K
// (ImplicitViscosity.cs): b = 2, and a from the lattice's row sum with a margin. No wave's error grows whatever a is,
// since every eigenvalue lies in (0, b]: one below a is taken down more slowly. The rounds are recorded, not
// decided on the GPU, so nothing is read back.
// Why after the pressure: a flow that viscosity holds (a wave of the flow with decay rate lambda, driven by buoyancy's
// pressure a) runs at a / lambda when the step damps every velocity it drifts with, as the explicit force does. Solved
// before the constant-density solve, the pressure's kick of each step went into the drift undamped, and such a flow ran
// at (1 + lambda dt) a / lambda: OilAndWater with its oil at 100 Pa s had 7.3 times the kinetic energy at 0.1 s at its
// own steps (6.5 explicit limits) that the explicit force gave it, and has 1.4 times it solved after
// (ViscositySolveTests). The velocity the drift then takes is no longer the one the constant-density solve corrected;
// the viscous change of a divergence-free flow is nearly divergence-free, and the divergence-free solve after the drift
// takes out what is left.

// Whether this sub-step's viscosity is the implicit solve's (NonPressureForces then leaves it out).
bool ViscosityIsImplicit()
{
    return _ViscositySolveHigh > 0.0;
}

// The Jacobi step z_i from the predicted velocity v*_i, the iterate x_i, and the sums over i's neighbours of the
// viscous force at the iterate (F_i(x)) and of the couplings (sum c), for particle mass m_i.
float3 ViscousJacobiStep(float3 predicted, float3 iterate, float3 viscousForce, float couplingSum, float mass)
{
    float3 residual = (predicted - iterate) + (_TimeStep / mass) * viscousForce;
    return residual / (1.0 + _TimeStep * couplingSum / mass);
}

#endif
