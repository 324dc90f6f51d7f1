#ifndef SPHFLUID_SPH_DENSITY_DIFFUSION_INCLUDED
#define SPHFLUID_SPH_DENSITY_DIFFUSION_INCLUDED

#include "SphKernels.hlsl"

// delta-SPH: the number density carried by each particle and integrated with the continuity equation plus a
// diffusive term, instead of summed from the neighbours (WcsphDensity = DeltaSph; FluidSolver's DensityRate and
// ContinuityDensity kernels). Molteni & Colagrossi 2009 ("A simple procedure to improve the pressure evaluation in
// hydrodynamic context using the SPH", Computer Physics Communications 180) and Antuono, Colagrossi, Marrone &
// Molteni 2010 ("Free-surface flows solved by means of SPH schemes with numerical diffusive terms", Computer Physics
// Communications 181), written for the number density delta of the density-contrast formulation:
//   D delta_i / Dt = sum_j (v_i - v_j) . gradW_ij + sum_b omega_b (v_i - v_b) . gradW_ib            (continuity)
//                  + xi h c0 sum_j psi_ij (x_j - x_i) . gradW_ij / (r_ij^2 + 0.01 H^2) / delta_j   (diffusion)
//   psi_ij = 2 ((delta_j - delta_i) - (delta_j^H - delta_i^H))
// xi = 0.1 (the papers' delta), h = H / 2, c0 the speed of sound. (x_j - x_i) . gradW_ij >= 0, so the term moves
// number density from the denser particle of a pair to the other: it is a Laplacian of delta, which damps the
// particle-scale pressure noise a weakly compressible fluid keeps ringing with.
// Why the continuity equation: a particle keeps the number density it carries when it loses neighbours, so a
// splash that reaches a wall is compressed from its own density and meets the wall with a pressure, where summation
// density starts it from a deficit that the clamped equation of state turns into no pressure at all; and the spawn
// jitter is not mistaken for density noise (delta starts hydrostatic, FluidSimulation's initial state).
// Why the hydrostatic part delta^H is taken out of psi: at rest delta grows linearly with depth, and the plain
// Laplacian of Molteni & Colagrossi is not zero where the kernel is cut (the free surface, the walls), so it pushes
// a resting column away from hydrostatics. Antuono et al. subtract the first-order part with a renormalised
// gradient (one more neighbour pass and a 3 x 3 inverse per particle); subtracting the hydrostatic difference
// instead (as Fourtakas, Dominguez, Vacondio & Rogers 2019, "Local uniform stencil (LUST) boundary condition for
// arbitrary 3-D boundaries in parallel smoothed particle hydrodynamics (SPH) models", Computers & Fluids 190, do
// for the density) makes each pair's term exactly zero in a fluid at rest, cut kernel or not, at no extra pass.
// With the linearised Tait law, d delta = delta0 dp / (gamma k) and dp = rho0 g . dx:
//   delta_j^H - delta_i^H = delta0_ij rho0_ij g . (x_j - x_i) / (gamma k)       (pair means of both phases)
// Multi-phase: the number density diffuses, not the mass density. All phases share one rest number density on the
// spawn lattice (DerivedParticleMass), so delta is smooth across an interface while rho = m delta jumps there;
// diffusing rho would smear that jump into the lighter phase and push it by a pressure it does not have, diffusing
// delta leaves it alone (the pressure, from delta / delta0 of each particle's own phase, stays continuous).
// Boundary particles take part in the continuity term (their volume omega_b and the wall's velocity, as in the
// summation density they replace) but not in the diffusion: they carry no delta of their own, and with the
// hydrostatic part taken out a cut support needs no mirrored partner.
// Time integration (with SphIntegration's Velocity Verlet): along a sub-step's drift every particle moves with its
// half-step velocity, and the continuity term is the time derivative of the kernel sum, so it is integrated by the
// trapezoidal rule over the drift: half from the positions before it (DensityRate, with v + a dt / 2, the velocity
// HalfStep will give, or, where the viscosity is implicit, the velocity HalfKick and the solve gave), half after it
// (ContinuityDensity, after the re-sort). The diffusion is explicit, from the
// state before the drift. Both passes read their neighbours' delta from one buffer and write another, by particle
// id (the particles are re-sorted every sub-step):
//   DensityRate:        delta*_i      = delta_i^n + dt/2 C_i(x^n, v^{n+1/2}) + dt D_i(x^n, delta^n)
//   ContinuityDensity:  delta_i^{n+1} = delta*_i  + dt/2 C_i(x^{n+1}, v^{n+1/2})
// (FluidSimulation.ComputeForces runs both with dt = 0 outside a step: delta is kept and the rates are read out.)

#define DENSITY_DIFFUSION_XI 0.1

// Reads _DensityDiffusion = xi h c0 (m^2/s) and _HydrostaticCompliance = 1 / (gamma k) (1/Pa) from FluidConstants.hlsl.

RWStructuredBuffer<float> _NumberDensities;     // by particle id: delta^n, 1/m^3
RWStructuredBuffer<float> _NumberDensitiesHalf; // by particle id: delta* (DensityRate's partial step), 1/m^3
RWStructuredBuffer<float2> _DensityRates;       // per sorted particle: continuity C_i and diffusion D_i before the drift, 1/(m^3 s)

// A pair's share of the continuity term: (v_i - v_j) . gradW_ij (times omega_b for a boundary particle).
float ContinuityPair(float3 velocityI, float3 velocityJ, float3 gradient)
{
    return dot(velocityI - velocityJ, gradient);
}

// delta_j^H - delta_i^H: the number density difference of a fluid at rest between x_j and x_i = x_j + rij.
float HydrostaticNumberDensityDifference(float restNumberDensityIJ, float restDensityIJ, float3 gravity, float3 rij)
{
    return -restNumberDensityIJ * restDensityIJ * _HydrostaticCompliance * dot(gravity, rij);
}

// A fluid pair's share of the diffusion term D_i (without xi h c0).
float DensityDiffusionPair(float deltaI, float deltaJ, float hydrostaticDifference, float3 rij, float r2, float3 gradient)
{
    float psi = 2.0 * ((deltaJ - deltaI) - hydrostaticDifference);
    return psi * (-dot(rij, gradient)) / ((r2 + 0.01 * _SmoothingRadius2) * deltaJ);
}

// delta* from delta^n, the continuity sum before the drift and the diffusion sum.
float HalfStepNumberDensity(float delta, float continuity, float diffusion, float timeStep)
{
    return delta + 0.5 * timeStep * continuity + timeStep * _DensityDiffusion * diffusion;
}

#endif
