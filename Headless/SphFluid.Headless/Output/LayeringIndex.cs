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
    /// pair has different rest densities. Sorting by height makes it O(N log N); each particle then counts the
    /// lower particles of each density class, O(classes) per particle.
    /// </summary>
    public static double Of(ReadOnlySpan<float> heights, ReadOnlySpan<float> restDensities)
    {
        if (heights.Length != restDensities.Length)
            throw new ArgumentException($"LayeringIndex: {heights.Length} heights but {restDensities.Length} rest densities");
        int n = heights.Length;

        // Density classes, lightest first.
        var distinct = new SortedSet<float>();
        foreach (float d in restDensities) distinct.Add(d);
        var classes = new List<float>(distinct);
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

        var below = new long[classes.Count];
        long ordered = 0, inverted = 0;
        for (int start = 0; start < n;)
        {
            int end = start + 1;
            while (end < n && keys[end] == keys[start]) end++;
            // A run of equal heights: each member is compared with everything strictly lower, then joins it.
            for (int s = start; s < end; s++)
            {
                int c = classOf[order[s]];
                for (int other = 0; other < c; other++) inverted += below[other];
                for (int other = c + 1; other < classes.Count; other++) ordered += below[other];
            }
            for (int s = start; s < end; s++) below[classOf[order[s]]]++;
            start = end;
        }
        return (ordered - inverted) / pairs;
    }
}
