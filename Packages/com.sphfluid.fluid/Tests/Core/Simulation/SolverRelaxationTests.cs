using System;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// The relaxation of DFSPH's Jacobi step (SolverRelaxation). Its wave analysis must be the solve's own operator: on a
    /// periodic lattice, q applied through the pair force and the number density's rate of change as the solver writes them
    /// (DivergenceFreeSolver.hlsl), divided by the DFSPH factor, must have the largest eigenvalue the analysis predicts, and
    /// the factor must be the waves' average. At DFSPH's 2 spacings that eigenvalue is above 2 for both kernels, so the
    /// papers' full step overshoots, and the relaxed step must bring every wave down without changing its sign.
    /// </summary>
    public sealed class SolverRelaxationTests
    {
        const double Spacing = 1.0, Support = 2.0;

        /// <summary>Wendland C2 at 2.85 spacings, the support of the RestingTank and OilAndWater scenes, is checked too: its
        /// stiffest wave sets DFSPH's relaxation limit there (SolverRelaxation.StableLimit, 2 / 5.38).</summary>
        [TestCase(KernelFamily.CubicSpline, 2.0, 2.82)]
        [TestCase(KernelFamily.WendlandC2, 2.0, 2.61)]
        [TestCase(KernelFamily.WendlandC2, 2.85, 5.38)]
        public void ThePapersFullStepOvershootsTheStiffestLatticeWave(KernelFamily kind, double supportRatio, double expected)
        {
            double support = supportRatio * Spacing;
            double stiffest = SolverRelaxation.StiffestMode(kind, Spacing, support);
            TestContext.Progress.WriteLine($"{kind} at {supportRatio} spacings: lambda_max {stiffest:F3}, omega {SolverRelaxation.For(kind, Spacing, support):F3}");
            Assert.That(stiffest, Is.EqualTo(expected).Within(0.01));
            Assert.That(stiffest, Is.GreaterThan(2.0), "1 - lambda_max below -1: the full step makes this wave grow");
        }

        /// <summary>The DFSPH factor is the operator's diagonal, so lambda averages to 1 over the zone (sampled on a grid fine
        /// enough that the sines of the neighbour offsets are exactly orthogonal on it).</summary>
        [TestCase(KernelFamily.CubicSpline)]
        [TestCase(KernelFamily.WendlandC2)]
        public void TheWavesAverageToTheFactor(KernelFamily kind)
        {
            const int n = 16;
            double sum = 0.0;
            for (int a = 0; a < n; a++)
            for (int b = 0; b < n; b++)
            for (int c = 0; c < n; c++)
                sum += SolverRelaxation.Mode(kind, Spacing, Support, 2 * Math.PI * a / n, 2 * Math.PI * b / n, 2 * Math.PI * c / n);
            Assert.That(sum / (n * n * n), Is.EqualTo(1.0).Within(1e-9));
        }

        /// <summary>On a grid finer than, and offset from, the one the maximum is searched on, no wave's residual changes sign
        /// by more than 1 % under the relaxed step (none can grow the other way: lambda is a square, so 1 - omega lambda is at
        /// most 1).</summary>
        [TestCase(KernelFamily.CubicSpline)]
        [TestCase(KernelFamily.WendlandC2)]
        public void TheRelaxedStepBringsEveryWaveDownWithoutFlippingIt(KernelFamily kind)
        {
            double omega = SolverRelaxation.For(kind, Spacing, Support);
            const int n = 37;
            double lowest = 1.0;
            for (int a = 0; a <= n; a++)
            for (int b = 0; b <= a; b++)
            for (int c = 0; c <= b; c++)
            {
                double factor = 1.0 - omega * SolverRelaxation.Mode(kind, Spacing, Support, Math.PI * a / n, Math.PI * b / n, Math.PI * c / n);
                lowest = Math.Min(lowest, factor);
            }
            Assert.That(lowest, Is.GreaterThanOrEqualTo(-0.01));
        }

        /// <summary>The largest eigenvalue of the solve's operator on a periodic 12^3 lattice, by power iteration: q_j moves
        /// particle i by -(q_i + q_j) gradW_ij (dt = m = 1), the number density changes by sum_j gradW_ij . (dv_i - dv_j), and the
        /// step divides by sum_j |gradW_ij|^2. The 12-point lattice holds the cubic spline's stiffest wave (k = pi / 3 per axis
        /// in two axes) only nearly, so the power iteration may read a little below the zone's maximum, never above.</summary>
        [TestCase(KernelFamily.CubicSpline)]
        [TestCase(KernelFamily.WendlandC2)]
        public void TheAnalysisIsTheSolvesOperator(KernelFamily kind)
        {
            const int side = 12;
            int count = side * side * side;
            var pairs = new System.Collections.Generic.List<(int J, double Gx, double Gy, double Gz)>[count];
            var diagonal = new double[count];
            for (int i = 0; i < count; i++)
            {
                pairs[i] = new System.Collections.Generic.List<(int, double, double, double)>();
                int ix = i % side, iy = i / side % side, iz = i / (side * side);
                for (int dx = -2; dx <= 2; dx++)
                for (int dy = -2; dy <= 2; dy++)
                for (int dz = -2; dz <= 2; dz++)
                {
                    double r = Math.Sqrt(dx * dx + dy * dy + dz * dz);
                    if (r <= 0.0 || r >= Support) continue;
                    int j = Wrap(ix - dx, side) + side * (Wrap(iy - dy, side) + side * Wrap(iz - dz, side));
                    double radial = SmoothingKernels.Derivative(kind, r, Support) / r; // r_ij = x_i - x_j = (dx, dy, dz)
                    pairs[i].Add((j, radial * dx, radial * dy, radial * dz));
                    diagonal[i] += radial * radial * r * r;
                }
            }
            var random = new Random(7);
            var q = new double[count];
            for (int i = 0; i < count; i++) q[i] = random.NextDouble() - 0.5;
            double lambda = 0.0;
            var dv = new double[3 * count];
            var next = new double[count];
            for (int iteration = 0; iteration < 400; iteration++)
            {
                for (int i = 0; i < count; i++)
                {
                    double x = 0, y = 0, z = 0;
                    foreach (var (j, gx, gy, gz) in pairs[i])
                    {
                        x -= (q[i] + q[j]) * gx;
                        y -= (q[i] + q[j]) * gy;
                        z -= (q[i] + q[j]) * gz;
                    }
                    dv[3 * i] = x; dv[3 * i + 1] = y; dv[3 * i + 2] = z;
                }
                double norm = 0.0, dot = 0.0;
                for (int i = 0; i < count; i++)
                {
                    double rate = 0.0;
                    foreach (var (j, gx, gy, gz) in pairs[i])
                        rate += gx * (dv[3 * i] - dv[3 * j]) + gy * (dv[3 * i + 1] - dv[3 * j + 1]) + gz * (dv[3 * i + 2] - dv[3 * j + 2]);
                    next[i] = -rate / diagonal[i];
                    dot += next[i] * q[i];
                    norm += next[i] * next[i];
                }
                double qq = 0.0;
                foreach (double v in q) qq += v * v;
                lambda = dot / qq;
                norm = Math.Sqrt(norm);
                for (int i = 0; i < count; i++) q[i] = next[i] / norm;
            }
            double predicted = SolverRelaxation.StiffestMode(kind, Spacing, Support);
            TestContext.Progress.WriteLine($"{kind}: power iteration {lambda:F4}, analysis {predicted:F4}");
            Assert.That(lambda, Is.LessThanOrEqualTo(predicted * 1.001));
            Assert.That(lambda, Is.GreaterThanOrEqualTo(predicted * 0.98));
        }

        static int Wrap(int index, int side) => ((index % side) + side) % side;
    }
}
