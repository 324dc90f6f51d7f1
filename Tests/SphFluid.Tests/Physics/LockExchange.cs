using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using SphFluid.Headless.Output;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The lock exchange: two liquids of densities rho_heavy &gt; rho_light side by side in a channel of depth H, released
    /// at once. The heavy one runs under the light one along the floor and the light one over it along the top, each
    /// front at a constant speed once the fluid has accelerated, until it meets the end wall. Benjamin's steady gravity
    /// current ("Gravity currents and related phenomena", 1968) flowing without loss of energy fills half the channel,
    /// and a current of depth H / 2 advancing into a liquid at rest moves at
    ///   U = (1/2) sqrt(g H (rho_heavy - rho_light) / rho_ambient),
    /// the ambient being the liquid it runs into (his flow-force balance, in which only the ambient moves in the front's
    /// frame). That is a Froude number U / sqrt(g' H) of one half, the fastest a current can run: one that loses energy to
    /// viscosity or mixing runs slower and thinner, and none runs faster (Shin, Dalziel and Linden, "Gravity currents
    /// produced by lock exchange", 2004, take the lock exchange's two currents to be his).
    /// </summary>
    public static class LockExchange
    {
        /// <summary>Benjamin's energy-conserving front speed, m/s, of a current running into <paramref name="ambientDensity"/>.</summary>
        public static double FrontSpeed(double gravity, double depth, double heavyDensity, double lightDensity, double ambientDensity) =>
            0.5 * Math.Sqrt(gravity * depth * (heavyDensity - lightDensity) / ambientDensity);

        /// <summary>Particles with fewer than this many others of their own liquid within the support are strays, and set no front.</summary>
        public const int Company = 3;

        /// <summary>
        /// The two fronts, container-local x (the container axis-aligned): the heavy liquid's farthest reach in +x (it
        /// starts at -x) and the light liquid's farthest reach in -x, each the farthest particle of its liquid with
        /// <see cref="Company"/> others of the same liquid within the support, so that a particle carried ahead of its
        /// current on its own sets no front.
        /// </summary>
        public static (double Heavy, double Light) Fronts(Particle[] particles, Vector3 containerCentre, uint heavy, uint light, float supportRadius)
        {
            double Farthest(uint phase, int sign)
            {
                var own = particles.Where(p => p.Phase == phase).Select(p => p.Position - containerCentre).ToArray();
                var neighbourhood = new ParticleNeighbourhood(own, supportRadius);
                foreach (int i in Enumerable.Range(0, own.Length).OrderByDescending(i => sign * own[i].X))
                    if (!neighbourhood.IsIsolated(i, Company)) return own[i].X;
                return double.NaN;
            }
            return (Farthest(heavy, +1), Farthest(light, -1));
        }

        /// <summary>Width, m, of the column behind a front over which <see cref="Heads"/> takes a liquid's share of the depth:
        /// the shipped scene's spacing, fixed, so that the measure does not change with the resolution.</summary>
        public const double HeadColumn = 0.015;

        /// <summary>The share of the depth that makes a head: half the body of Benjamin's current, which fills half.</summary>
        public const double HeadShare = 0.25;

        /// <summary>
        /// The two fronts measured by depth rather than by neighbours, container-local x as <see cref="Fronts"/>: the
        /// farthest x at which a liquid makes up at least <see cref="HeadShare"/> of the particles in the
        /// <see cref="HeadColumn"/>-wide column behind it. Every particle of either liquid stands for the same volume, so
        /// that is its share of the depth there. A film running ahead a few particles thick sets no front at any
        /// resolution, where the neighbour rule of <see cref="Fronts"/> counts a thinner film as the support shrinks. A
        /// steady head reads a constant distance ahead of its nose, which leaves its speed as it is.
        /// </summary>
        public static (double Heavy, double Light) Heads(Particle[] particles, Vector3 containerCentre, uint heavy, uint light)
        {
            const double bin = 0.001;
            int window = (int)Math.Round(HeadColumn / bin);
            double low = particles.Min(p => p.Position.X - containerCentre.X), high = particles.Max(p => p.Position.X - containerCentre.X);
            int bins = (int)Math.Ceiling((high - low) / bin) + 1;
            var all = new int[bins + 1];
            var heavyCount = new int[bins + 1];
            var lightCount = new int[bins + 1];
            foreach (var p in particles)
            {
                int b = Math.Min(bins - 1, (int)((p.Position.X - containerCentre.X - low) / bin)) + 1;
                all[b]++;
                if (p.Phase == heavy) heavyCount[b]++;
                else if (p.Phase == light) lightCount[b]++;
            }
            for (int b = 1; b <= bins; b++)
            {
                all[b] += all[b - 1];
                heavyCount[b] += heavyCount[b - 1];
                lightCount[b] += lightCount[b - 1];
            }
            bool IsHead(int[] own, int first, int last) // bins first..last, 0-based and clamped
            {
                first = Math.Max(0, first);
                last = Math.Min(bins - 1, last);
                int total = all[last + 1] - all[first];
                return total > 0 && own[last + 1] - own[first] >= HeadShare * total;
            }
            double heavyHead = double.NaN, lightHead = double.NaN;
            for (int b = bins - 1; b >= 0; b--)
                if (IsHead(heavyCount, b - window + 1, b)) { heavyHead = low + (b + 1) * bin; break; }
            for (int b = 0; b < bins; b++)
                if (IsHead(lightCount, b, b + window - 1)) { lightHead = low + b * bin; break; }
            return (heavyHead, lightHead);
        }

        /// <summary>Least-squares speed, m/s, of a front's distance from the lock over the samples where it lies between
        /// <paramref name="from"/> and <paramref name="to"/> metres from it.</summary>
        public static (double Speed, int Samples) Speed(IReadOnlyList<double> times, IReadOnlyList<double> distances, double from, double to)
        {
            var points = Enumerable.Range(0, times.Count).Where(k => distances[k] >= from && distances[k] <= to)
                .Select(k => (T: times[k], X: distances[k])).ToList();
            if (points.Count < 3) return (double.NaN, points.Count);
            double mt = points.Average(p => p.T), mx = points.Average(p => p.X);
            double stx = points.Sum(p => (p.T - mt) * (p.X - mx)), stt = points.Sum(p => (p.T - mt) * (p.T - mt));
            return (stx / stt, points.Count);
        }
    }
}
