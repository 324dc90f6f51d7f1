#ifndef SPHFLUID_SPH_VISCOSITY_INCLUDED
#define SPHFLUID_SPH_VISCOSITY_INCLUDED

#include "SphKernels.hlsl"

// Viscosity with the Laplacian of Mueller, Charypar & Gross 2003 (eq. 14 and 22) in the volume form
// of the multi-phase formulation (Solenthaler & Pajarola 2008: V_j = 1 / delta_j):
//   F_i^v = sum_j mu_ij (v_j - v_i) lapW(r_ij) / (delta_i delta_j),      a_i^v = F_i^v / m_i
// Mixing rule across phases: the harmonic mean mu_ij = 2 mu_i mu_j / (mu_i + mu_j) (Hu & Adams 2006,
// "A multi-phase SPH method for macroscopic and mesoscopic flows", JCP 213), which keeps the shear
// stress continuous at an interface (0 when both are 0). The pair term is antisymmetric: momentum-conserving.
float MixedViscosity(float muI, float muJ)
{
    float sum = muI + muJ;
    return sum > 0.0 ? 2.0 * muI * muJ / sum : 0.0;
}

float3 ViscosityForcePair(float mixedViscosity, float3 velocityI, float3 velocityJ, float r,
                          float numberDensityI, float numberDensityJ)
{
    return (mixedViscosity * ViscosityLaplacian(r) / (numberDensityI * numberDensityJ)) * (velocityJ - velocityI);
}

#endif
