using System;
using System.Buffers.Binary;
using System.Globalization;
using System.IO;
using System.Numerics;
using System.Text;
using System.Xml;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// Writes particles as a VTK XML UnstructuredGrid (.vtu) that ParaView opens: world positions (m) as the points,
/// one vertex cell per particle (so every representation draws them), and point data velocity (m/s, 3
/// components), phase (index into the scene's phase table), density (kg/m^3), pressure (Pa) and id (stable from
/// spawn; the solver reorders particles every step). The time is in the field data as TimeValue (s).
/// Every array is inline base64 binary (format="binary"), uncompressed: a little-endian UInt64 byte count followed
/// by the little-endian values, encoded as one base64 run, so the file is plain XML any XML reader parses.
/// </summary>
public static class VtuParticles
{
    const byte VertexCell = 1; // VTK_VERTEX

    // Bytes per particle of each array Write writes: velocity, phase, density, pressure, id, points, connectivity,
    // offsets, types.
    static readonly int[] ArrayBytesPerParticle = { 12, 4, 4, 4, 4, 12, 8, 8, 1 };

    /// <summary>The bytes of the arrays' base64 runs in a file of <paramref name="particles"/> particles: all of the file
    /// but its XML, which adds about a kilobyte.</summary>
    public static long DataBytes(long particles)
    {
        long bytes = 0;
        foreach (int perParticle in ArrayBytesPerParticle)
            bytes += 4 * ((8 + perParticle * particles + 2) / 3);
        return bytes;
    }

    /// <param name="densities">Per particle, in the order of <paramref name="particles"/>: rho, p, delta, p/delta^2.</param>
    public static void Write(string path, double time, ReadOnlySpan<Particle> particles, ReadOnlySpan<Vector4> densities)
    {
        RequireOnePerParticle(particles, densities);
        using var file = File.Create(path);
        Write(file, time, particles, densities);
    }

    /// <inheritdoc cref="Write(string, double, ReadOnlySpan{Particle}, ReadOnlySpan{Vector4})"/>
    public static void Write(Stream file, double time, ReadOnlySpan<Particle> particles, ReadOnlySpan<Vector4> densities)
    {
        RequireOnePerParticle(particles, densities);
        int n = particles.Length;
        var c = CultureInfo.InvariantCulture;
        using var xml = XmlWriter.Create(file, new XmlWriterSettings { Indent = true, Encoding = new UTF8Encoding(false), NewLineChars = "\n" });
        xml.WriteStartDocument();
        xml.WriteStartElement("VTKFile");
        xml.WriteAttributeString("type", "UnstructuredGrid");
        xml.WriteAttributeString("version", "1.0");
        xml.WriteAttributeString("byte_order", "LittleEndian");
        xml.WriteAttributeString("header_type", "UInt64");
        xml.WriteStartElement("UnstructuredGrid");

        xml.WriteStartElement("FieldData");
        xml.WriteStartElement("DataArray");
        xml.WriteAttributeString("type", "Float64");
        xml.WriteAttributeString("Name", "TimeValue");
        xml.WriteAttributeString("NumberOfTuples", "1");
        xml.WriteAttributeString("format", "ascii");
        xml.WriteString(time.ToString("R", c));
        xml.WriteEndElement();
        xml.WriteEndElement();

        xml.WriteStartElement("Piece");
        xml.WriteAttributeString("NumberOfPoints", n.ToString(c));
        xml.WriteAttributeString("NumberOfCells", n.ToString(c));

        xml.WriteStartElement("PointData");
        xml.WriteAttributeString("Scalars", "density");
        xml.WriteAttributeString("Vectors", "velocity");
        var floats = new float[3 * n];
        for (int i = 0; i < n; i++) Put(floats, i, particles[i].Velocity);
        Array(xml, "Float32", "velocity", 3, Bytes(floats));
        var uints = new uint[n];
        for (int i = 0; i < n; i++) uints[i] = particles[i].Phase;
        Array(xml, "UInt32", "phase", 1, Bytes(uints));
        var scalars = new float[n];
        for (int i = 0; i < n; i++) scalars[i] = densities[i].X;
        Array(xml, "Float32", "density", 1, Bytes(scalars));
        for (int i = 0; i < n; i++) scalars[i] = densities[i].Y;
        Array(xml, "Float32", "pressure", 1, Bytes(scalars));
        for (int i = 0; i < n; i++) uints[i] = particles[i].Id;
        Array(xml, "UInt32", "id", 1, Bytes(uints));
        xml.WriteEndElement();

        xml.WriteStartElement("Points");
        for (int i = 0; i < n; i++) Put(floats, i, particles[i].Position);
        Array(xml, "Float32", null, 3, Bytes(floats));
        xml.WriteEndElement();

        xml.WriteStartElement("Cells");
        var longs = new long[n];
        for (int i = 0; i < n; i++) longs[i] = i;
        Array(xml, "Int64", "connectivity", 1, Bytes(longs));
        for (int i = 0; i < n; i++) longs[i] = i + 1;
        Array(xml, "Int64", "offsets", 1, Bytes(longs));
        var types = new byte[n];
        System.Array.Fill(types, VertexCell);
        Array(xml, "UInt8", "types", 1, types);
        xml.WriteEndElement();

        xml.WriteEndElement(); // Piece
        xml.WriteEndElement(); // UnstructuredGrid
        xml.WriteEndElement(); // VTKFile
        xml.WriteEndDocument();
    }

    static void Array(XmlWriter xml, string type, string? name, int components, byte[] data)
    {
        xml.WriteStartElement("DataArray");
        xml.WriteAttributeString("type", type);
        if (name != null) xml.WriteAttributeString("Name", name);
        if (components > 1) xml.WriteAttributeString("NumberOfComponents", components.ToString(CultureInfo.InvariantCulture));
        xml.WriteAttributeString("format", "binary");
        // Header and values in one base64 run, as VTK's reader decodes them (no padding between the two).
        var run = new byte[8 + data.Length];
        BinaryPrimitives.WriteUInt64LittleEndian(run, (ulong)data.Length);
        data.CopyTo(run, 8);
        xml.WriteBase64(run, 0, run.Length);
        xml.WriteEndElement();
    }

    static void Put(float[] into, int i, Vector3 v)
    {
        into[3 * i] = v.X;
        into[3 * i + 1] = v.Y;
        into[3 * i + 2] = v.Z;
    }

    static byte[] Bytes(float[] values)
    {
        var bytes = new byte[values.Length * 4];
        for (int i = 0; i < values.Length; i++) BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(4 * i), values[i]);
        return bytes;
    }

    static byte[] Bytes(uint[] values)
    {
        var bytes = new byte[values.Length * 4];
        for (int i = 0; i < values.Length; i++) BinaryPrimitives.WriteUInt32LittleEndian(bytes.AsSpan(4 * i), values[i]);
        return bytes;
    }

    static byte[] Bytes(long[] values)
    {
        var bytes = new byte[values.Length * 8];
        for (int i = 0; i < values.Length; i++) BinaryPrimitives.WriteInt64LittleEndian(bytes.AsSpan(8 * i), values[i]);
        return bytes;
    }

    static void RequireOnePerParticle(ReadOnlySpan<Particle> particles, ReadOnlySpan<Vector4> densities)
    {
        if (densities.Length != particles.Length)
            throw new ArgumentException($"VtuParticles: {densities.Length} densities for {particles.Length} particles");
    }
}
