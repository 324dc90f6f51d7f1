// SPH particles as ray-cast sphere impostors that refract, reflect and absorb (Built-in render pipeline).
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
            #include "Include/Particle.hlsl"
            #include "Include/Phase.hlsl"
            #include "Include/ParticleImpostorQuad.hlsl"
            #include "Include/ParticleImpostorSphere.hlsl"
            #include "Include/FluidOpticsRefraction.hlsl"
            #include "Include/FluidOpticsComposite.hlsl"

            StructuredBuffer<Particle> _Particles;
            StructuredBuffer<PhaseProperties> _Phases;

            Texture2D _FluidBackground;
            SamplerState sampler_FluidBackground;

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
                float4 lightPos = _WorldSpaceLightPos0; // directional: w = 0, xyz towards the light

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
                float4 grab = ComputeGrabScreenPos(RefractedClipPosition(hitCS, normalVS, _RefractionStrength));
                float2 grabUV = grab.xy / max(grab.w, 1e-6);

                LiquidLighting lighting;
                lighting.background = _FluidBackground.SampleLevel(sampler_FluidBackground, grabUV, 0.0).rgb;
                lighting.reflected = SampleEnvironment(reflect(rayDirection, n), 0.0);
                lighting.ambient = SampleEnvironment(n, _AmbientMip);
                lighting.lightColor = _LightColor0.rgb;

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
            ENDHLSL
        }
    }

    Fallback Off
}
