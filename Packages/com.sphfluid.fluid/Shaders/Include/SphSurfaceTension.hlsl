#ifndef SPHFLUID_SPH_SURFACE_TENSION_INCLUDED
#define SPHFLUID_SPH_SURFACE_TENSION_INCLUDED

#include "FluidConstants.hlsl"

// Surface tension as the continuum surface force of Brackbill, Kothe & Zemach 1992, "A continuum method for modeling
// surface tension", in the SPH form of Morris 2000, "Simulating surface tension with smoothed particle hydrodynamics":
//   colour gradient  g_i = sum_{j same phase} (1 / delta_j) gradW(r_ij)   (the Normals pass stores n_i = H g_i)
//   curvature        kappa_i = -div n^ = -sum_{j same phase} w_i w_j (1 / delta_j) (n^_j - n^_i) . gradW(r_ij)
//   force            F_i = (sigma / share) kappa_i g_i V0_i,   V0_i = m_i / rho0
// sigma is the phase's SurfaceTension in N/m. Across a surface the colour field falls from 1 to 0, so |g| integrates to
// 1 through it and the force to the Laplace pressure sigma kappa, whatever the kernel, support or spacing. The particles
// sit only on the inner part of that fall and their curvature sum misses the neighbours beyond it; the share of the
// pressure they make, measured, is divided out (_SurfaceForceScale = 1 / (H share), SurfaceLayerShare.cs). The weight
// w ramps from 0 at |n| = 0.05 to 1 at 0.2 (Morris cuts at a threshold instead): deeper in, the colour gradient vanishes
// and its direction is noise, and a ramp keeps the force from jumping as a normal crosses it. The particle's rest volume
// V0 stands for 1 / delta_i, which a particle torn loose from the surface would make large. Each phase's colour field
// counts its own particles only, so an oil-water interface carries both liquids' tensions. The force is normal to the
// surface and puts no tension along the surface layer, which a surface stress does and which tears that layer apart
// (Headless/docs/physics.md). It is not a pair force, so momentum is conserved only as far as the curvature is smooth.

// How much a particle's normal counts, from 0 where |n| = H |g| is bulk noise to 1 where it is clearly a surface's; a
// ramp rather than a cut so that the force does not jump as a particle's normal crosses it.
float SurfaceWeight(float3 normal)
{
    return smoothstep(0.05, 0.2, length(normal));
}

// Force on i from one same-phase neighbour j (divide by m_i for the acceleration). normalI/J = H g (Normals pass),
// numberDensityJ = delta_j (_Densities.z), restVolumeI = m_i / rho0, gradient = gradW(r_ij) as the pressure force takes it.
float3 SurfaceTensionForcePair(float sigma, float3 normalI, float3 normalJ, float restVolumeI, float numberDensityJ,
                               float3 gradient)
{
    float weight = SurfaceWeight(normalI) * SurfaceWeight(normalJ);
    if (weight <= 0.0)
        return float3(0.0, 0.0, 0.0);
    float divergence = weight * dot(normalize(normalJ) - normalize(normalI), gradient) / numberDensityJ;
    return (-sigma * _SurfaceForceScale * divergence * restVolumeI) * normalI;
}

#endif
