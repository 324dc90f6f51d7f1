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
        /// <summary>Adds one error per overlapping pair, naming both boxes. Needs valid boxes.</summary>
        internal static void Validate(FluidSceneDescription scene, List<ValidationError> errors)
        {
            float tolerance = 0.01f * scene.Settings.ParticleSpacing;
            var boxes = scene.SpawnBoxes;
            for (int a = 0; a < boxes.Count; a++)
            for (int b = a + 1; b < boxes.Count; b++)
            {
                if (!Overlap(boxes[a], boxes[b], tolerance, out float depth)) continue;
                errors.Add(new ValidationError($"SpawnBoxes[{b}].Center",
                    $"SpawnBox '{boxes[b].Name}'", $"the box must not overlap SpawnBox '{boxes[a].Name}' (they interpenetrate by {ValidationRules.Format(depth)} m; boxes may only touch, within {ValidationRules.Format(tolerance)} m): overlapping boxes spawn particles on top of each other"));
            }
        }

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
