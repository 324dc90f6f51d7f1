#ifndef SPHFLUID_STANDIN_UNITYCG_INCLUDED
#define SPHFLUID_STANDIN_UNITYCG_INCLUDED

// Test-only stand-in for the few Built-in render pipeline declarations FluidParticles.shader and
// FluidParticlesUniversal.shader use
// (Unity's UnityCG.cginc -> UnityShaderVariables.cginc -> HLSLSupport.cginc), so that glslang can
// compile the shader's HLSL in CI. Written from Unity's documented names and meanings, declaring ONLY
// what the shader needs: a new Unity built-in used by the shader must be added here, and the compile
// test then fails until it is, which is the point. Not part of the Unity project (it lives in Tests/).
//
// Platform: by default a D3D11/Vulkan/Metal-like target (reversed Z, clip z in [0, w], UV origin at the
// top). -DSPHFLUID_STANDIN_OPENGL=1 gives an OpenGL Core-like target (no reversed Z, clip z in
// [-w, w], UV origin at the bottom) so both depth paths of the shader are compiled.

#if SPHFLUID_STANDIN_OPENGL
    #define UNITY_NEAR_CLIP_VALUE (-1.0)
    #define UNITY_UV_STARTS_AT_TOP 0
#else
    #define UNITY_REVERSED_Z 1
    #define UNITY_NEAR_CLIP_VALUE (1.0)
    #define UNITY_UV_STARTS_AT_TOP 1
#endif

// Texture/sampler pairs as Unity declares them on DX11-style platforms.
#define UNITY_DECLARE_TEXCUBE(tex) TextureCube tex; SamplerState sampler##tex
#define UNITY_SAMPLE_TEXCUBE_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)

cbuffer UnityPerCamera
{
    float3 _WorldSpaceCameraPos;
    float4 _ProjectionParams; // x: 1 or -1 (flipped projection), y: near, z: far, w: 1/far
    float4 unity_OrthoParams; // x, y: orthographic half width/height, w: 1 orthographic, 0 perspective
};

cbuffer UnityPerFrame
{
    float4x4 unity_MatrixV;
    float4x4 unity_MatrixVP;
};

#define UNITY_MATRIX_V unity_MatrixV
#define UNITY_MATRIX_VP unity_MatrixVP

cbuffer UnityLighting
{
    float4 _WorldSpaceLightPos0; // directional: direction towards the light, w = 0; else position, w = 1
};

UNITY_DECLARE_TEXCUBE(unity_SpecCube0);

cbuffer UnityReflectionProbes
{
    float4 unity_SpecCube0_HDR; // x: multiplier, y: exponent applied to alpha, w: 1 when alpha is used
};

// RGBM/HDR decode of a reflection probe sample (linear colour space).
float3 DecodeHDR(float4 data, float4 decodeInstructions)
{
    float alpha = decodeInstructions.w * (data.a - 1.0) + 1.0;
    return (decodeInstructions.x * pow(abs(alpha), decodeInstructions.y)) * data.rgb;
}

// Clip-space position -> projective grab-texture coordinates (divide xy by w).
float4 ComputeGrabScreenPos(float4 positionCS)
{
#if UNITY_UV_STARTS_AT_TOP
    float scale = -1.0;
#else
    float scale = 1.0;
#endif
    float4 o = positionCS * 0.5;
    o.xy = float2(o.x, o.y * scale) + o.w;
    o.zw = positionCS.zw;
    return o;
}

// Clip-space position -> projective render-target coordinates (divide xy by w): follows the projection's
// flip (_ProjectionParams.x = -1 when the camera renders upside down into a texture).
float4 ComputeScreenPos(float4 positionCS)
{
    float4 o = positionCS * 0.5;
    o.xy = float2(o.x, o.y * _ProjectionParams.x) + o.w;
    o.zw = positionCS.zw;
    return o;
}

#endif
