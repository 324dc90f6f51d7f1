using System;
using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Spawn boxes must not overlap: each box fills its own lattice, so two boxes over the same space put
    /// particles on top of each other at several times the rest density (30 boxes at one spot reached
    /// 3.9e12 m/s in one frame). Boxes may touch: their lattices then continue each other. Two boxes overlap
    /// when they interpenetrate by more than a hundredth of a spacing along every separating axis of the
    /// separating-axis theorem (Gottschalk, Lin &amp; Manocha 1996, "OBBTree: a hierarchical structure for
    /// rapid interference detection": the 3 + 3 face normals and their 9 cross products).
    /// </summary>
    internal static class SpawnOverlapRule
    {
        /// <summary>The most overlapping pairs named. Every pair was named, and 2 000 boxes at one spot made two million
        /// messages; past this many a last error says that more overlap.</summary>
        internal const int MaxNamedPairs = 10;

        /// <summary>Adds one error per overlapping pair, naming both boxes, for up to <see cref="MaxNamedPairs"/> pairs in
        /// the order of the later box, then one saying that more overlap. Needs valid boxes.</summary>
        /// <remarks>Only boxes whose world bounding boxes overlap along x, y and z are tested (a sweep along one world
        /// axis): every pair was, and 20 000 boxes a spacing wide, side by side, took 25 s to validate, in the editor too.
        /// The sweep runs along the axis where it meets fewest pairs, counted before it starts: along x always, 100 000
        /// boxes laid in one plane across x (a wall of tiles) met every pair and took 14.5 s. A pair whose bounding boxes
        /// overlap by no more than the tolerance along a world axis overlaps no more along it, and the separating-axis
        /// test's least overlap is the least over every direction, so it finds such a pair apart too.</remarks>
        internal static void Validate(FluidSceneDescription scene, List<ValidationError> errors)
        {
            float tolerance = 0.01f * scene.Settings.ParticleSpacing;
            var boxes = scene.SpawnBoxes;
            var low = new Vector3[boxes.Count];
            var high = new Vector3[boxes.Count];
            for (int i = 0; i < boxes.Count; i++)
            {
                var axes = Axes(boxes[i].Rotation);
                var reach = new Vector3(Reach(boxes[i].Size, axes, Vector3.UnitX), Reach(boxes[i].Size, axes, Vector3.UnitY), Reach(boxes[i].Size, axes, Vector3.UnitZ));
                low[i] = boxes[i].Center - reach;
                high[i] = boxes[i].Center + reach;
            }
            var (sweep, order) = SweepOrder(low, high, tolerance);

            // Each overlapping pair once, (later box, earlier box, depth). One past the named ones is enough to say that
            // more overlap, so the sweep stops there: boxes piled at one spot overlap pair by pair.
            var found = new List<(int Later, int Earlier, float Depth)>();
            for (int k = 0; k < order.Length && found.Count <= MaxNamedPairs; k++)
            {
                int a = order[k];
                for (int m = k + 1; m < order.Length && Along(low[order[m]], sweep) < Along(high[a], sweep) - tolerance && found.Count <= MaxNamedPairs; m++)
                {
                    int b = order[m];
                    if (!Apart(low[a].X, high[a].X, low[b].X, high[b].X, tolerance) && !Apart(low[a].Y, high[a].Y, low[b].Y, high[b].Y, tolerance)
                        && !Apart(low[a].Z, high[a].Z, low[b].Z, high[b].Z, tolerance) && Overlap(boxes[a], boxes[b], tolerance, out float depth))
                        found.Add((Math.Max(a, b), Math.Min(a, b), depth));
                }
            }
            found.Sort((x, y) => x.Later != y.Later ? x.Later.CompareTo(y.Later) : x.Earlier.CompareTo(y.Earlier));

            for (int i = 0; i < found.Count && i < MaxNamedPairs; i++)
            {
                var (later, earlier, depth) = found[i];
                errors.Add(new ValidationError($"SpawnBoxes[{later}].Center",
                    $"SpawnBox '{boxes[later].Name}'", $"the box must not overlap SpawnBox '{boxes[earlier].Name}' (they interpenetrate by {ValidationRules.Format(depth)} m; boxes may only touch, within {ValidationRules.Format(tolerance)} m): overlapping boxes spawn particles on top of each other"));
            }
            if (found.Count > MaxNamedPairs)
                errors.Add(new ValidationError("SpawnBoxes", "FluidScene",
                    $"more pairs of spawn boxes overlap than the {MaxNamedPairs} named; move the boxes apart, then validate again"));
        }

        /// <summary>The world axis (0 x, 1 y, 2 z) along which the sweep meets fewest pairs (for each box, the later ones
        /// whose low face lies below its high face less the tolerance), and the boxes in the order of their low faces
        /// along it, ties by index.</summary>
        static (int Axis, int[] Order) SweepOrder(Vector3[] low, Vector3[] high, float tolerance)
        {
            (int Axis, int[] Order, long Pairs) best = (0, Array.Empty<int>(), long.MaxValue);
            for (int axis = 0; axis < 3; axis++)
            {
                var order = new int[low.Length];
                for (int i = 0; i < order.Length; i++) order[i] = i;
                Array.Sort(order, (a, b) => Along(low[a], axis) != Along(low[b], axis) ? Along(low[a], axis).CompareTo(Along(low[b], axis)) : a.CompareTo(b));
                var sortedLow = new float[order.Length];
                for (int k = 0; k < order.Length; k++) sortedLow[k] = Along(low[order[k]], axis);
                long pairs = 0;
                for (int k = 0; k < order.Length; k++)
                    pairs += Math.Max(0, FirstAtOrPast(sortedLow, Along(high[order[k]], axis) - tolerance) - (k + 1));
                if (pairs < best.Pairs) best = (axis, order, pairs);
            }
            return (best.Axis, best.Order);
        }

        /// <summary>The index of the first value in ascending <paramref name="sorted"/> at or past <paramref name="limit"/>.</summary>
        static int FirstAtOrPast(float[] sorted, float limit)
        {
            int lo = 0, hi = sorted.Length;
            while (lo < hi)
            {
                int mid = (lo + hi) >> 1;
                if (sorted[mid] < limit) lo = mid + 1; else hi = mid;
            }
            return lo;
        }

        static float Along(Vector3 v, int axis) => axis == 0 ? v.X : axis == 1 ? v.Y : v.Z;

        /// <summary>Two intervals that overlap by no more than <paramref name="tolerance"/>.</summary>
        static bool Apart(float lowA, float highA, float lowB, float highB, float tolerance) =>
            Math.Min(highA, highB) - Math.Max(lowA, lowB) <= tolerance;

        static bool Overlap(FluidBlock a, FluidBlock b, float tolerance, out float depth)
        {
            var axesA = Axes(a.Rotation);
            var axesB = Axes(b.Rotation);
            var candidates = new List<Vector3>(15);
            candidates.AddRange(axesA);
            candidates.AddRange(axesB);
            foreach (var u in axesA)
            foreach (var v in axesB)
            {
                var cross = Vector3.Cross(u, v);
                if (cross.LengthSquared() > 1e-8f) candidates.Add(Vector3.Normalize(cross));
            }
            depth = float.MaxValue;
            foreach (var axis in candidates)
            {
                float centre = Math.Abs(Vector3.Dot(b.Center - a.Center, axis));
                float overlap = Reach(a.Size, axesA, axis) + Reach(b.Size, axesB, axis) - centre;
                if (overlap <= tolerance) return false;
                depth = Math.Min(depth, overlap);
            }
            return true;
        }

        static Vector3[] Axes(Quaternion rotation)
        {
            var q = Quaternion.Normalize(rotation);
            return new[] { Vector3.Transform(Vector3.UnitX, q), Vector3.Transform(Vector3.UnitY, q), Vector3.Transform(Vector3.UnitZ, q) };
        }

        /// <summary>Half the box's extent along <paramref name="axis"/>.</summary>
        static float Reach(Vector3 size, Vector3[] axes, Vector3 axis) =>
            0.5f * (size.X * Math.Abs(Vector3.Dot(axes[0], axis)) + size.Y * Math.Abs(Vector3.Dot(axes[1], axis))
                + size.Z * Math.Abs(Vector3.Dot(axes[2], axis)));
    }
}
