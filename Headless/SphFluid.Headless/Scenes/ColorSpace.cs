using System;
using System.Numerics;

namespace SphFluid.Headless.Scenes;

/// <summary>The sRGB transfer curve (IEC 61966-2-1), as Unity's <c>Color.linear</c> applies it to inspector colours: a
/// scene stores a phase colour linear (PhaseDescription.Color), converted from the sRGB the inspector picks.</summary>
public static class ColorSpace
{
    public static float SrgbToLinear(float c) =>
        c <= 0.04045f ? c / 12.92f : MathF.Pow((c + 0.055f) / 1.055f, 2.4f);

    /// <summary>RGB converted, alpha kept.</summary>
    public static Vector4 SrgbToLinear(Vector4 c) => new(SrgbToLinear(c.X), SrgbToLinear(c.Y), SrgbToLinear(c.Z), c.W);
}
