// SPH particles as ray-cast sphere impostors that refract, reflect and absorb (Built-in render pipeline;
// FluidParticlesUniversal.shader is the same pass for URP, and Fluid picks the one that matches
// the active pipeline). The pass itself lives in Include/FluidParticlesPass.hlsl.
//
// Drawn by ONE procedural call per frame, no mesh and no CPU copy of the particles:
//   Graphics.RenderPrimitives(renderParams, MeshTopology.Triangles, 6, particleCount)
//   (or Graphics.DrawProcedural(material, bounds, MeshTopology.Triangles, 6, particleCount))
// SV_InstanceID is the particle index into _Particles, SV_VertexID (0..5) the corner of its quad.
// Buffers (material or global): _Particles (StructuredBuffer<Particle>, stride 32),
// _Phases (StructuredBuffer<PhaseProperties>, stride 48), indexed by Particle.phase.
// The named GrabPass copies what is already drawn into _FluidBackground (once per frame, at its first use);
// the Transparent queue puts that copy after the opaque objects and the skybox. Particles refract that
// image, not each other; they write the depth of their true sphere surface.
Shader "SphFluid/Particles"
{
    Properties
    {
        _ParticleRadius ("Particle radius (m)", Range(0.0005, 0.5)) = 0.012
        _RefractionStrength ("Refraction shift (fraction of half screen)", Range(0, 0.2)) = 0.03
        _ReflectionStrength ("Reflection strength", Range(0, 2)) = 1
        _ThicknessScale ("Liquid depth per impostor (x chord)", Range(1, 50)) = 6
        _ScatterStrength ("Body colour strength", Range(0, 2)) = 0.6
        _SpecularStrength ("Sun highlight strength", Range(0, 4)) = 1
        _SpecularPower ("Sun highlight sharpness", Range(8, 2048)) = 400
        _AmbientMip ("Ambient blur (reflection mip)", Range(0, 8)) = 6
    }

    SubShader
    {
        Tags { "Queue" = "Transparent" "RenderType" = "Transparent" "IgnoreProjector" = "True" }

        GrabPass { "_FluidBackground" }

        Pass
        {
            Name "FluidParticles"
            Tags { "LightMode" = "ForwardBase" }
            Cull Off
            ZWrite On
            ZTest LEqual
            Blend Off

            HLSLPROGRAM
            #pragma target 4.5
            #pragma vertex vert
            #pragma fragment frag

            #include "UnityCG.cginc"
            #include "UnityLightingCommon.cginc"

            Texture2D _FluidBackground;
            SamplerState sampler_FluidBackground;

            float3 BackgroundBehind(float4 positionCS)
            {
                // The grab texture's rows start at the top on D3D-like platforms whatever the projection.
                float4 grab = ComputeGrabScreenPos(positionCS);
                return _FluidBackground.SampleLevel(sampler_FluidBackground, grab.xy / max(grab.w, 1e-6), 0.0).rgb;
            }

            float4 SunPosition() { return _WorldSpaceLightPos0; }
            float3 SunColor() { return _LightColor0.rgb; }

            #include "Include/FluidParticlesPass.hlsl"
            ENDHLSL
        }
    }

    Fallback Off
}
