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
            public readonly string Type;
            public readonly byte[] Data;
            public readonly uint StoredCrc;
            public readonly uint ComputedCrc;

            public Chunk(string type, byte[] data, uint storedCrc, uint computedCrc)
            {
                Type = type;
                Data = data;
                StoredCrc = storedCrc;
                ComputedCrc = computedCrc;
            }
        }

        public static List<Chunk> Read(byte[] png)
        {
            var chunks = new List<Chunk>();
            int at = 8; // after the signature
            while (at + 12 <= png.Length)
            {
                int length = BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(at));
                var typeAndData = png.AsSpan(at + 4, 4 + length);
                chunks.Add(new Chunk(
                    Encoding.ASCII.GetString(typeAndData.Slice(0, 4)),
                    typeAndData.Slice(4).ToArray(),
                    BinaryPrimitives.ReadUInt32BigEndian(png.AsSpan(at + 8 + length)),
                    Crc32.HashToUInt32(typeAndData)));
                at += 12 + length;
            }
            return chunks;
        }
    }
}
