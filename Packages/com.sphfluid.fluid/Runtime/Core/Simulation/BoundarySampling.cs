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
            const int steps = 2000;
            double sum = 0, h = 2.0 / steps;
            for (int i = 0; i < steps; i++)
            {
                double mu = -1.0 + (i + 0.5) * h;
                sum += SmoothingKernels.Value(kind, Math.Sqrt(Math.Max(0.0, distance * distance + r * r - 2.0 * distance * r * mu)), support) * h;
            }
            return 2.0 * Math.PI * r * r * sum;
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
