#ifndef SPHFLUID_SPH_XSPH_INCLUDED
#define SPHFLUID_SPH_XSPH_INCLUDED

#include "FluidConstants.hlsl"

#include "SphKernels.hlsl"

// XSPH velocity correction (Monaghan 1989, "On the problem of penetration in particle methods",
// JCP 82), volume form for several phases (the mass-weighted 2 m_j / (rho_i + rho_j) becomes
// 2 / (delta_i + delta_j), so a heavy neighbour does not drag a light particle more than a light one):
//   dv_i = epsilon sum_j (2 / (delta_i + delta_j)) (v_j - v_i) W(r_ij),   epsilon in [0, 1]
// Applied at the end of the full step (v += dv): particles move more coherently with their neighbours,
// which damps the particle-scale noise of weakly compressible SPH without a large viscosity. The share is per
// sub-step, so what it removes in a second goes with the sub-steps taken: the sloshing tank's wave loses 0.188/s to it
// at WCSPH's 1.111 ms and 0.361/s at 0.5 ms (Headless/docs/known-limits.md, "XSPH damps per sub-step").
// Reads _XsphEpsilon (FluidConstants.hlsl).

float3 XsphPair(float3 velocityI, float3 velocityJ, float r2, float numberDensityI, float numberDensityJ)
{
    return (2.0 * Kernel(r2) / (numberDensityI + numberDensityJ)) * (velocityJ - velocityI);
}

#endif
