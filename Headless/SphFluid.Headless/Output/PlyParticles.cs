using System;
using System.Buffers.Binary;
using System.Globalization;
using System.IO;
using System.Numerics;
using System.Text;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// Writes particles as a PLY point cloud (Blender, MeshLab): binary_little_endian 1.0, one vertex element per
/// particle with the properties float x y z (world position, m), float vx vy vz (m/s), uint phase, float density
/// (kg/m^3), float pressure (Pa), 36 bytes a vertex, no faces.
/// </summary>
public static class PlyParticles
{
    public const int VertexBytes = 36;

    /// <param name="densities">Per particle, in the order of <paramref name="particles"/>: rho, p, delta, p/delta^2.</param>
    public static void Write(string path, double time, ReadOnlySpan<Particle> particles, ReadOnlySpan<Vector4> densities)
    {
        RequireOnePerParticle(particles, densities);
        using var file = File.Create(path);
        Write(file, time, particles, densities);
    }

    /// <inheritdoc cref="Write(string, double, ReadOnlySpan{Particle}, ReadOnlySpan{Vector4})"/>
    public static void Write(Stream stream, double time, ReadOnlySpan<Particle> particles, ReadOnlySpan<Vector4> densities)
    {
        RequireOnePerParticle(particles, densities);
        var header = new StringBuilder();
        header.Append("ply\n");
        header.Append("format binary_little_endian 1.0\n");
        header.Append(string.Format(CultureInfo.InvariantCulture, "comment sphfluid particles at t = {0:R} s\n", time));
        header.Append(string.Format(CultureInfo.InvariantCulture, "element vertex {0}\n", particles.Length));
        foreach (string name in new[] { "x", "y", "z", "vx", "vy", "vz" }) header.Append("property float ").Append(name).Append('\n');
        header.Append("property uint phase\n");
        header.Append("property float density\n");
        header.Append("property float pressure\n");
        header.Append("end_header\n");

        using var file = new BufferedStream(stream, 1 << 16);
        file.Write(Encoding.ASCII.GetBytes(header.ToString()));
        Span<byte> vertex = stackalloc byte[VertexBytes];
        for (int i = 0; i < particles.Length; i++)
        {
            var p = particles[i];
            BinaryPrimitives.WriteSingleLittleEndian(vertex[0..], p.Position.X);
            BinaryPrimitives.WriteSingleLittleEndian(vertex[4..], p.Position.Y);
            BinaryPrimitives.WriteSingleLittleEndian(vertex[8..], p.Position.Z);
            BinaryPrimitives.WriteSingleLittleEndian(vertex[12..], p.Velocity.X);
            BinaryPrimitives.WriteSingleLittleEndian(vertex[16..], p.Velocity.Y);
            BinaryPrimitives.WriteSingleLittleEndian(vertex[20..], p.Velocity.Z);
            BinaryPrimitives.WriteUInt32LittleEndian(vertex[24..], p.Phase);
            BinaryPrimitives.WriteSingleLittleEndian(vertex[28..], densities[i].X);
            BinaryPrimitives.WriteSingleLittleEndian(vertex[32..], densities[i].Y);
            file.Write(vertex);
        }
    }

    static void RequireOnePerParticle(ReadOnlySpan<Particle> particles, ReadOnlySpan<Vector4> densities)
    {
        if (densities.Length != particles.Length)
            throw new ArgumentException($"PlyParticles: {densities.Length} densities for {particles.Length} particles");
    }
}
