using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.IO.Hashing;
using System.Text;

namespace SphFluid.Tests.Runner
{
    /// <summary>The chunks of a PNG file with the CRC each one stores and the CRC of its bytes. The pixel
    /// decoder the tests use (StbImageSharp) does not verify chunk CRCs, so this is what checks them.</summary>
    static class PngChunks
    {
        public sealed class Chunk
        {
            public string Type;
            public byte[] Data;
            public uint StoredCrc;
            public uint ComputedCrc;
        }

        public static List<Chunk> Read(byte[] png)
        {
            var chunks = new List<Chunk>();
            int at = 8; // after the signature
            while (at + 12 <= png.Length)
            {
                int length = BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(at));
                var typeAndData = png.AsSpan(at + 4, 4 + length);
                chunks.Add(new Chunk
                {
                    Type = Encoding.ASCII.GetString(typeAndData.Slice(0, 4)),
                    Data = typeAndData.Slice(4).ToArray(),
                    StoredCrc = BinaryPrimitives.ReadUInt32BigEndian(png.AsSpan(at + 8 + length)),
                    ComputedCrc = Crc32.HashToUInt32(typeAndData),
                });
                at += 12 + length;
            }
            return chunks;
        }
    }
}
