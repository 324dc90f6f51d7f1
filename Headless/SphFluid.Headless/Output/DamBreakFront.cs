using System;
using System.Numerics;

namespace SphFluid.Headless.Output;

/// <summary>
/// The two figures of a collapsing column ("An experimental study of the collapse of liquid columns on a rigid
/// horizontal plane", Martin and Moyce): how far the surge has run along the floor and how tall the column
/// still stands at the wall it started from. Both are container-local: the surge front is the largest x, measured
/// from the back wall (x = -size/2), reached by fluid within <see cref="BandSpacings"/> spacings of the floor;
/// the column is the greatest height above the floor of fluid within as many spacings of the back wall.
/// Isolated particles (fewer than <see cref="Company"/> others within the support radius) are spray and count
/// for neither. NaN where no fluid qualifies, and while the container is turned so far that its x faces are the
/// floor and ceiling: x is then the height, and a run along the floor has no x to reach.
/// </summary>
public static class DamBreakFront
{
    /// <summary>Thickness of the floor band and of the back-wall band, in particle spacings.</summary>
    public const float BandSpacings = 2f;

    /// <summary>Other particles a particle needs within the support radius to count as fluid, not spray.</summary>
    public const int Company = 3;

    /// <param name="local">Container-local positions.</param>
    public static (double SurgeFront, double Column) Measure(Vector3[] local, GravityFrame frame, float particleSpacing, float supportRadius)
    {
        if (frame.FloorAxis == 0) return (double.NaN, double.NaN);
        float band = BandSpacings * particleSpacing;
        var neighbourhood = new ParticleNeighbourhood(local, supportRadius);

        // Candidates sorted farthest first: the first one with company decides, so only a few are checked.
        double front = First(local, neighbourhood, p => frame.AboveFloor(p) <= band, p => frame.FromBackWall(p));
        double column = First(local, neighbourhood, p => frame.FromBackWall(p) <= band, p => frame.AboveFloor(p));
        return (front, column);
    }

    static double First(Vector3[] local, ParticleNeighbourhood neighbourhood, Func<Vector3, bool> inBand, Func<Vector3, float> reach)
    {
        int count = 0;
        var candidates = new int[local.Length];
        var keys = new float[local.Length];
        for (int i = 0; i < local.Length; i++)
        {
            float r = reach(local[i]);
            if (!float.IsFinite(r) || !inBand(local[i])) continue;
            candidates[count] = i;
            keys[count++] = -r;
        }
        Array.Sort(keys, candidates, 0, count);
        for (int c = 0; c < count; c++)
            if (!neighbourhood.IsIsolated(candidates[c], Company)) return -keys[c];
        return double.NaN;
    }
}
