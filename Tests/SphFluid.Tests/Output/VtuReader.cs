using System;
using System.Buffers.Binary;
using System.Globalization;
using System.Linq;
using System.Xml;
using NUnit.Framework;

namespace SphFluid.Tests.Output
{
    /// <summary>
    /// Reads back a particle .vtu with System.Xml alone, independently of the writer: each inline binary DataArray
    /// is one base64 run of a little-endian UInt64 byte count and the values.
    /// </summary>
    sealed class VtuReader
    {
        readonly XmlDocument _document = new XmlDocument();

        public VtuReader(string path)
        {
            _document.Load(path);
            var root = _document.DocumentElement.OrFail(path + "'s root element");
            Assert.That(root.Name, Is.EqualTo("VTKFile"));
            Assert.That(root.GetAttribute("type"), Is.EqualTo("UnstructuredGrid"));
            Assert.That(root.GetAttribute("byte_order"), Is.EqualTo("LittleEndian"));
            Assert.That(root.GetAttribute("header_type"), Is.EqualTo("UInt64"));
        }

        XmlElement Piece => (_document.SelectSingleNode("/VTKFile/UnstructuredGrid/Piece") as XmlElement).OrFail("Piece");

        public int Points => int.Parse(Piece.GetAttribute("NumberOfPoints"), CultureInfo.InvariantCulture);

        public int Cells => int.Parse(Piece.GetAttribute("NumberOfCells"), CultureInfo.InvariantCulture);

        public double Time => double.Parse(_document.SelectSingleNode("/VTKFile/UnstructuredGrid/FieldData/DataArray[@Name='TimeValue']").OrFail("TimeValue").InnerText, CultureInfo.InvariantCulture);

        /// <summary>The values of the array at <paramref name="xpath"/> (relative to the Piece), checked for type and component count.</summary>
        public byte[] Raw(string xpath, string type, int components)
        {
            var array = (Piece.SelectSingleNode(xpath) as XmlElement).OrFail(xpath);
            Assert.That(array.GetAttribute("type"), Is.EqualTo(type), xpath);
            Assert.That(array.GetAttribute("format"), Is.EqualTo("binary"), xpath);
            string declared = array.GetAttribute("NumberOfComponents");
            Assert.That(declared.Length == 0 ? 1 : int.Parse(declared, CultureInfo.InvariantCulture), Is.EqualTo(components), xpath);
            byte[] run = Convert.FromBase64String(new string(array.InnerText.Where(c => !char.IsWhiteSpace(c)).ToArray()));
            ulong length = BinaryPrimitives.ReadUInt64LittleEndian(run);
            Assert.That(length, Is.EqualTo((ulong)(run.Length - 8)), xpath + ": header byte count");
            return run.AsSpan(8).ToArray();
        }

        public float[] Floats(string xpath, int components)
        {
            byte[] raw = Raw(xpath, "Float32", components);
            var values = new float[raw.Length / 4];
            for (int i = 0; i < values.Length; i++) values[i] = BinaryPrimitives.ReadSingleLittleEndian(raw.AsSpan(4 * i));
            return values;
        }

        public uint[] UInts(string xpath)
        {
            byte[] raw = Raw(xpath, "UInt32", 1);
            var values = new uint[raw.Length / 4];
            for (int i = 0; i < values.Length; i++) values[i] = BinaryPrimitives.ReadUInt32LittleEndian(raw.AsSpan(4 * i));
            return values;
        }

        public long[] Longs(string xpath)
        {
            byte[] raw = Raw(xpath, "Int64", 1);
            var values = new long[raw.Length / 8];
            for (int i = 0; i < values.Length; i++) values[i] = BinaryPrimitives.ReadInt64LittleEndian(raw.AsSpan(8 * i));
            return values;
        }

        public float[] PointData(string name, int components = 1) => Floats($"PointData/DataArray[@Name='{name}']", components);

        public float[] Positions => Floats("Points/DataArray", 3);
    }
}
