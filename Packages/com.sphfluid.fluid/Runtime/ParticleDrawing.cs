using System;
using SphFluid.Simulation;
using UnityEngine;
using UnityEngine.Rendering;
using Object = UnityEngine.Object;

namespace SphFluid.Runtime
{
    /// <summary>
    /// Draws a fluid's particles with one procedural call, six vertices a particle placed by the particle shader from
    /// the particle buffer: in the Built-in pipeline with the package's particle material, in URP with a copy of its
    /// values on the URP particle shader, and not at all (one warning) in any other pipeline. The call is made for each
    /// camera as it starts to render (Camera.onPreCull in the Built-in pipeline, RenderPipelineManager.
    /// beginCameraRendering in URP), not from Update: a draw submitted from Update lasts one frame, and a paused editor
    /// runs no Update but still renders its Scene and Game views, which then showed no fluid. Owns the URP copy and the
    /// two subscriptions; Dispose destroys the one and removes the other, so nothing static holds the fluid after it.
    /// </summary>
    sealed class ParticleDrawing : IDisposable
    {
        /// <summary>The "RenderPipeline" SubShader tag URP's asset reports; FluidParticlesUniversal.shader carries it.</summary>
        const string UniversalPipelineTag = "UniversalPipeline";

        readonly FluidResources _resources;
        readonly Fluid _owner; // its running simulation is what is drawn; it names the fluid in the Console
        readonly Transform _container; // the bound that culls the draw holds it at any rotation
        readonly MaterialPropertyBlock _properties = new MaterialPropertyBlock();
        Material _universalMaterial; // the particle material's values on the URP shader, made at the first URP draw
        bool _pipelineWarned;

        public ParticleDrawing(FluidResources resources, Fluid owner, Transform container)
        {
            _resources = resources;
            _owner = owner;
            _container = container;
            Camera.onPreCull += DrawFor;
            RenderPipelineManager.beginCameraRendering += DrawFor;
        }

        void DrawFor(ScriptableRenderContext context, Camera camera) => DrawFor(camera);

        /// <summary>Draws the owner's particles for <paramref name="camera"/> at the owner's particle radius and on its
        /// layer; nothing while it runs no simulation, once its container is gone, or for an inspector's preview
        /// camera, which renders a preview scene of its own.</summary>
        void DrawFor(Camera camera)
        {
            FluidSimulation simulation = _owner.Simulation;
            if (simulation == null || _container == null || camera.cameraType == CameraType.Preview) return;
            Material material = MaterialForPipeline();
            if (material == null) return;
            var particles = (UnityComputeBuffer)simulation.Particles; // alternates every sort: fetch at each draw
            var phases = (UnityComputeBuffer)simulation.PhaseTable;
            float radius = _owner.ParticleRadius;
            _properties.SetBuffer(ShaderIds.Particles, particles.Buffer);
            _properties.SetBuffer(ShaderIds.Phases, phases.Buffer);
            _properties.SetFloat(ShaderIds.ParticleRadius, radius);

            float reach = _container.lossyScale.magnitude + 4f * radius;
            var parameters = new RenderParams(material)
            {
                camera = camera,
                worldBounds = new Bounds(_container.position, new Vector3(reach, reach, reach)),
                matProps = _properties,
                layer = _owner.gameObject.layer,
                shadowCastingMode = ShadowCastingMode.Off,
                receiveShadows = false,
            };
            Graphics.RenderPrimitives(parameters, MeshTopology.Triangles, 6, simulation.ParticleCount);
        }

        public void Dispose()
        {
            Camera.onPreCull -= DrawFor;
            RenderPipelineManager.beginCameraRendering -= DrawFor;
            if (_universalMaterial != null) Object.Destroy(_universalMaterial);
            _universalMaterial = null;
        }

        /// <summary>
        /// The material for the active render pipeline: the resources' particle material itself in the Built-in
        /// pipeline (no pipeline asset), a copy of its values on the URP particle shader in URP, null (not drawn, one
        /// warning) for any other pipeline. Asked at every draw: the pipeline asset may change with the quality level.
        /// </summary>
        Material MaterialForPipeline()
        {
            Material particleMaterial = _resources.ParticleMaterial;
            RenderPipelineAsset pipeline = GraphicsSettings.currentRenderPipeline;
            if (pipeline == null) return particleMaterial;
            if (pipeline.renderPipelineShaderTag != UniversalPipelineTag)
            {
                if (!_pipelineWarned)
                    Debug.LogWarning($"Fluid '{_owner.name}': render pipeline '{pipeline.name}' (shader tag '{pipeline.renderPipelineShaderTag}') is neither Built-in nor URP ('{UniversalPipelineTag}'); the fluid is simulated but not drawn", _owner);
                _pipelineWarned = true;
                return null;
            }
            if (_universalMaterial == null)
            {
                _universalMaterial = new Material(_resources.UniversalParticleShader) { name = particleMaterial.name + " (URP)", hideFlags = HideFlags.DontSave };
                string missing = UniversalOpaqueTexture.MissingReason(pipeline, Camera.main);
                if (missing != null)
                    Debug.LogWarning($"Fluid '{_owner.name}': {missing}; the liquid shows no scene behind it", _owner);
            }
            _universalMaterial.CopyPropertiesFromMaterial(particleMaterial); // inspector edits of the material carry over
            return _universalMaterial;
        }

        /// <summary>Material property ids, looked up once (on first use, on the main thread).</summary>
        static class ShaderIds
        {
            public static readonly int Particles = Shader.PropertyToID("_Particles");
            public static readonly int Phases = Shader.PropertyToID("_Phases");
            public static readonly int ParticleRadius = Shader.PropertyToID("_ParticleRadius");
        }
    }
}
