// The particles of FluidParticles.shader for the Universal Render Pipeline (URP 14, Unity 2022.3): the same
// pass (Include/FluidParticlesPass.hlsl) and the same Properties, so one material's values serve both and
// Fluid draws with this shader whenever URP is the active pipeline.
//
// URP has no GrabPass: the liquid refracts URP's copy of the opaque scene, _CameraOpaqueTexture, which URP
// makes only when "Opaque Texture" is ticked in the URP asset (Rendering > Opaque Texture) or on the camera
// (Rendering > Opaque Texture: On). Without it the texture is unbound and the liquid shows no scene behind it.
// The copy is taken after the opaque objects and the skybox, before the Transparent queue this pass runs in.
// Nothing here includes the URP package, so a Built-in project without URP installed still imports this
// shader cleanly: the opaque texture and the main light are declared by name as URP sets them
// (ShaderLibrary/DeclareOpaqueTexture.hlsl, Input.hlsl), and the camera matrices, unity_OrthoParams and the
// reflection probe come from UnityCG.cginc, which the engine fills in for every pipeline.
// Not supported: single-pass instanced XR (URP then makes the opaque texture a texture array).
Shader "SphFluid/ParticlesUniversal"
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
        Tags { "RenderPipeline" = "UniversalPipeline" "Queue" = "Transparent" "RenderType" = "Transparent" "IgnoreProjector" = "True" }

        Pass
        {
            Name "FluidParticles"
            Tags { "LightMode" = "UniversalForward" }
            Cull Off
            ZWrite On
            ZTest LEqual
            Blend Off

            HLSLPROGRAM
            #pragma target 4.5
            #pragma vertex vert
            #pragma fragment frag

            #include "UnityCG.cginc"

            Texture2D _CameraOpaqueTexture;
            SamplerState sampler_CameraOpaqueTexture;
            float4 _MainLightPosition; // URP: directional, xyz towards the light, w = 0
            float4 _MainLightColor;

            float3 BackgroundBehind(float4 positionCS)
            {
                // URP's targets follow the projection (_ProjectionParams.x flips y when rendering to a texture).
                float4 screen = ComputeScreenPos(positionCS);
                return _CameraOpaqueTexture.SampleLevel(sampler_CameraOpaqueTexture, screen.xy / max(screen.w, 1e-6), 0.0).rgb;
            }

            float4 SunPosition() { return _MainLightPosition; }
            float3 SunColor() { return _MainLightColor.rgb; }

            #include "Include/FluidParticlesPass.hlsl"
            ENDHLSL
        }
    }

    Fallback Off
}
