using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>A box filled with one phase on a regular lattice at start (and on reset). Boxes may touch but not
    /// overlap (<see cref="SpawnOverlapRule"/>).</summary>
    public sealed class SpawnBoxDescription
    {
        public const float MaxJitter = 0.5f;

        public string Name { get; set; } = "SpawnBox";

        public PhaseDescription Phase { get; set; } = new PhaseDescription();

        /// <summary>World-space centre, m.</summary>
        public Vector3 Center { get; set; }

        public Quaternion Rotation { get; set; } = Quaternion.Identity;

        /// <summary>Edge lengths, m; each at least one particle spacing.</summary>
        public Vector3 Size { get; set; } = new Vector3(0.2f, 0.2f, 0.2f);

        /// <summary>World-space velocity every particle starts with, m/s; with the scene's other speeds, below the
        /// speed of sound (<see cref="SpeedOfSoundRule"/>).</summary>
        public Vector3 InitialVelocity { get; set; }

        /// <summary>Random offset of each lattice point, as a fraction of the spacing, in [0, 0.5].</summary>
        public float Jitter { get; set; } = 0.05f;

        /// <summary>Seed of the deterministic jitter: same seed, same particles.</summary>
        public int Seed { get; set; } = 1;

        public SpawnBoxDescription() { }

        public SpawnBoxDescription(string name, PhaseDescription phase, Vector3 center, Vector3 size)
        {
            Name = name;
            Phase = phase;
            Center = center;
            Size = size;
        }

        public override string ToString() => $"SpawnBox '{Name}' ({Phase?.Name}) at {Center} size {Size}";
    }
}
