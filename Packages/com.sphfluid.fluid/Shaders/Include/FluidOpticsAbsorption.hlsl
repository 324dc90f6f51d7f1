#ifndef SPHFLUID_FLUID_OPTICS_ABSORPTION_INCLUDED
#define SPHFLUID_FLUID_OPTICS_ABSORPTION_INCLUDED

// Light that survives a path through a coloured liquid (Bouguer-Lambert-Beer law):
//   T_c = exp(-sigma_c L),   sigma_c = -a ln(tint_c)   so that   T_c = tint_c^(a L)
// with a the phase's absorption coefficient (1/m), L the path length (m) and tint the phase colour:
// a layer 1/a metres thick filters white light to exactly the tint, thinner layers less, thicker more.
// Channels the tint lacks are absorbed fastest: water (blue-green tint) darkens reds, oil (amber) blues.
// As used for fluid thickness by van der Laan, Green & Sainz 2009, "Screen space fluid rendering with
// curvature flow" (I3D), and Green 2010, "Screen space fluid rendering for games" (GDC).
float3 BeerLambertTransmittance(float3 tint, float absorption, float pathLength)
{
    // A tint channel of 0 would absorb everything at any depth; 1e-3 keeps the logarithm finite.
    float3 sigma = -max(absorption, 0.0) * log(clamp(tint, 1e-3, 1.0));
    return exp(-sigma * max(pathLength, 0.0));
}

#endif
