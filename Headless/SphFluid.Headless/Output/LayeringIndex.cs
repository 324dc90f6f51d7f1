using System;
using System.Collections.Generic;

namespace SphFluid.Headless.Output;

/// <summary>
/// How well the phases are ordered by density along gravity, for any number of phases: over every pair of
/// particles whose phases have different rest densities, (ordered pairs - inverted pairs) / pairs, where a pair
/// is ordered when the heavier particle lies lower. A uniform mix scores 0, perfect layers 1 (at any depth,
/// volume split or container size, because no length enters it), heavy over light -1. Pairs at exactly the
/// same height count as neither but stay in the denominator. It is Kendall's rank concordance ("A new measure
/// of rank correlation") between depth and rest density, taken over the pairs of different density only, so
/// that pairs within one phase, which no layering can order, do not dilute it.
/// </summary>
public static class LayeringIndex
{
    /// <summary>
    /// The index of particles with the given heights and phase rest densities (same length), or NaN when no
    /// pair has different rest densities. O(N log N): one sort by height, then each particle counts the lighter
    /// and heavier particles below it in a Fenwick tree over the density classes.
    /// </summary>
    public static double Of(ReadOnlySpan<float> heights, ReadOnlySpan<float> restDensities)
    {
        if (heights.Length != restDensities.Length)
            throw new ArgumentException($"LayeringIndex: {heights.Length} heights but {restDensities.Length} rest densities");
        int n = heights.Length;

        // Density classes, lightest first.
        var distinct = new HashSet<float>();
        foreach (float d in restDensities) distinct.Add(d);
        var classes = new List<float>(distinct);
        classes.Sort();
        var classOf = new int[n];
        var order = new int[n];
        var keys = new float[n];
        for (int i = 0; i < n; i++)
        {
            classOf[i] = classes.BinarySearch(restDensities[i]);
            order[i] = i;
            keys[i] = heights[i];
        }
        Array.Sort(keys, order);

        var classSize = new long[classes.Count];
        foreach (int c in classOf) classSize[c]++;
        double pairs = 0;
        for (int a = 0; a < classes.Count; a++)
            for (int b = a + 1; b < classes.Count; b++) pairs += (double)classSize[a] * classSize[b];
        if (pairs == 0) return double.NaN;

        // Fenwick tree over the classes: how many particles already passed (strictly lower) are lighter or heavier.
        var below = new long[classes.Count + 1];
        long passed = 0, ordered = 0, inverted = 0;
        for (int start = 0; start < n;)
        {
            int end = start + 1;
            while (end < n && keys[end] == keys[start]) end++;
            // A run of equal heights: each member is compared with everything strictly lower, then joins it.
            for (int s = start; s < end; s++)
            {
                int c = classOf[order[s]];
                long lighter = CountUpTo(below, c - 1), notHeavier = CountUpTo(below, c);
                inverted += lighter;
                ordered += passed - notHeavier;
            }
            for (int s = start; s < end; s++) Add(below, classOf[order[s]]);
            passed += end - start;
            start = end;
        }
        return (ordered - inverted) / pairs;
    }

    /// <summary>Particles counted in classes 0..<paramref name="c"/>.</summary>
    static long CountUpTo(long[] tree, int c)
    {
        long sum = 0;
        for (int i = c + 1; i > 0; i -= i & -i) sum += tree[i];
        return sum;
    }

    static void Add(long[] tree, int c)
    {
        for (int i = c + 1; i < tree.Length; i += i & -i) tree[i]++;
    }
}
