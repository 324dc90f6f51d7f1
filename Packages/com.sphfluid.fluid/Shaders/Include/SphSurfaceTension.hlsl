#ifndef SPHFLUID_SPH_SURFACE_TENSION_INCLUDED
#define SPHFLUID_SPH_SURFACE_TENSION_INCLUDED

#include "FluidConstants.hlsl"

#include "SphKernels.hlsl"

// Surface and interface tension of Akinci, Akinci & Teschner 2013, "Versatile surface tension and
// adhesion for SPH fluids" (SIGGRAPH Asia 2013, eqs. 1-7): cohesion plus a curvature term.
//   normal      n_i = h sum_j (1 / delta_j) gradW(r_ij)        (m_j / rho_j = 1 / delta_j)
//   cohesion    C(r) = 32 / (pi h^9) * { (h - r)^3 r^3                   if h/2 < r <= h
//                                       { 2 (h - r)^3 r^3 - h^6 / 64      if 0 < r <= h/2
//                                       { 0 otherwise
//   F_i^st = sum_{j same phase} K_ij ( -gamma m_i m_j C(r) r_ij / r  -  gamma m_i (n_i - n_j) ),
//   K_ij = 2 rho0 / (rho_i + rho_j)   (corrects the particle deficiency at the surface)
// gamma = the phase's SurfaceTension [N/m]. Only particles of the SAME phase attract: different
// phases feel no cohesion, and that asymmetry at an oil-water boundary is the interface tension.
// Deviation from the notes (documented): the normal is also summed over the SAME phase only, i.e. it
// is the gradient of the phase's own colour field, so a particle at an interface between two phases
// gets a normal (and the curvature term acts there); for one phase this is exactly Akinci's normal.
// Reads _CohesionCoefficient = 32 / (pi H^9) (FluidConstants.hlsl).

float Cohesion(float r)
{
    float h = _SmoothingRadius;
    if (r > h || r <= 0.0)
        return 0.0;
    float d = h - r;
    float term = d * d * d * r * r * r;
    if (2.0 * r > h)
        return _CohesionCoefficient * term;
    float h3 = h * h * h;
    return _CohesionCoefficient * (2.0 * term - h3 * h3 / 64.0);
}

// Force on i from one same-phase neighbour j (divide by m_i for the acceleration).
float3 SurfaceTensionForcePair(float tension, float restDensity, float massI, float massJ,
                               float densityI, float densityJ, float3 normalI, float3 normalJ,
                               float3 rij, float r)
{
    float k = 2.0 * restDensity / (densityI + densityJ);
    float3 cohesion = (-tension * massI * massJ * Cohesion(r) / r) * rij;
    float3 curvature = -tension * massI * (normalI - normalJ);
    return k * (cohesion + curvature);
}

#endif
