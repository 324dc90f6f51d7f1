using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;

namespace SphFluid.Headless.Output;

/// <summary>
/// How far the interfaces between liquids are from flat: for each interface, the least-squares plane through its
/// height over the container's floor, and how much that plane rises from one side of the floor to the other
/// (m, container-local). The layering index counts ordered pairs and so reads 0.97 for a layer whose interface
/// still rises by several spacings along the tank; a flat layer reads 0 here, whatever the layers' depths.
/// <para>
/// The interface above the liquids of rest density rho0 or more lies at their local thickness T(u, w) = their
/// volume per unit floor area over the floor point (u, w) (u, w container-local, measured from the floor's
/// centre). A plane a + b u + c w fitted to T over the floor (L_u by L_w) by least squares has
///   b = 12 sum_i V_i u_i / (L_u^3 L_w),   c = 12 sum_i V_i w_i / (L_w^3 L_u)
/// summed over those liquids' particles (V_i = m_i / rho_i): the first moment of their volume, so no binning
/// enters it. The plane rises by |b| L_u + |c| L_w across the floor. One figure is reported: the largest rise over
/// the interfaces (the liquids grouped by rest density; a single rest density has none: NaN).
/// </para>
/// <para>
/// The free surface lies at the thickness of all the liquids together, so the same plane fitted to every particle's
/// volume is the free surface's (<see cref="SurfaceRise"/>): a sloshing tank's fundamental mode rocks it.
/// </para>
/// </summary>
public static class InterfaceTilt
{
    /// <param name="local">Container-local positions (non-finite ones are skipped).</param>
    /// <param name="volumes">Each particle's volume m / rho, m^3.</param>
    /// <param name="restDensities">Each particle's phase rest density, kg/m^3.</param>
    /// <param name="floorAxis">Container-local axis normal to the floor (<see cref="GravityFrame.FloorAxis"/>).</param>
    /// <param name="size">The container's edge lengths, m.</param>
    public static double Measure(ReadOnlySpan<Vector3> local, ReadOnlySpan<float> volumes, ReadOnlySpan<float> restDensities, int floorAxis, Vector3 size) =>
        Of(Rises(local, volumes, restDensities, floorAxis, size));

    /// <summary>The largest rise across the floor of the interfaces whose signed rises are <paramref name="rises"/>
    /// (<see cref="Rises"/>); NaN for none.</summary>
    public static double Of(IReadOnlyList<(double AlongU, double AlongW)> rises) =>
        rises.Count == 0 ? double.NaN : rises.Max(r => Math.Abs(r.AlongU) + Math.Abs(r.AlongW));

    /// <summary>Each interface's plane, heaviest first: its signed rise b L_u from the u = -L_u/2 side of the floor to the
    /// u = +L_u/2 side, and c L_w likewise (m). An oscillating interface (an internal seiche) changes sign.</summary>
    public static IReadOnlyList<(double AlongU, double AlongW)> Rises(ReadOnlySpan<Vector3> local, ReadOnlySpan<float> volumes,
        ReadOnlySpan<float> restDensities, int floorAxis, Vector3 size)
    {
        if (volumes.Length != local.Length || restDensities.Length != local.Length)
            throw new ArgumentException($"InterfaceTilt: {local.Length} positions, {volumes.Length} volumes, {restDensities.Length} rest densities");
        int uAxis = floorAxis == 0 ? 1 : 0, wAxis = floorAxis == 2 ? 1 : 2;
        double lu = Component(size, uAxis), lw = Component(size, wAxis);

        // Volume moments per rest density, heaviest first: an interface lies above each prefix but the whole.
        var moments = new SortedDictionary<float, (double U, double W)>(Comparer<float>.Create((a, b) => b.CompareTo(a)));
        for (int i = 0; i < local.Length; i++)
        {
            var p = local[i];
            if (!float.IsFinite(p.X) || !float.IsFinite(p.Y) || !float.IsFinite(p.Z) || !float.IsFinite(volumes[i])) continue;
            moments.TryGetValue(restDensities[i], out var m);
            moments[restDensities[i]] = (m.U + volumes[i] * Component(p, uAxis), m.W + volumes[i] * Component(p, wAxis));
        }

        var rises = new List<(double, double)>();
        double sumU = 0, sumW = 0;
        foreach (var (u, w) in moments.Values.Take(Math.Max(0, moments.Count - 1)))
        {
            sumU += u;
            sumW += w;
            rises.Add(Rise(sumU, sumW, lu, lw));
        }
        return rises;
    }

    /// <summary>The free surface's plane: its signed rise along u and along w across the floor (m), fitted to every
    /// particle's volume whatever its liquid.</summary>
    public static (double AlongU, double AlongW) SurfaceRise(ReadOnlySpan<Vector3> local, ReadOnlySpan<float> volumes, int floorAxis, Vector3 size)
    {
        if (volumes.Length != local.Length)
            throw new ArgumentException($"InterfaceTilt: {local.Length} positions, {volumes.Length} volumes");
        int uAxis = floorAxis == 0 ? 1 : 0, wAxis = floorAxis == 2 ? 1 : 2;
        double sumU = 0, sumW = 0;
        for (int i = 0; i < local.Length; i++)
        {
            var p = local[i];
            if (!float.IsFinite(p.X) || !float.IsFinite(p.Y) || !float.IsFinite(p.Z) || !float.IsFinite(volumes[i])) continue;
            sumU += volumes[i] * Component(p, uAxis);
            sumW += volumes[i] * Component(p, wAxis);
        }
        return Rise(sumU, sumW, Component(size, uAxis), Component(size, wAxis));
    }

    /// <summary>b L_u and c L_w from the first moments of the volume below the plane.</summary>
    static (double AlongU, double AlongW) Rise(double momentU, double momentW, double lu, double lw) =>
        (12 * momentU / (lu * lu * lw), 12 * momentW / (lw * lw * lu));

    static float Component(Vector3 v, int axis) => axis == 0 ? v.X : axis == 1 ? v.Y : v.Z;
}
