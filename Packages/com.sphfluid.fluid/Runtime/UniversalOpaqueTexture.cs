using UnityEngine;
using UnityEngine.Rendering;
#if SPHFLUID_URP
using UnityEngine.Rendering.Universal;
#endif

namespace SphFluid.Runtime
{
    /// <summary>
    /// Whether a camera in URP gets the copy of the opaque scene (_CameraOpaqueTexture) the URP particle shader
    /// refracts. With the URP package in the project (SPHFLUID_URP, set by the runtime asmdef's versionDefines) the
    /// answer is URP's own: the camera's override of the asset's Opaque Texture, and no copy for Overlay cameras. A
    /// project without the package never runs URP, but the check still compiles: it then reads the asset's setting by
    /// name, which cannot see a camera's override.
    /// </summary>
    static class UniversalOpaqueTexture
    {
        /// <summary>Why <paramref name="camera"/> (null: the pipeline's default camera) renders without the opaque
        /// texture under <paramref name="pipeline"/>, or null when it has one or it cannot be told.</summary>
        public static string MissingReason(RenderPipelineAsset pipeline, Camera camera)
        {
#if SPHFLUID_URP
            if (!(pipeline is UniversalRenderPipelineAsset asset)) return null;
            // URP gives a camera without UniversalAdditionalCameraData the asset's settings (UniversalRenderPipeline.InitializeAdditionalCameraData).
            if (camera == null || !camera.TryGetComponent(out UniversalAdditionalCameraData cameraData))
                return asset.supportsCameraOpaqueTexture ? null : AssetOff(asset.name) + " and the camera uses the pipeline's setting";
            if (cameraData.renderType == CameraRenderType.Overlay)
                return $"camera '{camera.name}' is an Overlay camera, which URP never gives an opaque texture; draw the fluid with the base camera";
            if (cameraData.requiresColorTexture) return null;
            return cameraData.requiresColorOption == CameraOverrideOption.Off
                ? $"camera '{camera.name}' turns Opaque Texture off (Camera > Rendering > Opaque Texture)"
                : AssetOff(asset.name) + $" and camera '{camera.name}' uses the pipeline's setting";
#else
            // Read by name: the project must compile without the URP package.
            if (pipeline.GetType().GetProperty("supportsCameraOpaqueTexture")?.GetValue(pipeline) is bool opaque && !opaque)
                return AssetOff(pipeline.name) + " unless the camera turns it on";
            return null;
#endif
        }

        static string AssetOff(string asset) => $"URP asset '{asset}' has Opaque Texture off (Rendering > Opaque Texture)";
    }
}
