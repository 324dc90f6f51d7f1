using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using NUnit.Framework;

namespace SphFluid.Tests.Output
{
    /// <summary>Reads back a binary little-endian PLY point cloud: the header's vertex properties, then the body as rows of values.</summary>
    sealed class PlyReader
    {
        public List<(string Type, string Name)> Properties { get; } = new List<(string, string)>();
        public List<string> HeaderLines { get; } = new List<string>();
        public int Vertices { get; private set; }
        public double[][] Rows { get; private set; }

        public PlyReader(string path)
        {
            byte[] bytes = File.ReadAllBytes(path);
            int at = 0;
            while (true)
            {
                int end = Array.IndexOf(bytes, (byte)'\n', at);
                Assert.That(end, Is.GreaterThan(at - 1), "header line ends");
                string line = Encoding.ASCII.GetString(bytes, at, end - at);
                at = end + 1;
                HeaderLines.Add(line);
                string[] words = line.Split(' ');
                if (words[0] == "element" && words[1] == "vertex") Vertices = int.Parse(words[2], CultureInfo.InvariantCulture);
                if (words[0] == "property") Properties.Add((words[1], words[2]));
                if (line == "end_header") break;
            }
            Assert.That(HeaderLines[0], Is.EqualTo("ply"));
            Assert.That(HeaderLines[1], Is.EqualTo("format binary_little_endian 1.0"));

            int stride = 0;
            foreach (var (type, _) in Properties) stride += Size(type);
            Assert.That(bytes.Length - at, Is.EqualTo(Vertices * stride), "body is exactly the declared vertices");
            Rows = new double[Vertices][];
            for (int v = 0; v < Vertices; v++)
            {
                Rows[v] = new double[Properties.Count];
                for (int p = 0; p < Properties.Count; p++)
                {
                    var span = bytes.AsSpan(at);
                    Rows[v][p] = Properties[p].Type switch
                    {
                        "float" => BinaryPrimitives.ReadSingleLittleEndian(span),
                        "uint" => BinaryPrimitives.ReadUInt32LittleEndian(span),
                        "int" => BinaryPrimitives.ReadInt32LittleEndian(span),
                        _ => double.NaN,
                    };
                    at += Size(Properties[p].Type);
                }
            }
        }

        static int Size(string type) => type switch
        {
            "float" or "uint" or "int" => 4,
            "double" => 8,
            _ => throw new InvalidDataException("PLY property type " + type + " is not read by this test"),
        };
    }
}
