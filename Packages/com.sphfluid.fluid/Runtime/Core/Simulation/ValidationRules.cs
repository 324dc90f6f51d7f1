using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>Range checks that append a <see cref="ValidationError"/> worded the same way everywhere:
    /// "Field must be in [min, max] unit (was value)", owned by the object the caller names.</summary>
    internal static class ValidationRules
    {
        internal static string Format(float value) => value.ToString("G6", CultureInfo.InvariantCulture);
        internal static string Format(double value) => value.ToString("G6", CultureInfo.InvariantCulture);
        internal static string Format(Vector3 v) => $"({Format(v.X)}, {Format(v.Y)}, {Format(v.Z)})";

        internal static string Unit(string unit) => string.IsNullOrEmpty(unit) ? "" : " " + unit;

        internal static bool InRange(List<ValidationError> errors, string owner, string path, string field,
            float value, float min, float max, string unit)
        {
            if (!float.IsNaN(value) && !float.IsInfinity(value) && value >= min && value <= max) return true;
            errors.Add(new ValidationError(path + field,
                owner, $"{field} must be in [{Format(min)}, {Format(max)}]{Unit(unit)} (was {Format(value)})"));
            return false;
        }

        internal static bool InRange(List<ValidationError> errors, string owner, string path, string field,
            int value, int min, int max, string unit)
        {
            if (value >= min && value <= max) return true;
            errors.Add(new ValidationError(path + field,
                owner, $"{field} must be in [{min}, {max}]{Unit(unit)} (was {value})"));
            return false;
        }

        /// <summary>Strictly positive and at most <paramref name="max"/>: (0, max].</summary>
        internal static bool Positive(List<ValidationError> errors, string owner, string path, string field,
            float value, float max, string unit)
        {
            if (!float.IsNaN(value) && !float.IsInfinity(value) && value > 0f && value <= max) return true;
            errors.Add(new ValidationError(path + field,
                owner, $"{field} must be in (0, {Format(max)}]{Unit(unit)} (was {Format(value)})"));
            return false;
        }

        internal static bool Finite(List<ValidationError> errors, string owner, string path, string field,
            Vector3 value, float maxMagnitude, string unit)
        {
            bool finite = IsFinite(value.X) && IsFinite(value.Y) && IsFinite(value.Z);
            if (finite && value.Length() <= maxMagnitude) return true;
            errors.Add(new ValidationError(path + field,
                owner, $"{field} must be finite with magnitude in [0, {Format(maxMagnitude)}]{Unit(unit)} (was {Format(value)})"));
            return false;
        }

        internal static bool PositiveVector(List<ValidationError> errors, string owner, string path, string field,
            Vector3 value, float max, string unit)
        {
            bool ok = IsFinite(value.X) && IsFinite(value.Y) && IsFinite(value.Z)
                && value.X > 0 && value.Y > 0 && value.Z > 0 && value.X <= max && value.Y <= max && value.Z <= max;
            if (ok) return true;
            errors.Add(new ValidationError(path + field,
                owner, $"each {field} component must be in (0, {Format(max)}]{Unit(unit)} (was {Format(value)})"));
            return false;
        }

        internal static bool Rotation(List<ValidationError> errors, string owner, string path, string field, Quaternion q)
        {
            float len = q.Length();
            if (IsFinite(len) && Math.Abs(len - 1f) <= FluidSceneDescription.RotationLengthTolerance) return true;
            errors.Add(new ValidationError(path + field,
                owner, $"{field} must be a unit quaternion (length in {FluidSceneDescription.RotationLengthRange}) (was length {Format(len)})"));
            return false;
        }

        internal static bool IsFinite(float v) => !float.IsNaN(v) && !float.IsInfinity(v);
    }
}
