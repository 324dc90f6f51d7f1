#ifndef SPHFLUID_FLUID_OPTICS_FRESNEL_INCLUDED
#define SPHFLUID_FLUID_OPTICS_FRESNEL_INCLUDED

// Share of light a liquid surface reflects, the rest being refracted into it.
// Schlick's approximation of the Fresnel equations for an unpolarised dielectric interface:
//   F(theta) = F0 + (1 - F0) (1 - cos theta)^5,   F0 = ((n1 - n2) / (n1 + n2))^2
// (air/water n = 1.33: F0 = 0.020; air/oil n = 1.47: F0 = 0.036), theta the angle between the view
// ray and the surface normal. Schlick 1994, "An inexpensive BRDF model for physically-based
// rendering", Computer Graphics Forum 13(3).
float SchlickFresnel(float f0, float cosTheta)
{
    float m = 1.0 - saturate(cosTheta);
    float m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

#endif
