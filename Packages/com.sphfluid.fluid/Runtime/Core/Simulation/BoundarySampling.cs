using System;
using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Samples the container's walls and every sphere obstacle with boundary particles (SphBoundary.hlsl
    /// explains how they act). Each boundary is a shell of <see cref="Layers"/> layers on the fluid's lattice
    /// spacing, deep enough that a fluid particle touching the wall finds a full neighbourhood within the
    /// kernel support. A particle's weight omega is the volume it stands for in lattice cells, V_b / s^3: 1 on a wall
    /// lattice of the fluid's spacing, so a fluid lattice next to a wall sums exactly the lattice's number density
    /// delta0 (SmoothingKernels.LatticeNumberDensity) and sits at rest density.
    /// <para>
    /// It was V_b delta0, the cell's volume times the lattice sum, which is 1 only where the lattice sum equals the
    /// continuum's 1 / s^3. For Wendland C2 it does not (3.4 % more at 2 spacings, 2.1 % at 2.3, 0.4 % at 2.85): every
    /// wall particle weighed that much more than the fluid particle it stands in for, so a fluid lattice at rest read
    /// 0.34 % compressed beside each wall at 2.3 spacings (0.93 % in a corner), and the walls' own DFSPH constraint asked
    /// for a density no motion of the fluid could give: a DFSPH tank at rest with Wendland C2 at 2 to 2.6 spacings, which
    /// validation accepts, lifted its whole fluid and failed its health check within 0.1 s.
    /// </para>
    /// </summary>
    /// <remarks>
    /// Container: points at -S/2 + (i + 1/2) a on each axis, a = S / round(S / s) (the spacing adjusted so
    /// the walls are sampled evenly), for i from -L to n + L - 1, keeping those outside the inner box: the
    /// face layers, the edges and the corners. Sphere of radius R: L concentric layers at radii
    /// R - (l + 1/2) s, each sampled on a Fibonacci spiral (Gonzalez 2010, "Measurement of areas on a
    /// sphere using Fibonacci and latitude-longitude lattices", Math. Geosciences 42) with one point per s^2
    /// of area, weighted by the volume 4 pi r^2 s / n each one stands for.
    /// </remarks>
    public static class BoundarySampling
    {
        /// <summary>Shell layers for a support of <paramref name="support"/> at spacing <paramref name="spacing"/>: ceil(H / s).</summary>
        public static int Layers(float spacing, float support) => Math.Max(1, (int)Math.Ceiling(support / spacing - 1e-4));

        /// <summary>Boundary particles of the whole scene: the container's walls first, then each obstacle.</summary>
        public static BoundaryParticle[] Sample(FluidSceneDescription scene)
        {
            var list = new List<BoundaryParticle>();
            var s = scene.Settings;
            AddContainer(list, scene.Container.Size, s.ParticleSpacing, s.SmoothingRadius);
            if (scene.Obstacles != null)
                for (int o = 0; o < scene.Obstacles.Count; o++)
                    AddSphere(list, scene.Obstacles[o].Radius, (uint)o, s.SmoothingKernel, s.ParticleSpacing, s.SmoothingRadius);
            return list.ToArray();
        }

        /// <summary>Boundary particles the container's walls need (without building them).</summary>
        public static long ContainerCount(Vector3 size, float spacing, float support)
        {
            int layers = Layers(spacing, support);
            long nx = Cells(size.X, spacing), ny = Cells(size.Y, spacing), nz = Cells(size.Z, spacing);
            return (nx + 2 * layers) * (ny + 2 * layers) * (nz + 2 * layers) - nx * ny * nz;
        }

        static int Cells(float size, float spacing) => Math.Max(1, (int)Math.Round(size / (double)spacing));

        static void AddContainer(List<BoundaryParticle> list, Vector3 size, float spacing, float support)
        {
            int layers = Layers(spacing, support);
            int nx = Cells(size.X, spacing), ny = Cells(size.Y, spacing), nz = Cells(size.Z, spacing);
            double ax = size.X / (double)nx, ay = size.Y / (double)ny, az = size.Z / (double)nz;
            float weight = (float)(ax * ay * az / ((double)spacing * spacing * spacing));
            for (int k = -layers; k < nz + layers; k++)
            for (int j = -layers; j < ny + layers; j++)
            for (int i = -layers; i < nx + layers; i++)
            {
                bool inside = i >= 0 && i < nx && j >= 0 && j < ny && k >= 0 && k < nz;
                if (inside) continue;
                var local = new Vector3(
                    (float)(-0.5 * size.X + (i + 0.5) * ax),
                    (float)(-0.5 * size.Y + (j + 0.5) * ay),
                    (float)(-0.5 * size.Z + (k + 0.5) * az));
                list.Add(new BoundaryParticle(local, weight, BoundaryParticle.ContainerOwner));
            }
        }

        /// <summary>
        /// What a sphere's shells must weigh, relative to their volume, so that a fluid particle resting half a spacing
        /// outside the sphere sums as much boundary as it would half a spacing from a flat wall. A convex shell curves
        /// away from the particle, so at equal volume it fills less of the kernel's support, and the fluid pressed
        /// against a small sphere sank past its surface (a sphere of 2.25 spacings held still in a pool: 853 clamp hits
        /// in 4 s). Continuum sums over the shells at R - (l + 1/2) s and the flat layers at the same distances; 1 for
        /// a flat wall, growing as the radius shrinks towards the support.
        /// </summary>
        public static double ConvexWeightFactor(KernelFamily kind, double radius, double spacing, double support)
        {
            int layers = Layers((float)spacing, (float)support);
            double s = spacing, flat = 0, sphere = 0, outside = radius + 0.5 * s;
            for (int l = 0; l < layers; l++)
            {
                double r = radius - (l + 0.5) * s;
                if (r <= 0.25 * s) break;
                double d = outside - r;
                flat += PlaneIntegral(kind, d, support);
                sphere += ShellIntegral(kind, outside, r, support);
            }
            return sphere > 0 ? flat / sphere : 1.0;
        }

        /// <summary>The kernel integrated over a plane at distance d: 2 pi int_0^H W(sqrt(d^2 + rho^2)) rho d rho.</summary>
        static double PlaneIntegral(KernelFamily kind, double d, double support)
        {
            const int steps = 2000;
            double sum = 0, h = support / steps;
            for (int i = 0; i < steps; i++)
            {
                double rho = (i + 0.5) * h;
                sum += SmoothingKernels.Value(kind, Math.Sqrt(d * d + rho * rho), support) * rho * h;
            }
            return 2.0 * Math.PI * sum;
        }

        /// <summary>The kernel integrated over a sphere of radius r around a centre at distance D from the point.</summary>
        static double ShellIntegral(KernelFamily kind, double distance, double r, double support)
        {
            // Only the cap within the support: a large shell meets it over a sliver of mu that even steps would miss.
            double from = distance * r > 0.0
                ? Math.Max(-1.0, (distance * distance + r * r - support * support) / (2.0 * distance * r))
                : -1.0;
            if (from >= 1.0) return 0.0;
            const int steps = 2000;
            double sum = 0, h = (1.0 - from) / steps;
            for (int i = 0; i < steps; i++)
            {
                double mu = from + (i + 0.5) * h;
                sum += SmoothingKernels.Value(kind, Math.Sqrt(Math.Max(0.0, distance * distance + r * r - 2.0 * distance * r * mu)), support) * h;
            }
            return 2.0 * Math.PI * r * r * sum;
        }

        /// <summary>
        /// Each boundary particle's number density from its own body at rest, as DFSPH's wall constraint counts it
        /// (DivergenceFreeSolver.hlsl, "Walls as unknowns"), indexed like <see cref="Sample"/>'s particles. 0 for the
        /// container's walls: on the fluid's lattice their own sum is exact, and the GPU takes it with every other wall's
        /// (WallNumberDensity). A sphere's own shells cannot be summed instead: they are weighed up for the fluid outside
        /// (<see cref="ConvexWeightFactor"/>), so at its outer particles they read 6 to 22 % above rest with the fluid spawned
        /// around them (a sphere of 3.5 spacings), and the walls' constraint pushed the fluid off the sphere: SphereWake under
        /// DFSPH reached 8 m/s at 0.13 s with its sphere still. A sphere's particle at depth d below its surface takes
        /// delta0 less the fluid that fills the rest of its support: the kernel's share outside the sphere, scaled by what a
        /// fluid lattice beyond a flat wall at the same depth sums against that wall's continuum share (a lattice is not a
        /// continuum at half a spacing from a wall), so a large sphere's particle reads as a flat wall's does.
        /// </summary>
        public static float[] OwnNumberDensities(FluidSceneDescription scene, BoundaryParticle[] particles)
        {
            var s = scene.Settings;
            KernelFamily kind = s.SmoothingKernel;
            double spacing = s.ParticleSpacing, support = s.SmoothingRadius;
            double rest = SmoothingKernels.LatticeNumberDensity(kind, spacing, support);
            var own = new float[particles.Length];
            // A shell's particles lie at one radius (to rounding), and spheres of one radius share their shells' values.
            var byShell = new Dictionary<(float, long), float>();
            for (int i = 0; i < particles.Length; i++)
            {
                uint owner = particles[i].Owner;
                if (owner == BoundaryParticle.ContainerOwner) continue;
                float sphereRadius = scene.Obstacles[(int)owner].Radius;
                double distance = particles[i].Position.Length(), radius = sphereRadius;
                var shell = (sphereRadius, (long)Math.Round(64.0 * distance / spacing));
                if (!byShell.TryGetValue(shell, out float value))
                {
                    double depth = radius - distance, flat = PlaneShare(kind, depth, support);
                    double fill = flat > 1e-12
                        ? LatticeFill(kind, depth, spacing, support) * (1.0 - BallShare(kind, distance, radius, support)) / flat
                        : 0.0;
                    value = (float)(rest - fill);
                    byShell.Add(shell, value);
                }
                own[i] = value;
            }
            return own;
        }

        /// <summary>The kernel's share beyond a plane at distance d: over the spheres of radius rho around the point, the
        /// area beyond the plane, 2 pi rho (rho - d), times W(rho).</summary>
        static double PlaneShare(KernelFamily kind, double distance, double support) =>
            RadialIntegral(kind, support, rho => rho > distance ? 2.0 * Math.PI * rho * (rho - distance) : 0.0);

        /// <summary>The number density of a fluid lattice whose rows lie (m + 1/2) s beyond a flat wall face at depth d below
        /// the point: rows at d + (m + 1/2) s, m = 0, 1, ...</summary>
        static double LatticeFill(KernelFamily kind, double depth, double spacing, double support)
        {
            double sum = 0;
            int reach = (int)Math.Ceiling(support / spacing);
            for (double z = depth + 0.5 * spacing; z < support; z += spacing)
                for (int i = -reach; i <= reach; i++)
                for (int k = -reach; k <= reach; k++)
                    sum += SmoothingKernels.Value(kind, Math.Sqrt(i * i * spacing * spacing + k * k * spacing * spacing + z * z), support);
            return sum;
        }

        /// <summary>The kernel around a point at distance d inside a ball of radius R integrated over the ball: over the
        /// spheres of radius rho around the point, the area inside the ball times W(rho). A sphere within R - d lies wholly
        /// inside; one that crosses the ball's surface keeps the cap cos(phi) &lt; (R^2 - d^2 - rho^2) / (2 d rho), phi from
        /// the direction away from the centre.</summary>
        static double BallShare(KernelFamily kind, double distance, double radius, double support) =>
            RadialIntegral(kind, support, rho =>
            {
                if (rho <= radius - distance) return 4.0 * Math.PI * rho * rho;
                if (rho >= radius + distance || distance <= 0.0) return 0.0;
                double c = (radius * radius - distance * distance - rho * rho) / (2.0 * distance * rho);
                return 2.0 * Math.PI * rho * rho * (1.0 + Math.Max(-1.0, Math.Min(1.0, c)));
            });

        /// <summary>int_0^H W(rho) area(rho) d rho: the kernel over the part of its support whose sphere of radius rho has
        /// that area.</summary>
        static double RadialIntegral(KernelFamily kind, double support, Func<double, double> area)
        {
            const int steps = 4000;
            double sum = 0, h = support / steps;
            for (int i = 0; i < steps; i++)
            {
                double rho = (i + 0.5) * h;
                sum += SmoothingKernels.Value(kind, rho, support) * area(rho) * h;
            }
            return sum;
        }

        static void AddSphere(List<BoundaryParticle> list, float radius, uint owner, KernelFamily kind, float spacing, float support)
        {
            int layers = Layers(spacing, support);
            double s = spacing, cell = s * s * s;
            double golden = Math.PI * (3.0 - Math.Sqrt(5.0));
            double curvature = ConvexWeightFactor(kind, radius, spacing, support);
            for (int l = 0; l < layers; l++)
            {
                double r = radius - (l + 0.5) * s;
                if (r <= 0.25 * s)
                {
                    // The core of a small sphere: one particle for the volume left inside.
                    double rest = Math.Max(0.0, radius - l * s);
                    double volume = 4.0 / 3.0 * Math.PI * rest * rest * rest;
                    if (volume > 0) list.Add(new BoundaryParticle(Vector3.Zero, (float)(volume / cell), owner));
                    break;
                }
                int n = Math.Max(1, (int)Math.Round(4.0 * Math.PI * r * r / (s * s)));
                float weight = (float)(4.0 * Math.PI * r * r * s / n / cell * curvature);
                for (int p = 0; p < n; p++)
                {
                    double y = 1.0 - 2.0 * (p + 0.5) / n;
                    double ring = Math.Sqrt(Math.Max(0.0, 1.0 - y * y));
                    double phi = golden * p;
                    var direction = new Vector3((float)(ring * Math.Cos(phi)), (float)y, (float)(ring * Math.Sin(phi)));
                    list.Add(new BoundaryParticle(direction * (float)r, weight, owner));
                }
            }
        }
    }
}
