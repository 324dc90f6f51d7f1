using System;
using System.Numerics;

namespace SphFluid.Reference
{
    /// <summary>A double-precision 3-vector for the CPU reference (System.Numerics has none).</summary>
    public struct Double3
    {
        public double X, Y, Z;

        public Double3(double x, double y, double z) { X = x; Y = y; Z = z; }
        public Double3(Vector3 v) { X = v.X; Y = v.Y; Z = v.Z; }

        public static readonly Double3 Zero = new Double3(0, 0, 0);

        public double this[int axis]
        {
            get => axis == 0 ? X : axis == 1 ? Y : Z;
            set { if (axis == 0) X = value; else if (axis == 1) Y = value; else Z = value; }
        }

        public static Double3 operator +(Double3 a, Double3 b) => new Double3(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        public static Double3 operator -(Double3 a, Double3 b) => new Double3(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        public static Double3 operator -(Double3 a) => new Double3(-a.X, -a.Y, -a.Z);
        public static Double3 operator *(Double3 a, double s) => new Double3(a.X * s, a.Y * s, a.Z * s);
        public static Double3 operator *(double s, Double3 a) => new Double3(a.X * s, a.Y * s, a.Z * s);
        public static Double3 operator /(Double3 a, double s) => new Double3(a.X / s, a.Y / s, a.Z / s);

        public static double Dot(Double3 a, Double3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
        public static Double3 Cross(Double3 a, Double3 b) =>
            new Double3(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

        public double LengthSquared() => Dot(this, this);
        public double Length() => Math.Sqrt(Dot(this, this));

        public Vector3 ToVector3() => new Vector3((float)X, (float)Y, (float)Z);

        public override string ToString() => $"({X:G6}, {Y:G6}, {Z:G6})";
    }
}
