using Silk.NET.Vulkan;

namespace SphFluid.Vulkan;

/// <summary>Texel formats a <see cref="VulkanTexture"/> can have, named as Unity's <c>GraphicsFormat</c> names them.
/// Each is what glslang declares for one <c>RWTexture</c> element type, so a kernel can write it without the
/// optional write-without-format feature.</summary>
public enum VulkanTextureFormat
{
    /// <summary><c>RWTexture&lt;float&gt;</c></summary>
    R32_SFloat,
    /// <summary><c>RWTexture&lt;float2&gt;</c></summary>
    R32G32_SFloat,
    /// <summary><c>RWTexture&lt;float4&gt;</c></summary>
    R32G32B32A32_SFloat,
    /// <summary><c>RWTexture&lt;uint&gt;</c></summary>
    R32_UInt,
    /// <summary><c>RWTexture&lt;int&gt;</c></summary>
    R32_SInt,
    /// <summary><c>RWTexture&lt;uint4&gt;</c></summary>
    R32G32B32A32_UInt,
}

/// <summary>How each <see cref="VulkanTextureFormat"/> appears to Vulkan, to SPIR-V and to HLSL.</summary>
public static class TexelEncoding
{
    public static Format VulkanFormat(this VulkanTextureFormat f) => f switch
    {
        VulkanTextureFormat.R32_SFloat => Format.R32Sfloat,
        VulkanTextureFormat.R32G32_SFloat => Format.R32G32Sfloat,
        VulkanTextureFormat.R32G32B32A32_SFloat => Format.R32G32B32A32Sfloat,
        VulkanTextureFormat.R32_UInt => Format.R32Uint,
        VulkanTextureFormat.R32_SInt => Format.R32Sint,
        _ => Format.R32G32B32A32Uint,
    };

    /// <summary>The SPIR-V <c>ImageFormat</c> glslang writes for an <c>RWTexture</c> of this format's element type.</summary>
    public static uint SpirvFormat(this VulkanTextureFormat f) => f switch
    {
        VulkanTextureFormat.R32_SFloat => 3,
        VulkanTextureFormat.R32G32_SFloat => 6,
        VulkanTextureFormat.R32G32B32A32_SFloat => 1,
        VulkanTextureFormat.R32_UInt => 33,
        VulkanTextureFormat.R32_SInt => 24,
        _ => 30,
    };

    /// <summary>The HLSL scalar a texel is made of: "float", "uint" or "int".</summary>
    public static string Scalar(this VulkanTextureFormat f) => f switch
    {
        VulkanTextureFormat.R32_UInt or VulkanTextureFormat.R32G32B32A32_UInt => "uint",
        VulkanTextureFormat.R32_SInt => "int",
        _ => "float",
    };

    public static int BytesPerTexel(this VulkanTextureFormat f) => f switch
    {
        VulkanTextureFormat.R32G32_SFloat => 8,
        VulkanTextureFormat.R32G32B32A32_SFloat or VulkanTextureFormat.R32G32B32A32_UInt => 16,
        _ => 4,
    };

    /// <summary>The HLSL element type of an <c>RWTexture</c> in this format, e.g. "float4".</summary>
    public static string HlslElement(this VulkanTextureFormat f)
    {
        int components = f.BytesPerTexel() / 4;
        return components == 1 ? f.Scalar() : f.Scalar() + components;
    }
}
