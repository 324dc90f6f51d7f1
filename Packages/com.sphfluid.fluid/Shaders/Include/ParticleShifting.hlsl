#ifndef SPHFLUID_PARTICLE_SHIFTING_INCLUDED
#define SPHFLUID_PARTICLE_SHIFTING_INCLUDED

#include "FluidConstants.hlsl"

#include "SphKernels.hlsl"

// Particle shifting (Lind, Xu, Stansby & Rogers 2012, "Incompressible smoothed particle hydrodynamics for
// free-surface flows: A generalised diffusion-based algorithm for stability and validations for impulsive
// flows and propagating waves", JCP 231): after each sub-step every particle moves a little down the gradient
// of the particle concentration, as a Fickian diffusion would move it,
//   C_i      = sum_j V_j W(r_ij)                 V_j = 1 / delta_j (a boundary particle: omega_b / delta_i)
//   gradC_i  = sum_j V_j gradW(r_ij)
//   dr_i     = -D_i gradC_i,   D_i = A h |v_i| dt   (h = H / 2; the velocity-scaled coefficient of the paper's
//                                                    eq. 13, so a fluid at rest is not moved and dr stays a
//                                                    fixed fraction of the distance the particle travels)
// Particles bunched along streamlines or left in a strained lattice are spread back towards a uniform
// distribution, which the pressure alone does only by converting the lattice's stored energy into motion.
// The volume V_j = 1 / delta_j (not the rest volume) makes C = 1 in a uniformly compressed fluid, so the
// hydrostatic compression of a resting column is not mistaken for a concentration gradient; a wall's boundary
// particles count with the fluid particle's own volume so that the wall looks like more of the same fluid.
// Free surface (Lind et al. 2012, sec. 3.2): where the kernel is truncated gradC points into the fluid and would
// push the particle out through the surface; there the component along the surface normal n = -gradC / |gradC|
// is removed and only the shift along the surface is kept. The surface is found, as in the paper, by the
// divergence of position,
//   div r_i  = -sum_j V_j r_ij . gradW(r_ij)       (3 inside a full support in 3-D, about half that at a surface)
// below SHIFTING_SURFACE_DIVERGENCE. (The particle's own density is no test: the free-surface layer packs until
// it is nearly at rest density. Left with the normal shift, a surface particle is lifted every sub-step while
// gravity pulls it down, and with D proportional to |v| the two settled at a fall of 0.3 m/s in place in a
// resting tank.)
// Phase interfaces (Mokos, Rogers & Stansby 2017, "A multi-phase particle shifting algorithm for SPH
// simulations of violent hydrodynamics with a large number of particles", J. Hydraulic Research 55): a particle
// with neighbours of another phase keeps only the shift along the interface, whose normal is the gradient of
// the other phases' concentration, so shifting never mixes the phases across it.
// The shift is capped at SHIFTING_MAX_FRACTION of the particle spacing per sub-step (the paper's safeguard
// against a violent splash). Velocities are not corrected for the shift: at |dr| << s the Taylor correction
// (dr . grad) v is below the solver's noise.

#define SHIFTING_SURFACE_DIVERGENCE 2.8
#define SHIFTING_MAX_FRACTION 0.05

// Reads _ShiftingCoefficient = A h, m (A dimensionless, h = H / 2), from FluidConstants.hlsl.

// One neighbour's share of C and gradC: (V_j W, V_j gradW).
float4 ConcentrationPair(float volumeJ, float weight, float3 gradient)
{
    return float4(volumeJ * gradient, volumeJ * weight);
}

// The part of v normal to a unit vector n removed (n = 0 leaves v whole).
float3 TangentialPart(float3 v, float3 n)
{
    return v - dot(v, n) * n;
}

// One neighbour's share of div r: -V_j r_ij . gradW.
float PositionDivergencePair(float volumeJ, float3 rij, float3 gradient)
{
    return -volumeJ * dot(rij, gradient);
}

// dr_i from C_i (w) and gradC_i (xyz), the other phases' concentration gradient, div r_i, the speed and the sub-step.
float3 ShiftOf(float4 concentration, float3 otherPhaseGradient, float positionDivergence, float speed, float timeStep, float spacing)
{
    float3 shift = -(_ShiftingCoefficient * speed * timeStep) * concentration.xyz;
    float gradientLength2 = dot(concentration.xyz, concentration.xyz);
    if (positionDivergence < SHIFTING_SURFACE_DIVERGENCE && gradientLength2 > 0.0)
        shift = TangentialPart(shift, concentration.xyz * rsqrt(gradientLength2));
    float interfaceLength2 = dot(otherPhaseGradient, otherPhaseGradient);
    if (interfaceLength2 > 0.0)
        shift = TangentialPart(shift, otherPhaseGradient * rsqrt(interfaceLength2));
    float length2 = dot(shift, shift);
    float cap = SHIFTING_MAX_FRACTION * spacing;
    return length2 > cap * cap ? shift * (cap * rsqrt(length2)) : shift;
}

#endif
