using System;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Fills spawn boxes with particles on a regular lattice that fills the box exactly: n_a points along each box
    /// axis a, spaced L_a / n_a, so the outermost particles sit half a (per-axis) spacing inside each face and two
    /// boxes that touch continue the lattice without a gap. Each point is moved by a small deterministic jitter drawn
    /// from the box's seed and kept inside the box, then the fluid is lowered into hydrostatic equilibrium
    /// (<see cref="HydrostaticSpawn"/>).
    /// </summary>
    /// <remarks>
    /// Why the lattice fills the box rather than keeping the spacing s exactly: with floor(L / s) points per axis at
    /// spacing s, a box lost up to a spacing of fluid per axis, a different fraction at every resolution (6 % of the
    /// mass at four times the particles), and two stacked boxes opened a gap of up to a spacing between them. Filling
    /// the box makes each particle stand for the cell volume V / N of its box, and the derived particle mass
    /// (<see cref="DerivedParticleMass"/>) is rest density times that cell, so a box carries rest density times its
    /// own volume at any spacing. The counts per axis are floor or ceil of L / s, whichever combination brings the
    /// cell closest to s^3: the lattice then stays nearly cubic and boxes of one phase share nearly the same cell.
    /// </remarks>
    public static class SpawnLayout
    {
        /// <summary>The declared bound of <see cref="FluidBlock.Jitter"/>: the lattice clamps to it as the
        /// validation refuses beyond it.</summary>
        static readonly float MaxJitter = (float)SettingRules.Of(typeof(FluidBlock), nameof(FluidBlock.Jitter)).Max;

        /// <summary>The particles' extent along gravity plus one spacing, m (the half spacing above and below the outer
        /// particles); without gravity their largest extent. The depth the Chebyshev solve is tuned for
        /// (<see cref="ChebyshevBounds"/>) and the height of DFSPH's gravity wave (<see cref="TimeStepController.GravityWaveSpeed"/>).</summary>
        public static double Depth(Particle[] particles, Vector3 gravity, double spacing)
        {
            if (particles.Length == 0) return spacing;
            bool down = gravity.LengthSquared() > 0f;
            Vector3 up = down ? -Vector3.Normalize(gravity) : Vector3.Zero;
            Vector3 lo = new Vector3(float.MaxValue), hi = new Vector3(float.MinValue);
            float top = float.MinValue, bottom = float.MaxValue;
            foreach (var p in particles)
            {
                lo = Vector3.Min(lo, p.Position);
                hi = Vector3.Max(hi, p.Position);
                float height = Vector3.Dot(p.Position, up);
                top = Math.Max(top, height);
                bottom = Math.Min(bottom, height);
            }
            Vector3 extent = hi - lo;
            double depth = down ? top - bottom : Math.Max(extent.X, Math.Max(extent.Y, extent.Z));
            return depth + spacing;
        }

        /// <summary>Lattice points along each box axis: floor or ceil of Size / s per axis, the combination whose cell
        /// volume V / (nx ny nz) is closest to s^3 (an exact multiple of s, within rounding, keeps Size / s).</summary>
        public static void CountPerAxis(FluidSettings settings, FluidBlock box, out int nx, out int ny, out int nz)
        {
            nx = ny = nz = 0;
            double s = settings.ParticleSpacing;
            var size = box.Size;
            if (!(s > 0) || !(size.X > 0f) || !(size.Y > 0f) || !(size.Z > 0f)) return;
            double qx = size.X / s, qy = size.Y / s, qz = size.Z / s;
            if (!(qx < int.MaxValue && qy < int.MaxValue && qz < int.MaxValue)) return;
            double best = double.PositiveInfinity;
            foreach (int cx in Candidates(qx))
            foreach (int cy in Candidates(qy))
            foreach (int cz in Candidates(qz))
            {
                // Volume mismatch first; among equal ones the least stretched lattice.
                double volume = Math.Abs(Math.Log((double)cx * cy * cz / (qx * qy * qz)));
                double stretch = Math.Abs(Math.Log(cx / qx)) + Math.Abs(Math.Log(cy / qy)) + Math.Abs(Math.Log(cz / qz));
                double cost = volume + 1e-6 * stretch;
                if (cost >= best) continue;
                best = cost;
                nx = cx; ny = cy; nz = cz;
            }
        }

        /// <summary>floor(q) and ceil(q), at least 1; q alone when it is a whole number within rounding (0.2 / 0.02 = 10).</summary>
        static int[] Candidates(double q)
        {
            double nearest = Math.Round(q);
            if (Math.Abs(q - nearest) < 1e-4) return new[] { Math.Max(1, (int)nearest) };
            int low = (int)Math.Floor(q);
            return low < 1 ? new[] { 1 } : new[] { low, low + 1 };
        }

        /// <summary>Volume each particle of this box stands for, m^3: the box volume over its lattice count (0 for an empty box).</summary>
        public static double CellVolume(FluidSettings settings, FluidBlock box)
        {
            long count = Count(settings, box);
            return count > 0 ? (double)box.Size.X * box.Size.Y * box.Size.Z / count : 0.0;
        }

        /// <summary>Lattice points of this box: the particles it spawns unless a sphere obstacle displaces some
        /// (<see cref="SpawnedCount"/>). Its particles' mass and volume go with this count (<see cref="CellVolume"/>).</summary>
        public static long Count(FluidSettings settings, FluidBlock box)
        {
            CountPerAxis(settings, box, out int nx, out int ny, out int nz);
            return (long)nx * ny * nz;
        }

        /// <summary>Particles this box of <paramref name="scene"/> spawns: its lattice points less those inside a sphere
        /// obstacle (<see cref="Generate(FluidSceneDescription)"/>).</summary>
        /// <remarks>Only the lattice points near a sphere are tested, so the cost goes with the spheres' volume in points,
        /// not the box's (the inspector counts at every event). Each is the walk's own point (<see cref="BoxLattice.Point"/>),
        /// so the count is the walk's to the point.</remarks>
        public static long SpawnedCount(FluidSceneDescription scene, FluidBlock box)
        {
            long count = Count(scene.Settings, box);
            if (scene.Obstacles == null || scene.Obstacles.Count == 0 || count == 0) return count;
            var lattice = new BoxLattice(scene.Settings, box);
            float margin = 0.5f * scene.Settings.ParticleSpacing;
            var near = new LatticeRange[scene.Obstacles.Count];
            for (int m = 0; m < near.Length; m++)
            {
                near[m] = lattice.Near(scene.Obstacles[m], margin);
                // A point near two spheres is counted out once: with the first whose range holds it.
                for (int k = near[m].K0; k <= near[m].K1; k++)
                for (int j = near[m].J0; j <= near[m].J1; j++)
                for (int i = near[m].I0; i <= near[m].I1; i++)
                {
                    bool earlier = false;
                    for (int e = 0; e < m && !earlier; e++) earlier = near[e].Holds(i, j, k);
                    if (!earlier && InsideObstacle(scene, lattice.Point(i, j, k), margin)) count--;
                }
            }
            return count;
        }

        /// <summary>Whether any box of <paramref name="scene"/> (valid but for this) spawns a particle: false only where sphere
        /// obstacles cover every lattice point. Stops at the first point spawned.</summary>
        public static bool SpawnsAny(FluidSceneDescription scene)
        {
            foreach (var box in scene.SpawnBoxes)
                foreach (var _ in Positions(scene, box))
                    return true;
            return false;
        }

        /// <summary>Particles the whole scene spawns.</summary>
        public static int TotalCount(FluidSceneDescription scene)
        {
            long total = 0;
            foreach (var box in scene.SpawnBoxes) total += SpawnedCount(scene, box);
            return (int)Math.Min(total, int.MaxValue);
        }

        /// <summary>All particles of the scene, box after box, ids 0..N-1 in that order. Lattice points that fall
        /// inside a sphere obstacle (closer than half a spacing to its surface) are not spawned: the sphere
        /// displaces that fluid, as it would if it were lowered into it, instead of overlapping its boundary particles.
        /// Throws <see cref="ArgumentException"/> with every validation message if the scene is invalid.</summary>
        public static Particle[] Generate(FluidSceneDescription scene) => Generate(scene, out _);

        /// <summary>As <see cref="Generate(FluidSceneDescription)"/>, with the hydrostatic pressure each particle was spawned
        /// under, Pa, by particle id (<see cref="HydrostaticSpawn"/>).</summary>
        public static Particle[] Generate(FluidSceneDescription scene, out double[] pressures)
        {
            scene.ThrowIfInvalid();
            var particles = new Particle[TotalCount(scene)];
            var phases = scene.Phases();
            int next = 0;
            foreach (var box in scene.SpawnBoxes)
            {
                uint phase = (uint)IndexOf(phases, box.Phase.Name);
                next = Fill(scene, box, phase, particles, next);
            }
            if (next < particles.Length) Array.Resize(ref particles, next);
            pressures = new double[particles.Length];
            HydrostaticSpawn.Apply(scene, particles, pressures);
            return particles;
        }

        static int IndexOf(System.Collections.Generic.IReadOnlyList<PhaseDescription> phases, string name)
        {
            for (int i = 0; i < phases.Count; i++)
                if (phases[i].Name == name) return i;
            return -1;
        }

        static int Fill(FluidSceneDescription scene, FluidBlock box, uint phase, Particle[] particles, int next)
        {
            foreach (var position in Positions(scene, box))
            {
                particles[next] = new Particle(position, box.InitialVelocity, phase, (uint)next);
                next++;
            }
            return next;
        }

        /// <summary>The box's particle positions in spawn order, before the hydrostatic lowering: its lattice, jittered,
        /// without the points inside a sphere obstacle.</summary>
        static System.Collections.Generic.IEnumerable<Vector3> Positions(FluidSceneDescription scene, FluidBlock box)
        {
            var lattice = new BoxLattice(scene.Settings, box);
            float margin = 0.5f * scene.Settings.ParticleSpacing;
            for (int k = 0; k < lattice.Nz; k++)
            for (int j = 0; j < lattice.Ny; j++)
            for (int i = 0; i < lattice.Nx; i++)
            {
                var position = lattice.Point(i, j, k);
                if (!InsideObstacle(scene, position, margin)) yield return position;
            }
        }

        static bool InsideObstacle(FluidSceneDescription scene, Vector3 position, float margin)
        {
            if (scene.Obstacles == null) return false;
            foreach (var o in scene.Obstacles)
                if (Vector3.Distance(position, o.Center) < o.Radius + margin) return true;
            return false;
        }

        /// <summary>One box's spawn lattice: point (i, j, k) at its place in the box, jittered by draws that depend on the
        /// point alone, so that any point can be made without the ones before it.</summary>
        readonly struct BoxLattice
        {
            public readonly int Nx, Ny, Nz;
            readonly Vector3 _center, _half, _step;
            readonly Quaternion _rotation;
            readonly float _jitter;
            readonly ulong _seed;

            public BoxLattice(FluidSettings settings, FluidBlock box)
            {
                CountPerAxis(settings, box, out Nx, out Ny, out Nz);
                _center = box.Center;
                _half = box.Size * 0.5f;
                _step = new Vector3(box.Size.X / Nx, box.Size.Y / Ny, box.Size.Z / Nz);
                _rotation = Quaternion.Normalize(box.Rotation);
                _jitter = Math.Max(0f, Math.Min(MaxJitter, box.Jitter)) * settings.ParticleSpacing;
                _seed = unchecked((ulong)(uint)box.Seed * 0x9E3779B97F4A7C15UL + 0x632BE59BD9B4E019UL);
            }

            /// <summary>The point in the box's frame before its jitter.</summary>
            Vector3 Local(int i, int j, int k) =>
                new Vector3((i - 0.5f * (Nx - 1)) * _step.X, (j - 0.5f * (Ny - 1)) * _step.Y, (k - 0.5f * (Nz - 1)) * _step.Z);

            public Vector3 Point(int i, int j, int k)
            {
                var local = Local(i, j, k);
                if (_jitter > 0f)
                {
                    // Three draws a point, x, y, z, in the lattice's order: the sequence a SplitMix64 stream gives.
                    ulong first = 3UL * (ulong)(i + (long)Nx * (j + (long)Ny * k));
                    local += new Vector3(Draw(first), Draw(first + 1), Draw(first + 2)) * _jitter;
                    local = Vector3.Clamp(local, -_half, _half);
                }
                return _center + Vector3.Transform(local, _rotation);
            }

            /// <summary>The lattice points that may lie within <paramref name="margin"/> of <paramref name="sphere"/>: those
            /// whose unjittered place is within its radius, the margin and the largest jitter on every box axis (the
            /// clamp only draws a point back towards its place), one more each side against rounding.</summary>
            public LatticeRange Near(RigidSphere sphere, float margin)
            {
                var c = Vector3.Transform(sphere.Center - _center, Quaternion.Conjugate(_rotation));
                double reach = (double)sphere.Radius + margin + 1.7321 * _jitter;
                Axis(c.X, reach, _step.X, Nx, out int i0, out int i1);
                Axis(c.Y, reach, _step.Y, Ny, out int j0, out int j1);
                Axis(c.Z, reach, _step.Z, Nz, out int k0, out int k1);
                return new LatticeRange(i0, i1, j0, j1, k0, k1);
            }

            /// <summary>Indices along one axis whose place lies within <paramref name="reach"/> of <paramref name="c"/>,
            /// clipped to [0, n - 1] (empty when first &gt; last); every index where a bound is not a number.</summary>
            static void Axis(double c, double reach, double step, int n, out int first, out int last)
            {
                double middle = 0.5 * (n - 1);
                double lo = Math.Floor((c - reach) / step + middle) - 1, hi = Math.Ceiling((c + reach) / step + middle) + 1;
                if (double.IsNaN(lo) || double.IsNaN(hi)) { first = 0; last = n - 1; return; }
                first = (int)Math.Max(0, Math.Min(n, lo));
                last = (int)Math.Max(-1, Math.Min(n - 1, hi));
            }

            /// <summary>Draw <paramref name="n"/> of the box's stream, uniform in [-1, 1): SplitMix64 (Steele, Lea and Flood,
            /// "Fast splittable pseudorandom number generators", 2014), whose n-th value depends on n alone; identical on
            /// every runtime, unlike System.Random.</summary>
            float Draw(ulong n)
            {
                unchecked
                {
                    ulong z = _seed + (n + 1) * 0x9E3779B97F4A7C15UL;
                    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
                    z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
                    z ^= z >> 31;
                    return (float)((z >> 40) * (1.0 / (1UL << 24)) * 2.0 - 1.0);
                }
            }
        }

        /// <summary>A block of lattice indices, bounds included.</summary>
        readonly struct LatticeRange
        {
            public readonly int I0, I1, J0, J1, K0, K1;

            public LatticeRange(int i0, int i1, int j0, int j1, int k0, int k1)
            {
                I0 = i0; I1 = i1; J0 = j0; J1 = j1; K0 = k0; K1 = k1;
            }

            public bool Holds(int i, int j, int k) => i >= I0 && i <= I1 && j >= J0 && j <= J1 && k >= K0 && k <= K1;
        }
    }
}
