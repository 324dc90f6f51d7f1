using System;
using System.Globalization;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// <c>--export-every</c>: each export writes particles_NNNN.vtu (ParaView) and particles_NNNN.ply (Blender, MeshLab)
/// of the same state, and rewrites particles.pvd, the time index over every .vtu so far.
/// </summary>
public sealed class ParticleExport
{
    public const string IndexName = "particles.pvd";

    readonly OutputFolder _output;
    readonly PvdTimeIndex _index = new();

    public ParticleExport(OutputFolder output) => _output = output ?? throw new ArgumentNullException(nameof(output));

    /// <summary>Exports written so far.</summary>
    public int Count => _index.Entries.Count;

    public void Write(double time, ReadOnlySpan<Particle> particles, ReadOnlySpan<Vector4> densities)
    {
        string stem = string.Format(CultureInfo.InvariantCulture, "particles_{0:D4}", Count);
        VtuParticles.Write(_output.PathOf(stem + ".vtu"), time, particles, densities);
        PlyParticles.Write(_output.PathOf(stem + ".ply"), time, particles, densities);
        _index.Add(time, stem + ".vtu");
        _index.Write(_output.PathOf(IndexName));
    }
}
