using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace SphFluid.Headless.Runs;

/// <summary>
/// How many particles a scene can have and still simulate a 60 Hz frame's worth of time in a frame: the GPU
/// milliseconds per frame (a sub-step's GPU time times the sub-steps of dt a 60 Hz frame takes) measured at several
/// particle counts, interpolated to the count that spends a budget. Another GPU is estimated by multiplying the measured
/// milliseconds by how many times less memory bandwidth it has (issue #8: the neighbour loops that are most of a
/// sub-step stream particles, so they scale with bandwidth). That overstates the time of small scenes, whose GPU time is
/// mostly dispatch latency that a slower card does not multiply, so the estimate errs towards fewer particles.
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

    static double RoundToTwoFigures(double x)
    {
        if (x <= 0) return x;
        double unit = Math.Pow(10, Math.Floor(Math.Log10(x)) - 1);
        return Math.Round(x / unit) * unit;
    }
}
