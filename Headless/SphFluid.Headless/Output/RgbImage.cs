using System;

namespace SphFluid.Headless.Output;

/// <summary>An 8-bit RGB raster, row-major from the top-left corner.</summary>
public sealed class RgbImage
{
    public int Width { get; }
    public int Height { get; }

    /// <summary>Three bytes per pixel (R, G, B), <see cref="Width"/> pixels per row.</summary>
    public byte[] Pixels { get; }

    public RgbImage(int width, int height)
    {
        if (width < 1 || width > 16384) throw new ArgumentOutOfRangeException(nameof(width), width, "image width must be in [1, 16384]");
        if (height < 1 || height > 16384) throw new ArgumentOutOfRangeException(nameof(height), height, "image height must be in [1, 16384]");
        Width = width;
        Height = height;
        Pixels = new byte[width * height * 3];
    }

    public void Fill(Rgb color)
    {
        for (int i = 0; i < Pixels.Length; i += 3)
        {
            Pixels[i] = color.R;
            Pixels[i + 1] = color.G;
            Pixels[i + 2] = color.B;
        }
    }

    public void Set(int x, int y, Rgb color)
    {
        if ((uint)x >= (uint)Width || (uint)y >= (uint)Height) return;
        int i = (y * Width + x) * 3;
        Pixels[i] = color.R;
        Pixels[i + 1] = color.G;
        Pixels[i + 2] = color.B;
    }

    public Rgb Get(int x, int y)
    {
        int i = (y * Width + x) * 3;
        return new Rgb(Pixels[i], Pixels[i + 1], Pixels[i + 2]);
    }

    /// <summary>A filled disc (a particle splat), clipped to the image.</summary>
    public void FillDisc(float cx, float cy, float radius, Rgb color)
    {
        int x0 = (int)MathF.Floor(cx - radius), x1 = (int)MathF.Ceiling(cx + radius);
        int y0 = (int)MathF.Floor(cy - radius), y1 = (int)MathF.Ceiling(cy + radius);
        float r2 = radius * radius;
        for (int y = Math.Max(0, y0); y <= Math.Min(Height - 1, y1); y++)
        {
            float dy = y + 0.5f - cy;
            for (int x = Math.Max(0, x0); x <= Math.Min(Width - 1, x1); x++)
            {
                float dx = x + 0.5f - cx;
                if (dx * dx + dy * dy <= r2) Set(x, y, color);
            }
        }
    }

    /// <summary>A one-pixel line (Bresenham), clipped to the image.</summary>
    public void DrawLine(float ax, float ay, float bx, float by, Rgb color)
    {
        int x0 = (int)MathF.Round(ax), y0 = (int)MathF.Round(ay), x1 = (int)MathF.Round(bx), y1 = (int)MathF.Round(by);
        int dx = Math.Abs(x1 - x0), sx = x0 < x1 ? 1 : -1;
        int dy = -Math.Abs(y1 - y0), sy = y0 < y1 ? 1 : -1;
        int err = dx + dy;
        for (int guard = 0; guard < 1 << 16; guard++)
        {
            Set(x0, y0, color);
            if (x0 == x1 && y0 == y1) break;
            int e2 = 2 * err;
            if (e2 >= dy) { err += dy; x0 += sx; }
            if (e2 <= dx) { err += dx; y0 += sy; }
        }
    }
}

/// <summary>An 8-bit sRGB colour.</summary>
public readonly record struct Rgb(byte R, byte G, byte B)
{
    /// <summary>From a linear RGB colour in [0, 1] (the phase table's colours are linear, as Unity's are in a linear project).</summary>
    public static Rgb FromLinear(float r, float g, float b) => new(Encode(r), Encode(g), Encode(b));

    static byte Encode(float linear)
    {
        float c = Math.Clamp(float.IsFinite(linear) ? linear : 0f, 0f, 1f);
        float s = c <= 0.0031308f ? 12.92f * c : 1.055f * MathF.Pow(c, 1f / 2.4f) - 0.055f;
        return (byte)Math.Clamp((int)MathF.Round(s * 255f), 0, 255);
    }

    public Rgb Scale(float factor) => new(
        (byte)Math.Clamp((int)(R * factor), 0, 255), (byte)Math.Clamp((int)(G * factor), 0, 255), (byte)Math.Clamp((int)(B * factor), 0, 255));
}
