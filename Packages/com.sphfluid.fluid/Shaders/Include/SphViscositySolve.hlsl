#ifndef SPHFLUID_SPH_VISCOSITY_SOLVE_INCLUDED
#define SPHFLUID_SPH_VISCOSITY_SOLVE_INCLUDED

#include "FluidConstants.hlsl"

// The viscous force of SphViscosity.hlsl taken implicitly, so that a sub-step (DFSPH's, or WCSPH's where it pays off)
// may be longer than the explicit force's limit, 1 / (nu Lambda_max) (ViscousStepLimit.cs): a liquid of 100 Pa s held OilAndWater to steps 6.5 times
// shorter than its flow's own. Weiler, Koschier, Brand & Bender 2018, "A physically consistent implicit viscosity solver
// for SPH fluids", solve their own viscosity operator implicitly; this solve keeps the Morris form the explicit force
// uses, so that either converges to the same viscosity as the step shrinks.
// The step is Alexander's two-stage diagonally implicit Runge-Kutta method (Alexander 1977, "Diagonally implicit
// Runge-Kutta methods for stiff O.D.E.'s"), second order and L-stable: two backward Euler solves of step h = gamma dt,
// gamma = 1 - 1 / sqrt 2 (ImplicitViscosity.cs). Everything else the sub-step gives the velocity, v* - v_n (gravity,
// the other forces, the constant-density solve's pressure), enters both stages as a constant forcing f = (v* - v_n) / dt,
// as the method takes a source term, and not as a kick before them: stage one solves
//   Y1 = v_n + gamma (v* - v_n) + h a(Y1),
// stage two
//   Y2 = v* + (1 - gamma) dt a(Y1) + h a(Y2),   (1 - gamma) dt a(Y1) = (dt / h - 1) (Y1 - t1)  (t1 stage one's target),
// whose solution is the new velocity. Backward Euler alone takes a wave of decay rate lambda down by 1 / (1 + lambda dt)
// a step, and a slow flow lags: ViscositySolveTests' cellular flow kept 4 % more than the viscous operator's exact decay
// leaves at 9.8 explicit limits, where the two stages, which take it down by (1 - (1 - 2 gamma) lambda dt) /
// (1 + gamma lambda dt)^2, keep 0.1 % less. With the forcing inside the stages a flow that viscosity holds against it
// keeps its speed f / lambda at any step (either stage's solution is f / lambda when v_n is); applied as a kick before
// them, the kick's part in a wave stiffer than lambda dt = 1 + sqrt 2 came out with its sign turned (the two stages'
// factor is negative there), and OilAndWater with its oil at 100 Pa s had 2.6 times the explicit force's kinetic
// energy at 0.1 s, where backward Euler had 1.4 times. Each stage's x solves
//   m_i x_i + h sum_j c_ij (x_i - x_j) + h sum_b c_ib (x_i - v_b) = m_i t_i        (each component alone)
// with t its target (the solve runs between the constant-density solve and the drift, so v* holds that solve's pressure)
// and c = ViscosityCoupling >= 0, the same for i, j as for j, i. The matrix M + h L (L a weighted graph Laplacian, walls
// adding to its diagonal) is symmetric positive definite; its exact solution keeps the momentum of its target, which only
// walls with friction change, and so the step keeps v*'s (stage two's target has it: Y1 and t1 have the same). Divided by
// its diagonal row by row, m_i + h sum c, the residual is the Jacobi step
//   z_i = ((t_i - x_i) + h F_i(x) / m_i) / (1 + h sum c / m_i),   F_i(x) the viscous force at the velocities x,
// and the diagonally scaled operator's eigenvalues lie in [1 / (1 + beta), 2) by Gershgorin, beta = h sum c / m_i:
// about 1 / (1 + beta) for a long wave, near 2 for the stiffest. Chebyshev acceleration over [a, b]
// (DivergenceFreeSolver.hlsl's ChebyshevWeights, the steps d_k = beta_k d_{k-1} + gamma_k z_k, x += d_k) takes every
// wave's error down by at least 2 / (c^-K + c^K) in K rounds, c = (sqrt(b / a) - 1) / (sqrt(b / a) + 1), so the rounds
// grow as sqrt(beta) where an explicit viscosity needs sub-steps in proportion to beta, and two stages of h cost about
// one solve of dt. The host sets [a, b] and K (ImplicitViscosity.cs): b = 2, and a from the lattice's row sum with a
// margin. No wave's error grows whatever a is, since every eigenvalue lies in (0, b]: one below a is taken down more
// slowly. The rounds are recorded, not decided on the GPU, so nothing is read back.
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

// The Jacobi step z_i from the stage's target t_i, the iterate x_i, and the sums over i's neighbours of the viscous
// force at the iterate (F_i(x)) and of the couplings (sum c), for particle mass m_i.
float3 ViscousJacobiStep(float3 target, float3 iterate, float3 viscousForce, float couplingSum, float mass)
{
    float3 residual = (target - iterate) + (_ViscositySolveStep / mass) * viscousForce;
    return residual / (1.0 + _ViscositySolveStep * couplingSum / mass);
}

// Stage one's target t1 = v_n + gamma (v* - v_n) from the solve's first velocity v_n and v* (above).
float3 FirstStageTarget(float3 start, float3 predicted)
{
    return start + (_ViscositySolveStep / _ViscositySolveSpan) * (predicted - start);
}

// Stage two's target from v_n, stage one's target t1 (which gives v* back) and its solution Y1 (above).
float3 SecondStageTarget(float3 start, float3 firstTarget, float3 firstStage)
{
    float stages = _ViscositySolveSpan / _ViscositySolveStep; // 1 / gamma
    float3 predicted = start + stages * (firstTarget - start);
    return predicted + (stages - 1.0) * (firstStage - firstTarget);
}

#endif
