using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Text;
using SphFluid.Headless.Output;

namespace SphFluid.Tests.Runner
{
    /// <summary>Just enough of a PNG reader to check the encoder: chunks with their CRCs, IHDR, the inflated
    /// and unfiltered (None/Sub/Up/Average/Paeth) 8-bit RGB scanlines.</summary>
    static class PngDecoder
    {
        public sealed class Chunk
        {
            public string Type;
            public byte[] Data;
            public uint StoredCrc;
            public uint ComputedCrc;
        }

        public static List<Chunk> Chunks(byte[] png)
        {
            var chunks = new List<Chunk>();
            int at = 8;
            while (at < png.Length)
            {
                int length = (png[at] << 24) | (png[at + 1] << 16) | (png[at + 2] << 8) | png[at + 3];
                string type = Encoding.ASCII.GetString(png, at + 4, 4);
                var data = new byte[length];
                Array.Copy(png, at + 8, data, 0, length);
                int c = at + 8 + length;
                uint stored = (uint)((png[c] << 24) | (png[c + 1] << 16) | (png[c + 2] << 8) | png[c + 3]);
                var typed = new byte[4 + length];
                Array.Copy(png, at + 4, typed, 0, 4 + length);
                chunks.Add(new Chunk { Type = type, Data = data, StoredCrc = stored, ComputedCrc = Crc32.Compute(typed) });
                at = c + 4;
            }
            return chunks;
        }

        public static byte[] Pixels(List<Chunk> chunks, out int width, out int height)
        {
            var header = chunks[0].Data;
            width = (header[0] << 24) | (header[1] << 16) | (header[2] << 8) | header[3];
            height = (header[4] << 24) | (header[5] << 16) | (header[6] << 8) | header[7];
            var idat = new MemoryStream();
            foreach (var c in chunks) if (c.Type == "IDAT") idat.Write(c.Data, 0, c.Data.Length);
            idat.Position = 0;
            var raw = new MemoryStream();
            using (var z = new ZLibStream(idat, CompressionMode.Decompress)) z.CopyTo(raw);
            byte[] filtered = raw.ToArray();
            int row = width * 3;
            var pixels = new byte[row * height];
            for (int y = 0; y < height; y++)
            {
                byte filter = filtered[y * (row + 1)];
                for (int i = 0; i < row; i++)
                {
                    int x = filtered[y * (row + 1) + 1 + i];
                    int a = i >= 3 ? pixels[y * row + i - 3] : 0;
                    int b = y > 0 ? pixels[(y - 1) * row + i] : 0;
                    int c = i >= 3 && y > 0 ? pixels[(y - 1) * row + i - 3] : 0;
                    int predicted = filter switch
                    {
                        0 => 0,
                        1 => a,
                        2 => b,
                        3 => (a + b) / 2,
                        4 => Paeth(a, b, c),
                        _ => throw new InvalidDataException("unknown PNG filter " + filter),
                    };
                    pixels[y * row + i] = (byte)(x + predicted);
                }
            }
            return pixels;
        }

        static int Paeth(int a, int b, int c)
        {
            int p = a + b - c, pa = Math.Abs(p - a), pb = Math.Abs(p - b), pc = Math.Abs(p - c);
            return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        }
    }
}
