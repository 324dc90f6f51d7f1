using System;
using System.Text.RegularExpressions;

namespace SphFluid.Vulkan;

/// <summary>How a <c>SamplerState</c> filters between texels (Unity's FilterMode; trilinear is linear with one mip level).</summary>
public enum TextureFilter { Point, Linear }

/// <summary>What a <c>SamplerState</c> reads outside [0, 1] (Unity's TextureWrapMode).</summary>
public enum TextureWrap { Repeat, Clamp, Mirror, MirrorOnce }

/// <summary>
/// The filter and wrap a kernel's <c>SamplerState</c> samples with, found as Unity finds them: an "inline" sampler
/// whose name holds a filter word (Point, Linear, Trilinear) and a wrap word (Clamp, Repeat, Mirror, MirrorOnce),
/// such as <c>sampler_linear_clamp</c>, or <c>sampler&lt;TextureName&gt;</c>, which takes the texture's own settings.
/// </summary>
public readonly record struct SamplerSettings(TextureFilter Filter, TextureWrap Wrap)
{
    static readonly Regex PerAxisWrap = new("(clamp|repeat|mirror|mirroronce)[uvw]", RegexOptions.IgnoreCase);

    /// <summary>The settings an inline sampler name asks for, or null when the name is not an inline sampler.</summary>
    /// <exception cref="ArgumentException">The name asks for something this backend does not do (per-axis wrap,
    /// comparison, anisotropy); the message says what.</exception>
    public static SamplerSettings? FromInlineName(string name)
    {
        string n = name.ToLowerInvariant();
        TextureFilter? filter = n.Contains("point") ? TextureFilter.Point
            : n.Contains("linear") ? TextureFilter.Linear // also "trilinear"
            : null;
        TextureWrap? wrap = n.Contains("mirroronce") ? TextureWrap.MirrorOnce
            : n.Contains("mirror") ? TextureWrap.Mirror
            : n.Contains("clamp") ? TextureWrap.Clamp
            : n.Contains("repeat") ? TextureWrap.Repeat
            : null;
        if (filter == null || wrap == null) return null;
        if (PerAxisWrap.IsMatch(name)) throw new ArgumentException($"inline sampler '{name}' sets the wrap per axis, which the headless backend does not support; use one wrap word");
        if (n.Contains("compare")) throw new ArgumentException($"inline sampler '{name}' asks for a comparison sampler, which the headless backend does not support");
        if (n.Contains("aniso")) throw new ArgumentException($"inline sampler '{name}' asks for anisotropic filtering, which the headless backend does not support");
        return new SamplerSettings(filter.Value, wrap.Value);
    }
}
