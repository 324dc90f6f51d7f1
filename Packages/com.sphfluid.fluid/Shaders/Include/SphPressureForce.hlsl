#ifndef SPHFLUID_SPH_PRESSURE_FORCE_INCLUDED
#define SPHFLUID_SPH_PRESSURE_FORCE_INCLUDED

#include "SphKernels.hlsl"

// Pressure force of the density-contrast formulation (Solenthaler & Pajarola 2008, "Density contrast SPH
// interfaces", SCA 2008, eq. 6):
//   F_i^p = -sum_{j != i} (p_i / delta_i^2 + p_j / delta_j^2) gradW(r_ij),        a_i^p = F_i^p / m_i
// The pair term is antisymmetric in (i, j), so momentum is conserved up to rounding. Built from
// p / delta^2 (not p / rho^2) so that particles of different mass across a phase interface see no
// spurious force. pressureTermI/J = p / delta^2 (_Densities.w).
//
// Coincident particles (r = 0): gradW has no direction there, and a pair that never separates stays
// merged for ever (a 50 m/s impact merged 960 particles into 14 points). PairDirection gives such a
// pair a deterministic, antisymmetric direction from the particles' spawn ids and pushes them apart with
// the kernel gradient's magnitude at a hundredth of a support, so they separate at once whatever the
// GPU's thread order.

float3 PairDirection(float3 rij, float r, uint idI, uint idJ)
{
    if (r > 0.0)
        return rij / r;
    // Any fixed direction not on a lattice axis, signed by the id order: i and j get opposite ones.
    float3 axis = float3(0.5773503, 0.5773503, 0.5773503);
    return idI > idJ ? axis : -axis;
}

// gradW for a pair, with coincident pairs resolved by PairDirection.
float3 PairGradient(float3 rij, float r, uint idI, uint idJ)
{
    float rr = max(r, 0.01 * _SmoothingRadius);
    return KernelGradient(PairDirection(rij, r, idI, idJ) * rr, rr);
}

float3 PressureForcePair(float pressureTermI, float pressureTermJ, float3 gradient)
{
    return -(pressureTermI + pressureTermJ) * gradient;
}

#endif
