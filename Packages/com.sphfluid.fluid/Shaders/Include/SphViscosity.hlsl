#ifndef SPHFLUID_SPH_VISCOSITY_INCLUDED
#define SPHFLUID_SPH_VISCOSITY_INCLUDED

#include "FluidConstants.hlsl"

#include "SphKernels.hlsl"

// Physical (Newtonian) viscosity in the form of Morris, Fox & Zhu 1997 ("Modeling low Reynolds number
// incompressible flows using SPH", JCP 136, eq. 8), which needs only the kernel gradient, so viscosity
// uses the solver's one kernel. In the volume form of the multi-phase formulation (V = 1 / delta):
//   F_i^v = sum_j 2 mu_ij V_i V_j (r_ij . gradW_ij) / (r_ij^2 + 0.01 H^2) (v_i - v_j),   a_i^v = F_i^v / m_i
// (r_ij . gradW_ij <= 0, so the pair term damps the relative velocity; the 0.01 H^2 keeps it finite.)
// Mixing rule across phases: the harmonic mean mu_ij = 2 mu_i mu_j / (mu_i + mu_j) (Hu & Adams 2006,
// "A multi-phase SPH method for macroscopic and mesoscopic flows", JCP 213), which keeps the shear
// stress continuous at an interface. The pair term is antisymmetric: momentum-conserving.
float MixedViscosity(float muI, float muJ)
{
    float sum = muI + muJ;
    return sum > 0.0 ? 2.0 * muI * muJ / sum : 0.0;
}

// The pair's coupling c_ij = -2 mu_ij V_i V_j (r_ij . gradW_ij) / (r_ij^2 + 0.01 H^2) >= 0, kg/s: the force is
// c_ij (v_j - v_i). volumeIJ = V_i V_j (for a boundary neighbour: V_i times its volume). The implicit viscosity solve
// (SphViscositySolve.hlsl) sums it for its diagonal.
float ViscosityCoupling(float mixedViscosity, float3 rij, float r2, float3 gradient, float volumeIJ)
{
    float radial = dot(rij, gradient) / (r2 + 0.01 * _SmoothingRadius2);
    return -2.0 * mixedViscosity * volumeIJ * radial;
}

float3 ViscosityForcePair(float mixedViscosity, float3 velocityI, float3 velocityJ, float3 rij, float r2,
                          float3 gradient, float volumeIJ)
{
    return ViscosityCoupling(mixedViscosity, rij, r2, gradient, volumeIJ) * (velocityJ - velocityI);
}

// Artificial viscosity of Monaghan 1992 ("Smoothed particle hydrodynamics", ARA&A 30, eq. 4.1), the
// standard stabiliser of weakly compressible SPH: it acts only on approaching pairs and dissipates the
// acoustic noise the stiff equation of state makes, which the physical viscosity of water (Reynolds numbers
// of 50 and more at the particle scale) cannot. Volume form, with h = H / 2 and rho_ij = (rho_i + rho_j) / 2:
//   F_i^av = sum_j alpha c h rho_ij V_i V_j min(0, v_ij . r_ij) / (r_ij^2 + 0.01 H^2) gradW_ij
// (gradW_ij points from i towards j; with v_ij . r_ij < 0 the pair is pushed apart: antisymmetric and
// momentum-conserving.) _ArtificialViscosity = alpha c h (m^2/s), precomputed.
// Reads _ArtificialViscosity and _WallArtificialViscosity, alpha_w c h for the contact damping against boundary
// particles (SphBoundary.hlsl), from FluidConstants.hlsl.

float3 ArtificialViscosityForcePair(float3 velocityI, float3 velocityJ, float3 rij, float r2, float3 gradient,
                                    float meanDensity, float volumeIJ)
{
    float approach = min(0.0, dot(velocityI - velocityJ, rij)) / (r2 + 0.01 * _SmoothingRadius2);
    return (_ArtificialViscosity * meanDensity * volumeIJ * approach) * gradient;
}

// The same against a boundary particle, for a given relative velocity (the part into the wall) and coefficient.
float3 WallArtificialViscosityForcePair(float3 relativeVelocity, float3 rib, float r2, float3 gradient, float density, float volumeIB)
{
    float approach = min(0.0, dot(relativeVelocity, rib)) / (r2 + 0.01 * _SmoothingRadius2);
    return (_WallArtificialViscosity * density * volumeIB * approach) * gradient;
}

#endif
