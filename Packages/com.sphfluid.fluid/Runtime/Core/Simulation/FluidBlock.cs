using System;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// A block of fluid: a box filled with one phase on a regular lattice at start (and on reset), what a SpawnBox
    /// component describes to the engine-free core. Boxes may touch but not overlap
    /// (<see cref="SpawnOverlapRule"/>). The spawn values and the <see cref="Phase"/> block are declared once
    /// (<see cref="SettingAttribute"/>) and serialized by Unity inside the SpawnBox component; the placement (name, centre,
    /// rotation, size) is not a setting: Unity and the headless reader take it from the box's GameObject and Transform.
    /// </summary>
    [Serializable]
    public sealed class FluidBlock
    {
        const string Spawn = "Spawn";

        /// <summary>The liquid this box holds: a declared block, listed by the inspector, the scene reader and the README
        /// under "Phase." (<see cref="SettingRules.DeclaredPaths"/>).</summary>
        public PhaseDescription Phase = new PhaseDescription();

        // SpeedOfSoundRule narrows it for the scene.
        [Setting(Spawn, 0, 1000, "m/s", "Velocity every particle starts with, world space. With WCSPH it must stay below the speed of sound, with the scene's other speeds.")]
        public SettingVector InitialVelocity;

        [Setting(Spawn, 0, 0.5, "particle spacings", "Random offset of each lattice point, as a fraction of the spacing.")]
        public float Jitter = 0.05f;

        [Setting(Spawn, int.MinValue, int.MaxValue, "", "Seed of the deterministic jitter: the same seed spawns the same particles.")]
        public int Seed = 1;

        public string Name { get; set; } = "SpawnBox";

        /// <summary>World-space centre, m.</summary>
        public Vector3 Center { get; set; }

        public Quaternion Rotation { get; set; } = Quaternion.Identity;

        /// <summary>Edge lengths, m; each at least one particle spacing.</summary>
        public Vector3 Size { get; set; } = new Vector3(0.2f, 0.2f, 0.2f);

        public FluidBlock() { }

        public FluidBlock(string name, PhaseDescription phase, Vector3 center, Vector3 size)
        {
            Name = name;
            Phase = phase;
            Center = center;
            Size = size;
        }

        /// <summary>A copy whose phase is a copy too, so that editing one does not edit the other.</summary>
        public FluidBlock Clone()
        {
            var copy = (FluidBlock)MemberwiseClone();
            copy.Phase = Phase?.Clone();
            return copy;
        }

        public override string ToString() => $"SpawnBox '{Name}' ({Phase?.Name}) at {Center} size {Size}";
    }
}
