using System;
using NUnit.Framework;
using SphFluid.Reference;

namespace SphFluid.Tests.Solver
{
    /// <summary>GPU results against the double-precision reference (ReferenceSph), per particle, relative to the largest
    /// reference value: the worst particle is printed and must be within the tolerance.</summary>
    static class ReferenceComparison
    {
        public static void Compare(string what, double tolerance, int n, Func<int, double> expected, Func<int, double> actual)
        {
            double scale = Math.Max(Max(n, expected), 1e-30), worst = 0;
            int at = -1;
            for (int i = 0; i < n; i++)
            {
                double e = Math.Abs(actual(i) - expected(i)) / scale;
                if (e > worst) { worst = e; at = i; }
            }
            TestContext.Out.WriteLine($"{what}: scale {scale:G4}, worst relative error {worst:E2}");
            Assert.That(worst, Is.LessThanOrEqualTo(tolerance), $"{what}: particle id {at} (scale {scale:G4})");
        }

        /// <summary>Vectors compared by their largest component error, relative to the largest reference length.</summary>
        public static void CompareVectors(string what, double tolerance, int n, Func<int, Double3> expected, Func<int, Double3> actual)
        {
            double scale = Math.Max(Max(n, i => expected(i).Length()), 1e-30), worst = 0;
            int at = -1;
            for (int i = 0; i < n; i++)
            {
                var d = actual(i) - expected(i);
                double e = Math.Max(Math.Abs(d.X), Math.Max(Math.Abs(d.Y), Math.Abs(d.Z))) / scale;
                if (e > worst) { worst = e; at = i; }
            }
            TestContext.Out.WriteLine($"{what}: scale {scale:G4}, worst relative component error {worst:E2}");
            Assert.That(worst, Is.LessThanOrEqualTo(tolerance), $"{what}: particle id {at} (scale {scale:G4})");
        }

        /// <summary>The largest magnitude of <paramref name="f"/> over the particles.</summary>
        public static double Max(int n, Func<int, double> f)
        {
            double m = 0;
            for (int i = 0; i < n; i++) m = Math.Max(m, Math.Abs(f(i)));
            return m;
        }
    }
}
