#ifndef SPHFLUID_FLUID_PARTICLES_PASS_INCLUDED
#define SPHFLUID_FLUID_PARTICLES_PASS_INCLUDED

// The one draw pass of the particles, shared by every render pipeline's shader (FluidParticles.shader for
// the Built-in pipeline, FluidParticlesUniversal.shader for URP), so the impostor and the optics are
// written once. A pipeline differs only in where the image behind the liquid and the sun come from; the
// including shader supplies those before including this file:
//   float3 BackgroundBehind(float4 positionCS)  the opaque scene at a (refracted) clip-space position
//   float4 SunPosition()                        directional: xyz towards the light, w = 0; else position, w = 1
//   float3 SunColor()                           the main light's colour, linear
// and includes UnityCG.cginc first (camera matrices, unity_OrthoParams, the reflection probe), which
// every pipeline's engine fills in the same way.
//
// Drawn procedurally: SV_InstanceID is the particle index into _Particles, SV_VertexID (0..5) the corner
// of its quad. Particles refract the opaque image, not each other; they write the depth of their true
// sphere surface.

#include "Particle.hlsl"
#include "Phase.hlsl"
#include "ParticleImpostorQuad.hlsl"
#include "ParticleImpostorSphere.hlsl"
#include "FluidOpticsRefraction.hlsl"
#include "FluidOpticsComposite.hlsl"

StructuredBuffer<Particle> _Particles;
StructuredBuffer<PhaseProperties> _Phases;

float _ParticleRadius;
float _RefractionStrength;
float _ReflectionStrength;
float _ThicknessScale;
float _ScatterStrength;
float _SpecularStrength;
float _SpecularPower;
float _AmbientMip;

struct ImpostorVaryings
{
    float4 positionCS : SV_POSITION;
    float3 quadPointWS : TEXCOORD0;
    nointerpolation float4 sphere : TEXCOORD1;   // centre (world, m), radius (m)
    nointerpolation float4 tint : TEXCOORD2;     // phase colour: linear RGB, opacity
    nointerpolation float2 optics : TEXCOORD3;   // Schlick F0, absorption (1/m)
};

struct ImpostorFragment
{
    float4 color : SV_Target;
    float depth : SV_Depth;
};

float3 CameraForwardWS()
{
    // Unity's view space looks down -z: row 2 of the view matrix is the world "backward" axis.
    return -UNITY_MATRIX_V[2].xyz;
}

float3 NormalizeOr(float3 v, float3 fallback)
{
    float lengthSquared = dot(v, v);
    return lengthSquared > 1e-12 ? v * rsqrt(lengthSquared) : fallback;
}

float3 SampleEnvironment(float3 directionWS, float mip)
{
    float4 encoded = UNITY_SAMPLE_TEXCUBE_LOD(unity_SpecCube0, directionWS, mip);
    return DecodeHDR(encoded, unity_SpecCube0_HDR);
}

ImpostorVaryings vert(uint vertexId : SV_VertexID, uint instanceId : SV_InstanceID)
{
    Particle particle = _Particles[instanceId];
    PhaseProperties phase = _Phases[particle.phase];

    float orthographic = unity_OrthoParams.w;
    float3 toEye = _WorldSpaceCameraPos.xyz - particle.position;
    float eyeDistance = length(toEye);
    float3 towardEye = orthographic > 0.5 ? -CameraForwardWS() : NormalizeOr(toEye, -CameraForwardWS());
    float radius = max(_ParticleRadius, 0.0);
    float halfSize = ImpostorHalfSize(radius, eyeDistance, orthographic);
    float3 quadPoint = ImpostorQuadVertex(particle.position, halfSize, ImpostorQuadCorner(vertexId),
        towardEye, UNITY_MATRIX_V[1].xyz, UNITY_MATRIX_V[0].xyz);

    ImpostorVaryings o;
    o.positionCS = mul(UNITY_MATRIX_VP, float4(quadPoint, 1.0));
    o.quadPointWS = quadPoint;
    o.sphere = float4(particle.position, radius);
    o.tint = phase.color;
    o.optics = float2(phase.fresnelF0, phase.absorption);
    return o;
}

ImpostorFragment frag(ImpostorVaryings i)
{
    float3 centre = i.sphere.xyz;
    float radius = i.sphere.w;
    float3 rayDirection = unity_OrthoParams.w > 0.5
        ? CameraForwardWS()
        : NormalizeOr(i.quadPointWS - _WorldSpaceCameraPos.xyz, CameraForwardWS());
    ImpostorHit hit = ImpostorIntersect(i.quadPointWS, rayDirection, centre, radius);
    clip(hit.covered - 0.5);

    float4 hitCS = mul(UNITY_MATRIX_VP, float4(hit.position, 1.0));
    float3 n = hit.normal;
    float4 lightPos = SunPosition();

    LiquidSurface surface;
    surface.normal = n;
    surface.toEye = -rayDirection;
    surface.toLight = NormalizeOr(lightPos.xyz - hit.position * lightPos.w, float3(0.0, 1.0, 0.0));
    surface.thickness = hit.thickness;
    surface.tint = i.tint;
    surface.fresnelF0 = i.optics.x;
    surface.absorption = i.optics.y;

    // The opaque image behind, at the screen position shifted by the normal.
    float3 normalVS = mul((float3x3)UNITY_MATRIX_V, n);

    LiquidLighting lighting;
    lighting.background = BackgroundBehind(RefractedClipPosition(hitCS, normalVS, _RefractionStrength));
    lighting.reflected = SampleEnvironment(reflect(rayDirection, n), 0.0);
    lighting.ambient = SampleEnvironment(n, _AmbientMip);
    lighting.lightColor = SunColor();

    LiquidLook look;
    look.thicknessScale = _ThicknessScale;
    look.scatterStrength = _ScatterStrength;
    look.reflectionStrength = _ReflectionStrength;
    look.specularStrength = _SpecularStrength;
    look.specularPower = _SpecularPower;

    ImpostorFragment o;
    o.color = float4(ShadeLiquid(surface, lighting, look), 1.0);
#if defined(UNITY_REVERSED_Z)
    o.depth = ImpostorDeviceDepth(hitCS, 0.0);
#else
    o.depth = ImpostorDeviceDepth(hitCS, UNITY_NEAR_CLIP_VALUE);
#endif
    return o;
}

#endif
