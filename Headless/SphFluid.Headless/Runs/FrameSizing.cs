using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace SphFluid.Headless.Runs;

/// <summary>
/// How many particles a scene can have and still simulate a 60 Hz frame's worth of time in a frame: the GPU
/// milliseconds per frame (a sub-step's GPU time times the sub-steps of dt a 60 Hz frame takes) measured at several
/// particle counts, interpolated to the count that spends a budget. Another GPU is estimated from how many times slower
/// it is per particle. Only that part is scaled: a sub-step's GPU time is split into a fixed part and a part per
/// particle (<see cref="SplitCost"/>), and the fixed part, which is most of a small scene's, is each pass's longest
/// thread walking its neighbourhood one candidate after another, a latency a smaller card of similar clock shares.
/// Which throughput sets the ratio is measured, not assumed: an H100 and an H200, the same chip with 1.43 times the
/// memory bandwidth apart, cost the same per particle (README), so the ratio is not the memory bandwidth's.
/// </summary>
public static class FrameSizing
{
    /// <summary>Simulated seconds a 60 Hz frame must advance to run in real time.</summary>
    public const double FrameSeconds = 1.0 / 60.0;

    /// <summary>The default share of a 60 Hz frame's 16.7 ms that the simulation's GPU time may take: half, leaving the
    /// other half to drawing the particles and to the rest of the game.</summary>
    public const double DefaultBudgetMs = 1000.0 * FrameSeconds / 2;

    /// <summary>The largest particle count within the budget. <paramref name="BelowRange"/>: even the fewest measured
    /// (<paramref name="Particles"/>) spent more; <paramref name="AboveRange"/>: even the most measured spent less.</summary>
    public sealed record Fit(double Particles, bool BelowRange, bool AboveRange)
    {
        public override string ToString()
        {
            var c = CultureInfo.InvariantCulture;
            if (BelowRange) return string.Format(c, "fewer than {0:N0} particles (the fewest measured)", Particles);
            if (AboveRange) return string.Format(c, "more than {0:N0} particles (the most measured)", Particles);
            return string.Format(c, "about {0:N0} particles", RoundToTwoFigures(Particles));
        }
    }

    /// <summary>
    /// The count at which the frame time, interpolated linearly in log(particles) against log(ms) between the last
    /// measured count within <paramref name="budgetMs"/> and the first beyond it, reaches the budget. Counts beyond the
    /// first one over budget are not consulted: a noisy larger row that happens to read less must not extend the fit.
    /// </summary>
    public static Fit Largest(IReadOnlyList<(int Particles, double FrameMs)> rows, double budgetMs)
    {
        if (rows.Count == 0) throw new ArgumentException("no measured rows", nameof(rows));
        if (!(budgetMs > 0)) throw new ArgumentOutOfRangeException(nameof(budgetMs), budgetMs, "the budget must be > 0 ms");
        var sorted = rows.OrderBy(r => r.Particles).ToList();
        if (sorted[0].FrameMs > budgetMs) return new Fit(sorted[0].Particles, true, false);
        for (int k = 1; k < sorted.Count; k++)
        {
            if (sorted[k].FrameMs <= budgetMs) continue;
            var (n0, t0) = sorted[k - 1];
            var (n1, t1) = sorted[k];
            if (t0 <= 0 || n1 <= n0) return new Fit(n0, false, false);
            double slope = Math.Log((double)n1 / n0) / Math.Log(t1 / t0);
            return new Fit(n0 * Math.Exp(slope * Math.Log(budgetMs / t0)), false, false);
        }
        return new Fit(sorted[^1].Particles, false, true);
    }

    /// <summary>
    /// A sub-step's GPU time as <paramref name="FixedMs"/> plus <paramref name="MsPerParticle"/> times the particles: the
    /// least-squares fit of the measured rows in relative error (each row weighs alike, whatever its size), neither
    /// part below zero. One row, or rows of one count, give no split: all of it is per particle.
    /// </summary>
    public sealed record Cost(double FixedMs, double MsPerParticle)
    {
        public double SubstepMs(double particles) => FixedMs + MsPerParticle * particles;
    }

    public static Cost SplitCost(IReadOnlyList<(int Particles, double SubstepMs)> rows)
    {
        if (rows.Count == 0) throw new ArgumentException("no measured rows", nameof(rows));
        // Minimise sum ((a + b n - t) / t)^2: the normal equations of x = (1/t, n/t) against 1.
        double s11 = 0, s12 = 0, s22 = 0, r1 = 0, r2 = 0;
        foreach (var (n, t) in rows)
        {
            if (!(t > 0)) continue;
            double x1 = 1 / t, x2 = n / t;
            s11 += x1 * x1; s12 += x1 * x2; s22 += x2 * x2; r1 += x1; r2 += x2;
        }
        double det = s11 * s22 - s12 * s12;
        double perParticleOnly = s22 > 0 ? r2 / s22 : 0;
        if (!(Math.Abs(det) > 1e-12 * s11 * s22)) return new Cost(0, perParticleOnly);
        double a = (r1 * s22 - r2 * s12) / det, b = (s11 * r2 - s12 * r1) / det;
        if (a < 0) return new Cost(0, perParticleOnly);
        if (b < 0) return new Cost(r1 / s11, 0);
        return new Cost(a, b);
    }

    static double RoundToTwoFigures(double x)
    {
        if (x <= 0) return x;
        double unit = Math.Pow(10, Math.Floor(Math.Log10(x)) - 1);
        return Math.Round(x / unit) * unit;
    }
}
