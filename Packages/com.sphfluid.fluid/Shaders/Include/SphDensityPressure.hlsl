#ifndef SPHFLUID_SPH_DENSITY_PRESSURE_INCLUDED
#define SPHFLUID_SPH_DENSITY_PRESSURE_INCLUDED

#include "FluidConstants.hlsl"

// Density and pressure of the multi-phase density-contrast formulation
// (Solenthaler & Pajarola 2008, "Density contrast SPH interfaces", SCA 2008, eqs. 4-5):
//   number density   delta_i = sum_j W(r_ij)         (the scene's kernel family, SphKernels.hlsl; self
//                                                     included; any phase: a neighbour's volume
//                                                     counts, not its mass, so a light phase next to a
//                                                     heavy one is not seen as compressed)
//   density          rho_i   = m_i delta_i
// Tait equation of state (Becker & Teschner 2007, "Weakly compressible SPH for free surface flows",
// SCA 2007, eq. 6; Monaghan 1994):
//   p_i = k ((rho_i / rho0_i)^gamma - 1),  gamma = 7 by default, k = stiffness [Pa]
// Negative pressure is clamped to 0: at a free surface delta falls below delta0 and a negative pressure
// would pull particles together into clumps (the tensile instability, Swegle et al. 1995); cohesion is
// the surface-tension model's job, not the equation of state's.
// Stored per particle (float4 _Densities): x = rho, y = p, z = delta, w = p / delta^2 (the pressure
// term of the force, so the force loop reads it instead of dividing per pair).

// Reads _Stiffness (k, Pa) and _Gamma (FluidConstants.hlsl).

float TaitPressure(float density, float restDensity)
{
    float p = _Stiffness * (pow(max(density / restDensity, 0.0), _Gamma) - 1.0);
    return max(p, 0.0);
}

float4 DensityRecord(float numberDensity, float particleMass, float restDensity)
{
    float rho = particleMass * numberDensity;
    float p = TaitPressure(rho, restDensity);
    return float4(rho, p, numberDensity, p / (numberDensity * numberDensity));
}

#endif
