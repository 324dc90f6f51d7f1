using System;
using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Everything the solver needs to know about a scene, engine-free: settings, spawn boxes (and
    /// through them the phases), the container and the sphere obstacles. Unity components and the
    /// headless scene reader both build one of these.
    /// </summary>
    public sealed class FluidSceneDescription
    {
        public const int MaxPhases = 64;
        public const int MaxObstacles = 64;

        /// <summary>How far from 1 the length of the container's and each spawn box's rotation may be. Unity writes unit
        /// quaternions; a far longer or shorter one is a damaged scene, not a rotation.</summary>
        public const float RotationLengthTolerance = 0.01f;

        /// <summary>The lengths <see cref="RotationLengthTolerance"/> allows, as messages write them: "[0.99, 1.01]".</summary>
        public static string RotationLengthRange =>
            $"[{ValidationRules.Format(1f - RotationLengthTolerance)}, {ValidationRules.Format(1f + RotationLengthTolerance)}]";

        /// <summary>Most boundary particles (walls and obstacles): the particle sort's limit.</summary>
        public const int MaxBoundaryParticles = SphFluid.Sorting.ParticleSorter.MaxSupportedParticles;

        public FluidSettings Settings { get; set; } = new FluidSettings();
        public List<FluidBlock> SpawnBoxes { get; set; } = new List<FluidBlock>();
        public ContainerDescription Container { get; set; } = new ContainerDescription();
        public List<RigidSphere> Obstacles { get; set; } = new List<RigidSphere>();

        /// <summary>The distinct phases in order of first appearance among the spawn boxes (the phase-table order).</summary>
        public IReadOnlyList<PhaseDescription> Phases()
        {
            var phases = new List<PhaseDescription>();
            foreach (var box in SpawnBoxes)
            {
                if (box?.Phase == null) continue;
                if (IndexOf(phases, box.Phase.Name) < 0) phases.Add(box.Phase);
            }
            return phases;
        }

        /// <summary>Row of the phase table for a phase name, or -1.</summary>
        public int PhaseIndex(string phaseName) => IndexOf(Phases(), phaseName);

        static int IndexOf(IReadOnlyList<PhaseDescription> phases, string name)
        {
            for (int i = 0; i < phases.Count; i++)
                if (phases[i].Name == name) return i;
            return -1;
        }

        /// <summary>Number density delta0 of an interior particle of the spawn lattice.</summary>
        public double RestNumberDensity() =>
            SmoothingKernels.LatticeNumberDensity(Settings.SmoothingKernel, Settings.ParticleSpacing, Settings.SmoothingRadius);

        /// <summary>The GPU phase table: one row per distinct phase name, masses derived where 0 (<see cref="DerivedParticleMass"/>).</summary>
        public PhaseProperties[] BuildPhaseTable()
        {
            var phases = Phases();
            var table = new PhaseProperties[phases.Count];
            double latticeNumberDensity = RestNumberDensity();
            for (int i = 0; i < phases.Count; i++)
            {
                var p = phases[i];
                double mass = p.ParticleMass > 0f ? p.ParticleMass : DerivedParticleMass.Of(this, p);
                table[i] = new PhaseProperties
                {
                    RestDensity = p.RestDensity,
                    Viscosity = p.Viscosity,
                    ParticleMass = (float)mass,
                    WallWeightScale = (float)(p.RestDensity / mass / latticeNumberDensity),
                    SurfaceTension = p.SurfaceTension,
                    Color = p.Color, // linear, as declared
                    FresnelF0 = p.FresnelF0,
                    Absorption = p.Absorption,
                };
            }
            return table;
        }

        /// <summary>Every refused value of the scene; empty when it can be simulated.</summary>
        public IReadOnlyList<ValidationError> Validate()
        {
            var errors = new List<ValidationError>();
            if (Settings == null)
            {
                errors.Add(new ValidationError("Settings", "FluidScene", "Settings must be set (was null)"));
                return errors;
            }
            Settings.Validate(errors, "Settings.");
            bool settingsOk = errors.Count == 0;

            int beforeContainer = errors.Count;
            ValidateContainer(errors, settingsOk);
            // A box is placed against the container's position, rotation and size: where one of those is refused, "the box
            // must lie inside" would only repeat it.
            bool containerPlaced = true;
            for (int i = beforeContainer; i < errors.Count; i++)
                if (errors[i].Field is "Container" or "Container.Position" or "Container.Rotation" or "Container.Size") containerPlaced = false;
            ValidateBoxes(errors, settingsOk, containerPlaced);
            ValidateObstacles(errors);
            if (errors.Count > 0) return errors;
            SpawnOverlapRule.Validate(this, errors);
            // A sphere displaces the lattice points it covers (SpawnLayout); spheres that cover them all leave nothing to
            // simulate. The largest is named as the field to change (a radius typed as 50 instead of 0.5), every one in the text.
            if (Obstacles != null && Obstacles.Count > 0 && !SpawnLayout.SpawnsAny(this))
            {
                int largest = 0;
                for (int i = 1; i < Obstacles.Count; i++)
                    if (Obstacles[i].Radius > Obstacles[largest].Radius) largest = i;
                errors.Add(new ValidationError(ObstaclePath(largest) + nameof(RigidSphere.Radius),
                    ObstacleOwner(Obstacles[largest]), $"the sphere obstacles ({SphereList()}) cover every lattice point of the spawn boxes (each point within half a spacing of a sphere is left out), so the scene would spawn no particle; the total must be in [1, {Settings.MaxParticles}]: shrink or move the spheres or the boxes"));
            }
            // The Tait speed of sound only bounds the weakly compressible solver; DFSPH keeps the density by its solves.
            if (Settings.PressureSolver == PressureSolver.Wcsph)
                SpeedOfSoundRule.Validate(this, errors);
            return errors;
        }

        /// <summary>Largest extent of the container along any of its axes, m.</summary>
        public const float MaxContainerSize = 1000f;

        /// <summary>Whether every component of <paramref name="size"/> lies in the container's own range, [two particle
        /// spacings, <see cref="MaxContainerSize"/>] m, before its wall particles are counted.</summary>
        public static bool ContainerSizeInRange(Vector3 size, float particleSpacing)
        {
            float least = 2f * particleSpacing;
            return ValidationRules.IsFinite(size.X) && ValidationRules.IsFinite(size.Y) && ValidationRules.IsFinite(size.Z)
                && size.X >= least && size.Y >= least && size.Z >= least
                && size.X <= MaxContainerSize && size.Y <= MaxContainerSize && size.Z <= MaxContainerSize;
        }

        /// <summary>The container's own rules; its least size and wall count follow from the spacing, so they are checked only
        /// with <paramref name="settingsOk"/> (a refused spacing would name a range such as [2E+30, 1000] m here too).</summary>
        internal void ValidateContainer(List<ValidationError> errors, bool settingsOk = true)
        {
            const string owner = "Container";
            if (Container == null)
            {
                errors.Add(new ValidationError("Container", "FluidScene", "Container must be set (was null)"));
                return;
            }
            ValidationRules.Finite(errors, owner, "Container.", nameof(ContainerDescription.Position), Container.Position, 1e6f, "m");
            ValidationRules.Rotation(errors, owner, "Container.", nameof(ContainerDescription.Rotation), Container.Rotation);
            float spacing = settingsOk ? Settings.ParticleSpacing : 0f;
            var size = Container.Size;
            if (!ContainerSizeInRange(size, spacing))
            {
                errors.Add(new ValidationError("Container.Size", "Container", $"each Size component must be in [{ValidationRules.Format(2f * spacing)}, " +
                    $"{ValidationRules.Format(MaxContainerSize)}] m (two particle spacings or more) (was {ValidationRules.Format(size)})"));
            }
            else if (settingsOk)
            {
                long walls = BoundarySampling.ContainerCount(size, Settings.ParticleSpacing, Settings.SmoothingRadius);
                if (walls > MaxBoundaryParticles)
                    errors.Add(new ValidationError("Container.Size",
                        "Container", $"Size {ValidationRules.Format(size)} m needs {walls} wall particles at spacing {ValidationRules.Format(Settings.ParticleSpacing)} m, more than the {MaxBoundaryParticles} allowed; shrink the container or raise ParticleSpacing"));
            }
            if (Container.Friction != WallFriction.Slip && Container.Friction != WallFriction.NoSlip)
                errors.Add(new ValidationError("Container.Friction", "Container", $"Friction must be one of {SettingRules.EnumValues(typeof(WallFriction))} (was {(int)Container.Friction})"));
            ValidationRules.Finite(errors, owner, "Container.", nameof(ContainerDescription.Velocity), Container.Velocity, 1000f, "m/s");
            ValidationRules.Finite(errors, owner, "Container.", nameof(ContainerDescription.AngularVelocity), Container.AngularVelocity, 1000f, "rad/s");
        }

        void ValidateBoxes(List<ValidationError> errors, bool settingsOk, bool containerPlaced)
        {
            if (SpawnBoxes == null || SpawnBoxes.Count == 0)
            {
                errors.Add(new ValidationError("SpawnBoxes", "FluidScene", "SpawnBoxes must hold at least one box (was 0)"));
                return;
            }
            var firstOfPhase = new Dictionary<string, FluidBlock>();
            // Phase names become diagnostics columns and inspector rows, where "Water" and "water" would read as one
            // phase twice; names must differ by more than letter case.
            var firstOfFoldedName = new Dictionary<string, FluidBlock>(StringComparer.OrdinalIgnoreCase);
            long total = 0;
            for (int b = 0; b < SpawnBoxes.Count; b++)
            {
                var box = SpawnBoxes[b];
                string path = $"SpawnBoxes[{b}].";
                if (box == null)
                {
                    errors.Add(new ValidationError($"SpawnBoxes[{b}]", "FluidScene", $"SpawnBoxes[{b}] must be set (was null)"));
                    continue;
                }
                string owner = $"SpawnBox '{box.Name}'";
                int before = errors.Count;
                ValidatePhase(errors, owner, path + "Phase.", box.Phase);
                if (box.Phase != null && !string.IsNullOrEmpty(box.Phase.Name))
                {
                    if (firstOfPhase.TryGetValue(box.Phase.Name, out var first))
                    {
                        if (!first.Phase.SameDefinition(box.Phase))
                            errors.Add(new ValidationError(path + "Phase",
                                owner, $"phase '{box.Phase.Name}' is defined differently in SpawnBox '{first.Name}' and SpawnBox '{box.Name}', which differ in " +
                                $"{string.Join(", ", first.Phase.DifferencesFrom(box.Phase))}; boxes of one phase must agree"));
                    }
                    else firstOfPhase.Add(box.Phase.Name, box);
                    if (firstOfFoldedName.TryGetValue(box.Phase.Name, out var folded))
                    {
                        if (folded.Phase.Name != box.Phase.Name)
                            errors.Add(new ValidationError(path + "Phase.Name",
                                owner, $"phase name '{box.Phase.Name}' differs from phase '{folded.Phase.Name}' of SpawnBox '{folded.Name}' only by letter case; phase names must differ by more than case (use the same name for the same liquid)"));
                    }
                    else firstOfFoldedName.Add(box.Phase.Name, box);
                }
                ValidationRules.Finite(errors, owner, path, nameof(FluidBlock.Center), box.Center, 1e6f, "m");
                ValidationRules.Rotation(errors, owner, path, nameof(FluidBlock.Rotation), box.Rotation);
                SettingRules.ValidateAll(box, errors, owner, path);
                if (!settingsOk) continue;

                float s = Settings.ParticleSpacing;
                var size = box.Size;
                bool sizeOk = ValidationRules.IsFinite(size.X) && ValidationRules.IsFinite(size.Y) && ValidationRules.IsFinite(size.Z)
                    && size.X >= s && size.Y >= s && size.Z >= s && size.X <= 1000f && size.Y <= 1000f && size.Z <= 1000f;
                if (!sizeOk)
                {
                    errors.Add(new ValidationError(path + "Size",
                        owner, $"each Size component must be in [{ValidationRules.Format(s)}, 1000] m (one particle spacing or more) (was {ValidationRules.Format(size)})"));
                    continue;
                }
                total += SpawnLayout.Count(Settings, box);
                if (containerPlaced && errors.Count == before && !BoxInsideContainer(box, out Vector3 corner))
                {
                    errors.Add(new ValidationError(path + "Center",
                        owner, $"the box (centre {ValidationRules.Format(box.Center)}, size {ValidationRules.Format(box.Size)} m) must lie inside the container " +
                        $"(centre {ValidationRules.Format(Container.Position)}, size {ValidationRules.Format(Container.Size)} m); its corner {ValidationRules.Format(corner)} is outside"));
                }
                if (errors.Count == before) ParticleMassRule.Validate(this, box.Phase, owner, path + "Phase.", errors);
            }
            if (firstOfPhase.Count > MaxPhases)
                errors.Add(new ValidationError("SpawnBoxes", "FluidScene", $"the number of phases must be in [1, {MaxPhases}] (was {firstOfPhase.Count})"));
            if (settingsOk && total > Settings.MaxParticles)
                errors.Add(new ValidationError("Settings.MaxParticles",
                    "FluidScene", $"the spawn boxes hold {total} particles; the total must be in [1, {Settings.MaxParticles}] (Settings.MaxParticles)"));
        }

        static void ValidatePhase(List<ValidationError> errors, string owner, string path, PhaseDescription phase)
        {
            if (phase == null)
            {
                errors.Add(new ValidationError(path.TrimEnd('.'), owner, $"Phase must be set (was null)"));
                return;
            }
            SettingRules.ValidateAll(phase, errors, owner, path);
        }

        void ValidateObstacles(List<ValidationError> errors)
        {
            if (Obstacles == null) return;
            if (Obstacles.Count > MaxObstacles)
                errors.Add(new ValidationError("Obstacles", "FluidScene", $"the number of obstacles must be in [0, {MaxObstacles}] (was {Obstacles.Count})"));
            for (int i = 0; i < Obstacles.Count; i++)
            {
                var o = Obstacles[i];
                string path = ObstaclePath(i);
                if (o == null)
                {
                    errors.Add(new ValidationError($"Obstacles[{i}]", "FluidScene", $"Obstacles[{i}] must be set (was null)"));
                    continue;
                }
                ValidateObstacle(errors, o, ObstacleOwner(o), path);
            }
        }

        /// <summary>The rules of one sphere; <paramref name="owner"/> and <paramref name="path"/> name it in the messages
        /// (FluidSimulation keeps them, so that a sphere driven every frame is checked without making strings).</summary>
        internal static void ValidateObstacle(List<ValidationError> errors, RigidSphere o, string owner, string path)
        {
            ValidationRules.Finite(errors, owner, path, nameof(RigidSphere.Center), o.Center, 1e6f, "m");
            ValidationRules.Positive(errors, owner, path, nameof(RigidSphere.Radius), o.Radius, 1000f, "m");
            ValidationRules.Finite(errors, owner, path, nameof(RigidSphere.Velocity), o.Velocity, 1000f, "m/s");
        }

        internal static string ObstacleOwner(RigidSphere o) => $"Sphere '{o.Name}'";

        string SphereList()
        {
            var spheres = new List<string>();
            foreach (var o in Obstacles)
                spheres.Add($"'{o.Name}' of world radius {ValidationRules.Format(o.Radius)} m at {ValidationRules.Format(o.Center)}");
            return string.Join("; ", spheres);
        }

        internal static string ObstaclePath(int index) => $"Obstacles[{index}].";

        bool BoxInsideContainer(FluidBlock box, out Vector3 outsideCorner)
        {
            var half = box.Size * 0.5f;
            var containerHalf = Container.Size * 0.5f;
            float tolerance = 1e-4f * Settings.ParticleSpacing + 1e-6f;
            var rotation = Quaternion.Normalize(box.Rotation);
            for (int c = 0; c < 8; c++)
            {
                var local = new Vector3((c & 1) != 0 ? half.X : -half.X, (c & 2) != 0 ? half.Y : -half.Y, (c & 4) != 0 ? half.Z : -half.Z);
                var world = box.Center + Vector3.Transform(local, rotation);
                var q = Container.ToLocal(world);
                if (Math.Abs(q.X) > containerHalf.X + tolerance || Math.Abs(q.Y) > containerHalf.Y + tolerance
                    || Math.Abs(q.Z) > containerHalf.Z + tolerance)
                {
                    outsideCorner = world;
                    return false;
                }
            }
            outsideCorner = default;
            return true;
        }

        /// <summary>Throws <see cref="ArgumentException"/> listing every validation message, if any.</summary>
        public void ThrowIfInvalid()
        {
            var errors = Validate();
            if (errors.Count == 0) return;
            var lines = new string[errors.Count];
            for (int i = 0; i < errors.Count; i++) lines[i] = errors[i].Message;
            throw new ArgumentException("The fluid scene is invalid:\n  " + string.Join("\n  ", lines));
        }
    }
}
