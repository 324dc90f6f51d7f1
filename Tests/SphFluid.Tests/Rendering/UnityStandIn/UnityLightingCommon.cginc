#ifndef SPHFLUID_STANDIN_UNITY_LIGHTING_COMMON_INCLUDED
#define SPHFLUID_STANDIN_UNITY_LIGHTING_COMMON_INCLUDED

// Test-only stand-in for Unity's UnityLightingCommon.cginc: the main light's colour in ForwardBase
// (see UnityCG.cginc beside this file for why it exists).
float4 _LightColor0;

#endif
