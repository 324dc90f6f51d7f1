#ifndef SPHFLUID_FLUID_OPTICS_REFRACTION_INCLUDED
#define SPHFLUID_FLUID_OPTICS_REFRACTION_INCLUDED

// Where to sample the image behind the liquid: screen-space refraction by normal offset.
// Snell's law n1 sin(theta1) = n2 sin(theta2) bends a ray entering a denser liquid towards -n, so the
// background it meets lies displaced against the tangential part of the normal. Screen-space
// approximation: shift the sample point in normalised device coordinates by
//   delta_ndc = -s * n_view.xy
// with s (_RefractionStrength) the shift, as a fraction of the half screen, at grazing incidence.
// Working in clip space (x, y scaled by w) keeps the shift independent of the particle's distance and
// lets the caller turn it into grab-texture coordinates the same way as the unshifted point.
// Sousa 2005, "Generic refraction simulation", GPU Gems 2, ch. 19.
float4 RefractedClipPosition(float4 positionCS, float3 normalVS, float strength)
{
    float4 shifted = positionCS;
    shifted.xy -= normalVS.xy * (strength * positionCS.w);
    return shifted;
}

#endif
