using System;
using System.Buffers.Binary;
using System.IO;
using System.IO.Compression;
using System.IO.Hashing;
using System.Text;

namespace SphFluid.Headless.Output;

/// <summary>
/// Writes an <see cref="RgbImage"/> as a PNG (ISO/IEC 15948): signature, IHDR (8-bit truecolour),
/// one zlib-compressed IDAT of filtered scanlines, IEND. Each scanline uses the Sub filter, which
/// suits flat-coloured snapshots well and keeps the encoder a few lines long.
/// </summary>
public static class PngEncoder
{
    public static readonly byte[] Signature = { 0x89, (byte)'P', (byte)'N', (byte)'G', 0x0D, 0x0A, 0x1A, 0x0A };

    public const byte FilterNone = 0, FilterSub = 1;

    public static byte[] Encode(RgbImage image)
    {
        ArgumentNullException.ThrowIfNull(image);
        using var png = new MemoryStream();
        png.Write(Signature);

        var header = new byte[13];
        BinaryPrimitives.WriteInt32BigEndian(header.AsSpan(0), image.Width);
        BinaryPrimitives.WriteInt32BigEndian(header.AsSpan(4), image.Height);
        header[8] = 8;  // bit depth
        header[9] = 2;  // colour type: truecolour
        header[10] = 0; // compression: deflate
        header[11] = 0; // filter method 0
        header[12] = 0; // no interlace
        WriteChunk(png, "IHDR", header);
        WriteChunk(png, "IDAT", CompressScanlines(image));
        WriteChunk(png, "IEND", Array.Empty<byte>());
        return png.ToArray();
    }

    public static void Write(Stream file, RgbImage image) => file.Write(Encode(image));

    static byte[] CompressScanlines(RgbImage image)
    {
        int rowBytes = image.Width * 3;
        var raw = new byte[image.Height * (rowBytes + 1)];
        for (int y = 0; y < image.Height; y++)
        {
            int src = y * rowBytes, dst = y * (rowBytes + 1);
            raw[dst] = FilterSub;
            for (int i = 0; i < rowBytes; i++)
            {
                byte left = i >= 3 ? image.Pixels[src + i - 3] : (byte)0;
                raw[dst + 1 + i] = (byte)(image.Pixels[src + i] - left);
            }
        }
        using var compressed = new MemoryStream();
        using (var zlib = new ZLibStream(compressed, CompressionLevel.Optimal, leaveOpen: true))
            zlib.Write(raw);
        return compressed.ToArray();
    }

    static void WriteChunk(Stream png, string type, byte[] data)
    {
        Span<byte> word = stackalloc byte[4];
        BinaryPrimitives.WriteInt32BigEndian(word, data.Length);
        png.Write(word);
        byte[] typeBytes = Encoding.ASCII.GetBytes(type);
        png.Write(typeBytes);
        png.Write(data);
        var crc = new Crc32();
        crc.Append(typeBytes);
        crc.Append(data);
        BinaryPrimitives.WriteUInt32BigEndian(word, crc.GetCurrentHashAsUInt32());
        png.Write(word);
    }
}
