using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Headless.Output;

/// <summary>
/// What a validation engineer reads off one instant of a run, computed on the CPU from the read-back particle
/// and density buffers: per phase <see cref="PhaseMeasures"/>, the <see cref="Output.LayeringIndex"/>, the
/// <see cref="DamBreakFront"/> figures, the <see cref="Output.InterfaceTilt"/>, the free surface's rise
/// (<see cref="Output.InterfaceTilt.SurfaceRise"/>) and the potential energy sum m |g| h
/// (h above the container's lowest corner, so it is 0 for fluid lying on that corner). Measuring results is not
/// solver maths, so it lives here.
/// </summary>
public sealed record FluidMeasures(double Time, IReadOnlyList<PhaseMeasures> Phases, double LayeringIndex,
    double SurgeFront, double BackWallColumn, double PotentialEnergy, IReadOnlyList<(double AlongU, double AlongW)> InterfaceRises,
    (double AlongU, double AlongW) SurfaceRise)
{
    /// <summary>The largest rise of an interface across the floor, m (<see cref="Output.InterfaceTilt"/>); NaN with one liquid.</summary>
    public double InterfaceTilt => Output.InterfaceTilt.Of(InterfaceRises);

    /// <param name="densities">Per particle, in the order of <paramref name="particles"/>: rho, p, delta, p/delta^2 (the
    /// solver's density buffer); empty to leave compression and expansion out (NaN).</param>
    public static FluidMeasures Measure(double time, ReadOnlySpan<Particle> particles, ReadOnlySpan<Vector4> densities,
        IReadOnlyList<PhaseProperties> phases, ContainerDescription container, Vector3 gravity, float particleSpacing, float supportRadius)
    {
        if (densities.Length != 0 && densities.Length != particles.Length)
            throw new ArgumentException($"FluidMeasures: {densities.Length} densities for {particles.Length} particles");
        var frame = new GravityFrame(container, gravity);
        int phaseCount = phases.Count, n = particles.Length;
        var count = new long[phaseCount];
        var heightSum = new double[phaseCount];
        var bottom = Filled(phaseCount, double.PositiveInfinity);
        var top = Filled(phaseCount, double.NegativeInfinity);
        var onFloor = new long[phaseCount];
        var onWalls = new long[phaseCount];
        var compressionSum = new double[phaseCount];
        var expansionSum = new double[phaseCount];
        var compressionMax = new double[phaseCount];
        var expansionMax = new double[phaseCount];
        long floorLayer = 0, wallLayer = 0;
        double potential = 0, g = gravity.Length();

        var local = new Vector3[n];
        var heights = new List<float>(n);
        var restDensities = new List<float>(n);
        var volumes = new float[n];
        var particleRestDensities = new float[n];
        for (int i = 0; i < n; i++)
        {
            var p = particles[i];
            local[i] = frame.ToLocal(p.Position);
            float h = frame.HeightOf(p.Position);
            if (p.Phase >= phaseCount || !float.IsFinite(h))
            {
                local[i] = new Vector3(float.NaN);
                continue;
            }
            int k = (int)p.Phase;
            count[k]++;
            heightSum[k] += h;
            bottom[k] = Math.Min(bottom[k], h);
            top[k] = Math.Max(top[k], h);
            potential += phases[k].ParticleMass * g * h;
            heights.Add(h);
            restDensities.Add(phases[k].RestDensity);
            particleRestDensities[i] = phases[k].RestDensity;
            volumes[i] = phases[k].ParticleMass / (densities.Length > 0 ? densities[i].X : phases[k].RestDensity);

            if (frame.AboveFloor(local[i]) <= particleSpacing) { floorLayer++; onFloor[k]++; }
            if (frame.FromWalls(local[i]) <= particleSpacing) { wallLayer++; onWalls[k]++; }

            if (densities.Length > 0)
            {
                double ratio = densities[i].X / phases[k].RestDensity;
                double compression = Math.Max(0, ratio - 1), expansion = Math.Max(0, 1 - ratio);
                compressionSum[k] += compression;
                expansionSum[k] += expansion;
                compressionMax[k] = Math.Max(compressionMax[k], compression);
                expansionMax[k] = Math.Max(expansionMax[k], expansion);
            }
        }

        var measures = new PhaseMeasures[phaseCount];
        for (int k = 0; k < phaseCount; k++)
        {
            bool any = count[k] > 0, dense = any && densities.Length > 0;
            measures[k] = new PhaseMeasures((int)count[k],
                any ? heightSum[k] / count[k] : double.NaN, any ? bottom[k] : double.NaN, any ? top[k] : double.NaN,
                floorLayer > 0 ? (double)onFloor[k] / floorLayer : double.NaN, wallLayer > 0 ? (double)onWalls[k] / wallLayer : double.NaN,
                dense ? compressionSum[k] / count[k] : double.NaN, dense ? compressionMax[k] : double.NaN,
                dense ? expansionSum[k] / count[k] : double.NaN, dense ? expansionMax[k] : double.NaN);
        }
        double index = Output.LayeringIndex.Of(heights.ToArray(), restDensities.ToArray());
        var (front, column) = DamBreakFront.Measure(local, frame, particleSpacing, supportRadius);
        var rises = Output.InterfaceTilt.Rises(local, volumes, particleRestDensities, frame.FloorAxis, container.Size);
        var surface = Output.InterfaceTilt.SurfaceRise(local, volumes, frame.FloorAxis, container.Size);
        return new FluidMeasures(time, measures, index, front, column, potential, rises, surface);
    }

    static double[] Filled(int length, double value)
    {
        var a = new double[length];
        Array.Fill(a, value);
        return a;
    }
}
