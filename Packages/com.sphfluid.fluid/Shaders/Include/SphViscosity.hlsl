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

// The strain-rate stress (FluidSettings.ViscousStress = StrainRate). Morris's pair term approximates mu times the
// Laplacian of the velocity, which for an incompressible flow is the divergence of the Newtonian stress
// mu (grad v + grad v^T); but pair by pair it resists any relative velocity, a rigid rotation's too, and at a free surface
// or a cut support it brakes a spinning liquid at about 2 nu / <r^2> (known limits). The strain-rate form applies the
// pair term to the velocity difference less the pair's mean rigid rotation, twice over:
//   F_i^v = sum_j 2 c_ij (v_j - v_i + Omega_ij x (x_i - x_j)),   Omega_ij = (Omega_i + Omega_j) / 2,
// Omega = curl v / 2 from the corrected velocity gradient (SphVelocityGradient.hlsl). Of a shear u(y) the pair's rotation
// takes half (v_j - v_i + Omega_ij x (x_i - x_j) = D (x_j - x_i), D the strain rate), so the factor 2 gives mu u'' back;
// in the bulk the sum is div(mu (grad v + grad v^T)) for a uniform mu, and a rigid rotation,
// whose Omega is exact with the correction, gets no force at any truncation of the support: a spinning liquid keeps its
// angular momentum. The pair term is still antisymmetric, so momentum is kept. Its stiffest wave decays twice as fast as
// Morris's, which halves the explicit step limit (TimeStepController.OperatorViscosity).

// The pair's coupling c_ij = -2 mu_ij V_i V_j (r_ij . gradW_ij) / (r_ij^2 + 0.01 H^2) >= 0, kg/s, twice that for the
// strain rate's stress: the force is c_ij (v_j - v_i) plus the strain rate's rotation term. volumeIJ = V_i V_j (for a
// boundary neighbour: V_i times its volume). The implicit viscosity solve (SphViscositySolve.hlsl) sums it for its
// diagonal.
float ViscosityCoupling(float mixedViscosity, float3 rij, float r2, float3 gradient, float volumeIJ)
{
    float radial = dot(rij, gradient) / (r2 + 0.01 * _SmoothingRadius2);
    float stress = _StrainRateViscosity != 0u ? 2.0 : 1.0;
    return -2.0 * stress * mixedViscosity * volumeIJ * radial;
}

// pairRotation = Omega_ij for the strain rate's stress, zero for Morris's.
float3 ViscosityForcePair(float mixedViscosity, float3 velocityI, float3 velocityJ, float3 rij, float r2,
                          float3 gradient, float volumeIJ, float3 pairRotation)
{
    return ViscosityCoupling(mixedViscosity, rij, r2, gradient, volumeIJ) * (velocityJ - velocityI + cross(pairRotation, rij));
}

// The rotation term alone, c_ij Omega_ij x (x_i - x_j): the part of the strain rate's pair term that the implicit
// solve, which takes c_ij (v_j - v_i), leaves to the explicit forces, at the rotations of the sub-step's start. A rigid
// rotation then still gets no force: the solve's term and this one cancel for the velocities the rotations came from.
float3 ViscosityRotationForcePair(float mixedViscosity, float3 rij, float r2, float3 gradient, float volumeIJ, float3 pairRotation)
{
    return ViscosityCoupling(mixedViscosity, rij, r2, gradient, volumeIJ) * cross(pairRotation, rij);
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
