#ifndef SPHFLUID_SPH_PRESSURE_FORCE_INCLUDED
#define SPHFLUID_SPH_PRESSURE_FORCE_INCLUDED

#include "SphKernels.hlsl"

// Pressure acceleration of the density-contrast formulation (Solenthaler & Pajarola 2008, eq. 6):
//   a_i^p = -(1 / m_i) sum_{j != i} (p_i / delta_i^2 + p_j / delta_j^2) gradW(r_ij)
// The pair term is antisymmetric in (i, j) (gradW is odd, the bracket symmetric), so the forces
// m_i a_i^p sum to zero: momentum is conserved exactly up to rounding. Built from p / delta^2 (not
// p / rho^2) so that particles of different mass across a phase interface see no spurious force.
// pressureTermI/J = p / delta^2 (_Densities.w). Returns the FORCE contribution; divide by m_i once.
float3 PressureForcePair(float pressureTermI, float pressureTermJ, float3 rij, float r)
{
    return -(pressureTermI + pressureTermJ) * SpikyGradient(rij, r);
}

#endif
