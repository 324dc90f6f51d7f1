#ifndef SPHFLUID_FLUID_OPTICS_COMPOSITE_INCLUDED
#define SPHFLUID_FLUID_OPTICS_COMPOSITE_INCLUDED

#include "FluidOpticsFresnel.hlsl"
#include "FluidOpticsAbsorption.hlsl"

// How the light paths at one point of a liquid surface add up to the colour the eye sees:
//   C = (1 - F) (B T + S) + F E_r k_r + L_c H
//   F   = Schlick(F0, n.v)                                    share reflected (FluidOpticsFresnel.hlsl)
//   B T = background seen through the liquid, filtered by T = tint^(a L s)   (FluidOpticsAbsorption.hlsl;
//         L the chord through the impostor, s = thickness scale: only the front-most particle is drawn,
//         so one impostor stands for several particle layers of liquid behind it)
//   S   = tint (1 - T) (L_c (0.5 + 0.5 n.l) + E_a) k_s opacity   light the liquid scatters back: its body colour,
//         lit by the wrapped sun and the blurred environment E_a (single-scattering approximation)
//   E_r = environment in the mirror direction, k_r the reflection strength
//   H   = k_h (n.h)^p F(h.v)                                  Blinn-Phong highlight of the main light.
// Fresnel: Schlick 1994; absorption: Bouguer-Lambert-Beer as in van der Laan, Green & Sainz 2009;
// highlight: Blinn 1977, "Models of light reflection for computer synthesized pictures" (SIGGRAPH).

struct LiquidSurface
{
    float3 normal;     // unit outward normal
    float3 toEye;      // unit, surface to eye
    float3 toLight;    // unit, surface to main light
    float thickness;   // chord through the impostor, m
    float4 tint;       // phase colour: linear RGB, opacity of the body colour
    float fresnelF0;   // Schlick reflectance at normal incidence
    float absorption;  // Beer-Lambert coefficient, 1/m
};

struct LiquidLighting
{
    float3 background; // image behind the liquid, sampled at the refracted position
    float3 reflected;  // environment in the mirror direction
    float3 ambient;    // blurred environment around the normal
    float3 lightColor; // main light colour, 0 when there is none
};

struct LiquidLook
{
    float thicknessScale;
    float scatterStrength;
    float reflectionStrength;
    float specularStrength;
    float specularPower;
};

float3 ShadeLiquid(LiquidSurface s, LiquidLighting l, LiquidLook look)
{
    float3 transmittance = BeerLambertTransmittance(s.tint.rgb, s.absorption, s.thickness * look.thicknessScale);
    float3 sun = l.lightColor * (0.5 + 0.5 * dot(s.normal, s.toLight));
    float3 body = s.tint.rgb * (1.0 - transmittance) * (sun + l.ambient) * (look.scatterStrength * s.tint.a);
    float3 refracted = l.background * transmittance + body;

    float fresnel = SchlickFresnel(s.fresnelF0, dot(s.normal, s.toEye));
    float3 halfVector = s.toLight + s.toEye;
    float halfLength = length(halfVector);
    halfVector = halfLength > 1e-6 ? halfVector / halfLength : s.normal;
    float highlight = pow(saturate(dot(s.normal, halfVector)), look.specularPower) * look.specularStrength;
    float3 specular = l.lightColor * (highlight * SchlickFresnel(s.fresnelF0, dot(halfVector, s.toEye)));

    return lerp(refracted, l.reflected * look.reflectionStrength, fresnel) + specular;
}

#endif
