using System;
using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Starts the WCSPH fluid in hydrostatic equilibrium: every spawned particle is lowered along gravity so that
    /// the fluid below it is compressed to the density the Tait equation of state needs to carry the weight
    /// above it. A resting tank spawned on the plain lattice would instead start with zero pressure, fall by
    /// that compression, and ring with pressure waves for seconds. The DFSPH fluid stays on the lattice (below).
    /// </summary>
    /// <remarks>
    /// Along the vertical line through a particle (up = -g), the pressure at height y is the weight of the
    /// spawned fluid above it, p(y) = |g| sum_boxes rho0_box L_box(y), with L_box(y) the length of that line
    /// above y inside the box. Under DFSPH the fluid is incompressible: its constant-density solve holds every particle
    /// at the rest density whatever the pressure, so the particles stay on the lattice and only the pressures are
    /// reported (a column compressed for the Tait fluid would be expanded by the first solve within one sub-step, a
    /// jolt through the whole column).
    /// Under WCSPH the density the equation of state asks for is
    /// rho / rho0 = (1 + p / k)^(1 / gamma) (Becker &amp; Teschner 2007, eq. 6, inverted), so each fluid layer
    /// of thickness dy shrinks to dy rho0 / rho, and a particle at height y moves down by
    /// D(y) = integral over the fluid below y of (1 - rho0 / rho(y')) dy'. The integral is taken by the
    /// midpoint rule in <see cref="Steps"/> pieces per box crossed; the particle count, ids and masses are
    /// unchanged.
    /// A sphere obstacle below the particle on that line holds the fluid above it: only the fluid between the
    /// sphere's top and the particle is compressed under it. (Taking the whole column lowered the particles resting on
    /// a submerged sphere by the compression of fluid the sphere displaces, 0.14 spacings inside the spawn's
    /// half-spacing margin in the SphereWake scene, and those started 12 % compressed.) The pressure is still the
    /// weight of the boxes' fluid above, the hydrostatic pressure at that depth, with or without a sphere there.
    /// </remarks>
    public static class HydrostaticSpawn
    {
        /// <summary>Midpoint-rule pieces per metre of fluid crossed (at least 64 per box).</summary>
        const int Steps = 64;

        /// <summary>Lowers <paramref name="particles"/> (spawned from <paramref name="scene"/>'s boxes) into hydrostatic equilibrium.</summary>
        public static void Apply(FluidSceneDescription scene, Particle[] particles) => Apply(scene, particles, null);

        /// <summary>As <see cref="Apply(FluidSceneDescription, Particle[])"/>, and writes into <paramref name="pressures"/> (when given,
        /// indexed like the particles) the pressure p each particle was lowered for, Pa: the weight of the spawned fluid above it.</summary>
        public static void Apply(FluidSceneDescription scene, Particle[] particles, double[] pressures)
        {
            var settings = scene.Settings;
            float g = settings.Gravity.Length();
            if (!(g > 0f) || particles.Length == 0) return;
            var up = -(Vector3)settings.Gravity / g;
            var boxes = scene.SpawnBoxes;
            bool compressible = settings.PressureSolver == PressureSolver.Wcsph;
            for (int i = 0; i < particles.Length; i++)
            {
                var x = particles[i].Position;
                double floor = HighestObstacleBelow(scene.Obstacles, x, up);
                double drop = Drop(boxes, x, up, floor, g, settings.Stiffness, settings.Gamma, out double pressure);
                if (pressures != null) pressures[i] = pressure;
                if (compressible) particles[i].Position = x - up * (float)drop;
            }
        }

        /// <summary>How far the particle at <paramref name="x"/> moves down: the compression of the fluid below it, down to
        /// <paramref name="floor"/> (the line's parameter t of a solid that carries it, or -infinity).</summary>
        static double Drop(List<FluidBlock> boxes, Vector3 x, Vector3 up, double floor, float g, float stiffness, float gamma, out double pressureHere)
        {
            // The vertical line x + t up: each box occupies one interval [enter, exit] of t.
            var spans = new List<(double Enter, double Exit, double Density)>();
            foreach (var box in boxes)
                if (Crossing(box, x, up, out double enter, out double exit))
                    spans.Add((enter, exit, box.Phase.RestDensity));
            pressureHere = 0.0;
            foreach (var span in spans)
                pressureHere += span.Density * g * Math.Max(0.0, span.Exit - Math.Max(span.Enter, 0.0));
            double drop = 0.0;
            foreach (var span in spans)
            {
                // The part of this box below the particle (t < 0) is compressed by the weight above each point.
                double from = Math.Max(span.Enter, floor), to = Math.Min(span.Exit, 0.0);
                if (to <= from) continue;
                int n = Math.Max(Steps, (int)Math.Ceiling((to - from) * 1000.0));
                double dt = (to - from) / n;
                for (int k = 0; k < n; k++)
                {
                    double t = from + (k + 0.5) * dt;
                    double pressure = 0.0;
                    foreach (var other in spans)
                        pressure += other.Density * g * Math.Max(0.0, other.Exit - Math.Max(other.Enter, t));
                    double ratio = Math.Pow(1.0 + pressure / stiffness, 1.0 / gamma);
                    drop += (1.0 - 1.0 / ratio) * dt;
                }
            }
            return drop;
        }

        /// <summary>The top of the highest sphere obstacle the line x + t up crosses below x (t &lt;= 0), or -infinity.
        /// Spawned particles lie outside every sphere, so a sphere the line crosses lies wholly below or above x.</summary>
        static double HighestObstacleBelow(List<RigidSphere> obstacles, Vector3 x, Vector3 up)
        {
            double top = double.NegativeInfinity;
            if (obstacles == null) return top;
            foreach (var sphere in obstacles)
            {
                // |x + t up - c|^2 = r^2 with |up| = 1: t = -b +- sqrt(b^2 - q).
                var offset = x - sphere.Center;
                double b = Vector3.Dot(up, offset);
                double q = (double)offset.LengthSquared() - (double)sphere.Radius * sphere.Radius;
                double discriminant = b * b - q;
                if (discriminant <= 0.0) continue;
                double exit = -b + Math.Sqrt(discriminant);
                if (exit <= 0.0) top = Math.Max(top, exit);
            }
            return top;
        }

        /// <summary>Where the line x + t up enters and leaves the (rotated) box, by the slab method.</summary>
        static bool Crossing(FluidBlock box, Vector3 x, Vector3 up, out double enter, out double exit)
        {
            var inverse = Quaternion.Conjugate(Quaternion.Normalize(box.Rotation));
            var origin = Vector3.Transform(x - box.Center, inverse);
            var direction = Vector3.Transform(up, inverse);
            var half = box.Size * 0.5f;
            enter = double.NegativeInfinity;
            exit = double.PositiveInfinity;
            for (int axis = 0; axis < 3; axis++)
            {
                double o = Component(origin, axis), d = Component(direction, axis), h = Component(half, axis);
                if (Math.Abs(d) < 1e-9)
                {
                    if (o < -h || o > h) return false;
                    continue;
                }
                double t0 = (-h - o) / d, t1 = (h - o) / d;
                if (t0 > t1) { double t = t0; t0 = t1; t1 = t; }
                enter = Math.Max(enter, t0);
                exit = Math.Min(exit, t1);
            }
            return exit > enter;
        }

        static double Component(Vector3 v, int axis) => axis == 0 ? v.X : axis == 1 ? v.Y : v.Z;
    }
}
