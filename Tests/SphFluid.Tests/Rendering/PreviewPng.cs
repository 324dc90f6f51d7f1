using System;
using System.IO;
using System.IO.Compression;
using System.IO.Hashing;
using System.Numerics;
using System.Text;

namespace SphFluid.Tests.Rendering
{
    /// <summary>Writes a linear-colour preview image as an 8-bit sRGB PNG (one IDAT, no filtering): for eyes, not for checks.</summary>
    public static class PreviewPng
    {
        public static void Write(string path, Vector4[] linearPixels, int width, int height)
        {
            var raw = new byte[height * (1 + width * 3)];
            for (int y = 0; y < height; y++)
            {
                int row = y * (1 + width * 3);
                raw[row] = 0; // filter: none
                for (int x = 0; x < width; x++)
                {
                    Vector4 c = linearPixels[y * width + x];
                    raw[row + 1 + x * 3] = ToSrgb8(c.X);
                    raw[row + 2 + x * 3] = ToSrgb8(c.Y);
                    raw[row + 3 + x * 3] = ToSrgb8(c.Z);
                }
            }
            byte[] compressed;
            using (var buffer = new MemoryStream())
            {
                using (var z = new ZLibStream(buffer, CompressionLevel.Optimal, true)) z.Write(raw, 0, raw.Length);
                compressed = buffer.ToArray();
            }
            var header = new byte[13];
            WriteBigEndian(header, 0, (uint)width);
            WriteBigEndian(header, 4, (uint)height);
            header[8] = 8; // bit depth
            header[9] = 2; // colour type: RGB
            Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(path)) ?? throw new ArgumentException("a file path, not a root", nameof(path)));
            using (var file = File.Create(path))
            {
                file.Write(new byte[] { 0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A }, 0, 8);
                WriteChunk(file, "IHDR", header);
                WriteChunk(file, "IDAT", compressed);
                WriteChunk(file, "IEND", new byte[0]);
            }
        }

        static byte ToSrgb8(float linear)
        {
            double c = Math.Clamp(double.IsNaN(linear) ? 0.0 : linear, 0.0, 1.0);
            double s = c <= 0.0031308 ? 12.92 * c : 1.055 * Math.Pow(c, 1.0 / 2.4) - 0.055;
            return (byte)Math.Round(s * 255.0);
        }

        static void WriteChunk(Stream stream, string type, byte[] data)
        {
            var length = new byte[4];
            WriteBigEndian(length, 0, (uint)data.Length);
            stream.Write(length, 0, 4);
            byte[] typeBytes = Encoding.ASCII.GetBytes(type);
            stream.Write(typeBytes, 0, 4);
            stream.Write(data, 0, data.Length);
            var crc = new Crc32();
            crc.Append(typeBytes);
            crc.Append(data);
            var crcBytes = new byte[4];
            WriteBigEndian(crcBytes, 0, crc.GetCurrentHashAsUInt32());
            stream.Write(crcBytes, 0, 4);
        }

        static void WriteBigEndian(byte[] target, int offset, uint value)
        {
            target[offset] = (byte)(value >> 24);
            target[offset + 1] = (byte)(value >> 16);
            target[offset + 2] = (byte)(value >> 8);
            target[offset + 3] = (byte)value;
        }
    }
}
