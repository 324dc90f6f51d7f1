using System;
using System.Collections.Generic;
using System.Linq;
using Silk.NET.Vulkan;
using SphFluid.Compute;

namespace SphFluid.Vulkan;

public sealed unsafe partial class VulkanComputeDevice
{
    readonly HashSet<VulkanTexture> _liveTextures = new();
    readonly List<VulkanTexture> _deferredTextureRelease = new();
    readonly Dictionary<SamplerSettings, Sampler> _samplers = new();

    /// <summary>A zeroed 2D texture for <c>Texture2D</c> / <c>RWTexture2D</c> (Unity: a RenderTexture with random write).</summary>
    public VulkanTexture CreateTexture2D(string name, int width, int height, VulkanTextureFormat format) =>
        CreateTexture(name, width, height, 1, 2, format);

    /// <summary>A zeroed 3D texture for <c>Texture3D</c> / <c>RWTexture3D</c> (Unity: a volume RenderTexture with random write).</summary>
    public VulkanTexture CreateTexture3D(string name, int width, int height, int depth, VulkanTextureFormat format) =>
        CreateTexture(name, width, height, depth, 3, format);

    VulkanTexture CreateTexture(string name, int width, int height, int depth, int dimensions, VulkanTextureFormat format)
    {
        ThrowIfDisposed();
        if (string.IsNullOrEmpty(name)) throw new ArgumentException("A texture needs a name (it appears in every error about it)", nameof(name));
        if (!Enum.IsDefined(typeof(VulkanTextureFormat), format))
            throw new ComputeException($"Texture '{name}': format {(int)format} is not one of {string.Join(", ", Enum.GetNames(typeof(VulkanTextureFormat)))}");
        uint limit = dimensions == 2 ? _limits.MaxImageDimension2D : _limits.MaxImageDimension3D;
        foreach (var (size, axis) in new[] { (width, "width"), (height, "height"), (depth, "depth") }.Take(dimensions))
            if (size < 1 || (uint)size > limit)
                throw new ComputeException($"Texture '{name}': {axis} {size} is outside [1, {limit}], this device's limit for {dimensions}D textures");
        _vk.GetPhysicalDeviceFormatProperties(_physical, format.VulkanFormat(), out var support);
        const FormatFeatureFlags needed = FormatFeatureFlags.StorageImageBit | FormatFeatureFlags.SampledImageBit;
        if ((support.OptimalTilingFeatures & needed) != needed)
            throw new ComputeException($"Texture '{name}': {DeviceName} cannot read and write {format} textures from kernels");

        var texture = new VulkanTexture(this, name, width, height, depth, dimensions, format);
        var info = new ImageCreateInfo
        {
            SType = StructureType.ImageCreateInfo,
            ImageType = dimensions == 2 ? ImageType.Type2D : ImageType.Type3D,
            Format = format.VulkanFormat(),
            Extent = new Extent3D((uint)width, (uint)height, (uint)depth),
            MipLevels = 1,
            ArrayLayers = 1,
            Samples = SampleCountFlags.Count1Bit,
            Tiling = ImageTiling.Optimal,
            Usage = ImageUsageFlags.StorageBit | ImageUsageFlags.SampledBit | ImageUsageFlags.TransferSrcBit | ImageUsageFlags.TransferDstBit,
            SharingMode = SharingMode.Exclusive,
            InitialLayout = ImageLayout.Undefined,
        };
        Check(_vk.CreateImage(_device, &info, null, out texture.Image), $"vkCreateImage (texture '{name}')");
        _vk.GetImageMemoryRequirements(_device, texture.Image, out var req);
        var alloc = new MemoryAllocateInfo
        {
            SType = StructureType.MemoryAllocateInfo, AllocationSize = req.Size,
            MemoryTypeIndex = FindMemoryType(req.MemoryTypeBits, MemoryPropertyFlags.DeviceLocalBit, MemoryPropertyFlags.DeviceLocalBit, 0),
        };
        if (_vk.AllocateMemory(_device, &alloc, null, out texture.Memory) != Result.Success)
        {
            _vk.DestroyImage(_device, texture.Image, null);
            throw new ComputeException($"Out of GPU memory allocating texture '{name}' ({texture}, {req.Size} bytes)");
        }
        _liveTextures.Add(texture);
        Check(_vk.BindImageMemory(_device, texture.Image, texture.Memory, 0), "vkBindImageMemory");
        var viewInfo = new ImageViewCreateInfo
        {
            SType = StructureType.ImageViewCreateInfo,
            Image = texture.Image,
            ViewType = dimensions == 2 ? ImageViewType.Type2D : ImageViewType.Type3D,
            Format = format.VulkanFormat(),
            SubresourceRange = new ImageSubresourceRange(ImageAspectFlags.ColorBit, 0, 1, 0, 1),
        };
        Check(_vk.CreateImageView(_device, &viewInfo, null, out texture.View), $"vkCreateImageView (texture '{name}')");

        WaitIdle();
        var image = texture.Image;
        Immediate(cmd =>
        {
            // Cleared as new buffers are, then left in GENERAL, where kernels use it.
            var toTransfer = new ImageMemoryBarrier
            {
                SType = StructureType.ImageMemoryBarrier,
                SrcAccessMask = 0,
                DstAccessMask = AccessFlags.TransferWriteBit,
                OldLayout = ImageLayout.Undefined,
                NewLayout = ImageLayout.TransferDstOptimal,
                SrcQueueFamilyIndex = Vk.QueueFamilyIgnored,
                DstQueueFamilyIndex = Vk.QueueFamilyIgnored,
                Image = image,
                SubresourceRange = new ImageSubresourceRange(ImageAspectFlags.ColorBit, 0, 1, 0, 1),
            };
            _vk.CmdPipelineBarrier(cmd, PipelineStageFlags.TopOfPipeBit, PipelineStageFlags.TransferBit, 0, 0, null, 0, null, 1, &toTransfer);
            var zero = default(ClearColorValue);
            var range = new ImageSubresourceRange(ImageAspectFlags.ColorBit, 0, 1, 0, 1);
            _vk.CmdClearColorImage(cmd, image, ImageLayout.TransferDstOptimal, &zero, 1, &range);
            Transition(cmd, image, ImageLayout.TransferDstOptimal, ImageLayout.General);
        });
        return texture;
    }

    /// <summary>Binds a texture to a kernel's <c>Texture2D/3D</c> or <c>RWTexture2D/3D</c> by name (Unity: <c>SetTexture</c>).</summary>
    public void SetTexture(IComputeProgram program, int kernel, int propertyId, VulkanTexture texture)
    {
        ThrowIfDisposed();
        var p = AsProgram(program, "SetTexture");
        p.CheckKernel(kernel);
        string name = PropertyName(propertyId);
        var t = AsTexture(texture, $"SetTexture '{name}' on kernel '{p.KernelName(kernel)}'");
        var variant = p.Variant(kernel);
        int index = Array.IndexOf(variant.TextureIds, propertyId);
        if (index >= 0) CheckTexture(p, variant, variant.Textures[index], t);
        else if (!p.AnyCompiledVariantDeclares(name))
            throw new ComputeException($"SetTexture: no kernel of {p.Path} declares a texture named '{name}' (kernel '{p.KernelName(kernel)}' reads " +
                                       (variant.Textures.Length == 0 ? "no texture" : string.Join(", ", variant.Textures.Select(r => r.Name))) + ")");
        p.TextureBindings[kernel][propertyId] = t;
    }

    VulkanTexture AsTexture(VulkanTexture texture, string what)
    {
        if (texture == null) throw new ArgumentNullException(nameof(texture), $"{what}: texture is null");
        if (!ReferenceEquals(texture.Device, this)) throw new ComputeException($"{what}: texture '{texture.Name}' was not created by this Vulkan device");
        texture.ThrowIfDisposed();
        return texture;
    }

    /// <summary>The HLSL declaration a texture resource stands for, e.g. "RWTexture3D&lt;float4&gt;".</summary>
    static string Declaration(SpirvResource r)
    {
        string element = r.ElementType;
        if (r.Kind == SpirvResourceKind.StorageImage)
            foreach (VulkanTextureFormat f in Enum.GetValues(typeof(VulkanTextureFormat)))
                if (f.SpirvFormat() == r.ImageFormat) element = f.HlslElement();
        return (r.Kind == SpirvResourceKind.StorageImage ? "RW" : "") + $"Texture{r.ImageDimensions}D<{element}>";
    }

    static void CheckTexture(VulkanProgram p, KernelVariant v, SpirvResource r, VulkanTexture t)
    {
        bool fits = r.ImageDimensions == t.Dimensions && r.ElementType == t.Format.Scalar()
                    && (r.Kind != SpirvResourceKind.StorageImage || r.ImageFormat == 0 || r.ImageFormat == t.Format.SpirvFormat());
        if (fits) return;
        var formats = Enum.GetValues(typeof(VulkanTextureFormat)).Cast<VulkanTextureFormat>()
            .Where(f => f.Scalar() == r.ElementType && (r.Kind != SpirvResourceKind.StorageImage || r.ImageFormat == 0 || f.SpirvFormat() == r.ImageFormat));
        throw new ComputeException($"Texture '{t.Name}' ({t}) does not fit '{r.Name}' of kernel '{v.Kernel}' in {p.Path}, a {Declaration(r)}; " +
                                   $"it needs a {r.ImageDimensions}D texture of {string.Join(" or ", formats)}");
    }

    internal void UploadTexture(VulkanTexture texture, ReadOnlySpan<byte> data)
    {
        ThrowIfDisposed();
        WaitIdle();
        EnsureStaging((ulong)data.Length);
        data.CopyTo(new Span<byte>(_stagingMapped, data.Length));
        var region = WholeTexture(texture);
        Immediate(cmd =>
        {
            Transition(cmd, texture.Image, ImageLayout.General, ImageLayout.TransferDstOptimal);
            _vk.CmdCopyBufferToImage(cmd, _staging, texture.Image, ImageLayout.TransferDstOptimal, 1, in region);
            Transition(cmd, texture.Image, ImageLayout.TransferDstOptimal, ImageLayout.General);
        });
    }

    internal void DownloadTexture(VulkanTexture texture, Span<byte> data)
    {
        ThrowIfDisposed();
        WaitIdle();
        EnsureStaging((ulong)data.Length);
        var region = WholeTexture(texture);
        Immediate(cmd =>
        {
            Transition(cmd, texture.Image, ImageLayout.General, ImageLayout.TransferSrcOptimal);
            _vk.CmdCopyImageToBuffer(cmd, texture.Image, ImageLayout.TransferSrcOptimal, _staging, 1, in region);
            Transition(cmd, texture.Image, ImageLayout.TransferSrcOptimal, ImageLayout.General);
        });
        new ReadOnlySpan<byte>(_stagingMapped, data.Length).CopyTo(data);
    }

    /// <summary>A layout change around a copy (copies are faster, and validation quieter, in the transfer layouts),
    /// ordered against every compute and transfer access before and after.</summary>
    void Transition(CommandBuffer cmd, Image image, ImageLayout from, ImageLayout to)
    {
        const AccessFlags any = AccessFlags.ShaderReadBit | AccessFlags.ShaderWriteBit | AccessFlags.TransferReadBit | AccessFlags.TransferWriteBit;
        var barrier = new ImageMemoryBarrier
        {
            SType = StructureType.ImageMemoryBarrier,
            SrcAccessMask = any,
            DstAccessMask = any,
            OldLayout = from,
            NewLayout = to,
            SrcQueueFamilyIndex = Vk.QueueFamilyIgnored,
            DstQueueFamilyIndex = Vk.QueueFamilyIgnored,
            Image = image,
            SubresourceRange = new ImageSubresourceRange(ImageAspectFlags.ColorBit, 0, 1, 0, 1),
        };
        const PipelineStageFlags stages = PipelineStageFlags.ComputeShaderBit | PipelineStageFlags.TransferBit;
        _vk.CmdPipelineBarrier(cmd, stages, stages, 0, 0, null, 0, null, 1, &barrier);
    }

    static BufferImageCopy WholeTexture(VulkanTexture t) => new BufferImageCopy
    {
        BufferOffset = 0,
        ImageSubresource = new ImageSubresourceLayers(ImageAspectFlags.ColorBit, 0, 0, 1),
        ImageExtent = new Extent3D((uint)t.Width, (uint)t.Height, (uint)t.Depth),
    };

    internal void Release(VulkanTexture texture)
    {
        if (_disposed || !_liveTextures.Contains(texture)) return;
        if (texture.LastUsedSerial > _completedSerial) _deferredTextureRelease.Add(texture);
        else DestroyTexture(texture);
    }

    void DestroyTexture(VulkanTexture texture)
    {
        if (!_liveTextures.Remove(texture)) return;
        if (texture.View.Handle != 0) _vk.DestroyImageView(_device, texture.View, null);
        _vk.DestroyImage(_device, texture.Image, null);
        _vk.FreeMemory(_device, texture.Memory, null);
        texture.View = default;
        texture.Image = default;
        texture.Memory = default;
    }

    void ReleaseDeferredTextures()
    {
        for (int i = _deferredTextureRelease.Count - 1; i >= 0; i--)
        {
            if (_deferredTextureRelease[i].LastUsedSerial > _completedSerial) continue;
            DestroyTexture(_deferredTextureRelease[i]);
            _deferredTextureRelease.RemoveAt(i);
        }
    }

    void DestroyAllTextures()
    {
        foreach (var t in _liveTextures.ToList()) DestroyTexture(t);
        _deferredTextureRelease.Clear();
        foreach (var s in _samplers.Values) _vk.DestroySampler(_device, s, null);
        _samplers.Clear();
    }

    /// <summary>The settings a kernel's <c>SamplerState</c> stands for: an inline sampler name, else
    /// <c>sampler&lt;Texture&gt;</c> of a texture bound to the same kernel, as in Unity.</summary>
    static SamplerSettings SamplerFor(VulkanProgram p, KernelVariant v, SpirvResource sampler, IReadOnlyList<VulkanTexture> textures)
    {
        SamplerSettings? inline;
        try { inline = SamplerSettings.FromInlineName(sampler.Name); }
        catch (ArgumentException e) { throw new ComputeException($"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: {e.Message}"); }
        if (inline != null) return inline.Value;
        if (sampler.Name.StartsWith("sampler", StringComparison.Ordinal))
        {
            string textureName = sampler.Name.Substring("sampler".Length);
            for (int i = 0; i < v.Textures.Length; i++)
                if (v.Textures[i].Name == textureName) return new SamplerSettings(textures[i].Filter, textures[i].Wrap);
        }
        throw new ComputeException($"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: SamplerState '{sampler.Name}' is neither an inline sampler " +
                                   "(a name with Point, Linear or Trilinear and Clamp, Repeat, Mirror or MirrorOnce, e.g. sampler_linear_clamp) " +
                                   "nor sampler<Texture> of a texture this kernel reads");
    }

    /// <summary>Linear filtering of 32-bit float formats is optional in Vulkan: refuse it by name where the device lacks
    /// it rather than let the driver return undefined values.</summary>
    void CheckLinearFiltering(VulkanProgram p, KernelVariant v, SpirvResource sampler, VulkanTexture[] textures)
    {
        for (int i = 0; i < textures.Length; i++)
        {
            if (v.Textures[i].Kind != SpirvResourceKind.SampledImage) continue;
            _vk.GetPhysicalDeviceFormatProperties(_physical, textures[i].Format.VulkanFormat(), out var support);
            if ((support.OptimalTilingFeatures & FormatFeatureFlags.SampledImageFilterLinearBit) == 0)
                throw new ComputeException($"Dispatch of kernel '{v.Kernel}' in {p.Path} refused: SamplerState '{sampler.Name}' filters linearly, " +
                                           $"but {DeviceName} cannot filter {textures[i].Format} textures such as '{textures[i].Name}'; use a point sampler");
        }
    }

    Sampler SamplerObject(SamplerSettings settings)
    {
        if (_samplers.TryGetValue(settings, out var sampler)) return sampler;
        var filter = settings.Filter == TextureFilter.Point ? Filter.Nearest : Filter.Linear;
        var wrap = settings.Wrap switch
        {
            TextureWrap.Clamp => SamplerAddressMode.ClampToEdge,
            TextureWrap.Mirror => SamplerAddressMode.MirroredRepeat,
            TextureWrap.MirrorOnce => SamplerAddressMode.MirrorClampToEdge,
            _ => SamplerAddressMode.Repeat,
        };
        var info = new SamplerCreateInfo
        {
            SType = StructureType.SamplerCreateInfo,
            MagFilter = filter, MinFilter = filter, MipmapMode = SamplerMipmapMode.Nearest,
            AddressModeU = wrap, AddressModeV = wrap, AddressModeW = wrap,
            MaxLod = 0,
        };
        Check(_vk.CreateSampler(_device, &info, null, out sampler), $"vkCreateSampler ({settings.Filter}, {settings.Wrap})");
        _samplers[settings] = sampler;
        return sampler;
    }
}
