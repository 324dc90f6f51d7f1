using System;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Fills spawn boxes with particles on a regular lattice of spacing s, centred in the box (so the
    /// outermost particles sit s/2 inside each face and adjacent boxes continue the lattice seamlessly),
    /// each moved by a small deterministic jitter drawn from the box's seed and kept inside the box, then
    /// lowered into hydrostatic equilibrium (<see cref="HydrostaticSpawn"/>).
    /// </summary>
    public static class SpawnLayout
    {
        /// <summary>Lattice points along each box axis: floor(Size / s), tolerant of rounding (0.2 / 0.02 = 10).</summary>
        public static void CountPerAxis(FluidSettings settings, SpawnBoxDescription box, out int nx, out int ny, out int nz)
        {
            float s = settings.ParticleSpacing;
            nx = AxisCount(box.Size.X, s);
            ny = AxisCount(box.Size.Y, s);
            nz = AxisCount(box.Size.Z, s);
        }

        static int AxisCount(float size, float spacing)
        {
            if (!(spacing > 0f) || !(size > 0f)) return 0;
            return (int)Math.Floor(size / (double)spacing + 1e-4);
        }

        /// <summary>Particles this box spawns.</summary>
        public static long Count(FluidSettings settings, SpawnBoxDescription box)
        {
            CountPerAxis(settings, box, out int nx, out int ny, out int nz);
            return (long)nx * ny * nz;
        }

        /// <summary>Particles the whole scene spawns.</summary>
        public static int TotalCount(FluidSceneDescription scene)
        {
            long total = 0;
            foreach (var box in scene.SpawnBoxes) total += Count(scene.Settings, box);
            return (int)Math.Min(total, int.MaxValue);
        }

        /// <summary>All particles of the scene, box after box, ids 0..N-1 in that order. Lattice points that fall
        /// inside a sphere obstacle (closer than half a spacing to its surface) are not spawned: the sphere
        /// displaces that fluid, as it would if it were lowered into it, instead of overlapping its boundary particles.
        /// Throws <see cref="ArgumentException"/> with every validation message if the scene is invalid.</summary>
        public static Particle[] Generate(FluidSceneDescription scene)
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
            HydrostaticSpawn.Apply(scene, particles);
            return particles;
        }

        static int IndexOf(System.Collections.Generic.IReadOnlyList<PhaseDescription> phases, string name)
        {
            for (int i = 0; i < phases.Count; i++)
                if (phases[i].Name == name) return i;
            return -1;
        }

        static int Fill(FluidSceneDescription scene, SpawnBoxDescription box, uint phase, Particle[] particles, int next)
        {
            var settings = scene.Settings;
            CountPerAxis(settings, box, out int nx, out int ny, out int nz);
            float s = settings.ParticleSpacing;
            var half = box.Size * 0.5f;
            var rotation = Quaternion.Normalize(box.Rotation);
            float jitter = Math.Max(0f, Math.Min(SpawnBoxDescription.MaxJitter, box.Jitter)) * s;
            var random = new SplitMix64(unchecked((ulong)(uint)box.Seed * 0x9E3779B97F4A7C15UL + 0x632BE59BD9B4E019UL));
            for (int k = 0; k < nz; k++)
            for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++)
            {
                var local = new Vector3((i - 0.5f * (nx - 1)) * s, (j - 0.5f * (ny - 1)) * s, (k - 0.5f * (nz - 1)) * s);
                if (jitter > 0f)
                {
                    local += new Vector3(random.NextSigned(), random.NextSigned(), random.NextSigned()) * jitter;
                    local = Vector3.Clamp(local, -half, half);
                }
                var position = box.Center + Vector3.Transform(local, rotation);
                if (InsideObstacle(scene, position, 0.5f * s)) continue;
                particles[next] = new Particle(position, box.InitialVelocity, phase, (uint)next);
                next++;
            }
            return next;
        }

        static bool InsideObstacle(FluidSceneDescription scene, Vector3 position, float margin)
        {
            if (scene.Obstacles == null) return false;
            foreach (var o in scene.Obstacles)
                if (Vector3.Distance(position, o.Center) < o.Radius + margin) return true;
            return false;
        }

        /// <summary>SplitMix64 (Steele et al. 2014): tiny, and identical on every runtime, unlike System.Random.</summary>
        struct SplitMix64
        {
            ulong _state;

            public SplitMix64(ulong seed) { _state = seed; }

            ulong Next()
            {
                unchecked
                {
                    ulong z = _state += 0x9E3779B97F4A7C15UL;
                    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
                    z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
                    return z ^ (z >> 31);
                }
            }

            /// <summary>Uniform in [-1, 1).</summary>
            public float NextSigned() => (float)((Next() >> 40) * (1.0 / (1UL << 24)) * 2.0 - 1.0);
        }
    }
}
