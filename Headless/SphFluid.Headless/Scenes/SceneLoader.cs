using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using SphFluid.Simulation;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Integrity;
using SphFluid.UnityFiles.Scenes;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Headless.Scenes;

/// <summary>
/// Reads a <c>.unity</c> file the way the FluidSimulator component sees its scene at Play: its serialized
/// settings, every active SpawnBox (world transform = box), the FluidContainer (the assigned one, else the
/// scene's), every active SphereObstacle, and the ContainerSpinner / SphereDriver motions. Field names are
/// the C# field names of Assets/SphFluid/Runtime; scripts are matched by the guid of their .cs.meta.
/// </summary>
public static class SceneLoader
{
    /// <summary>Loads and validates <paramref name="scenePath"/>; <paramref name="project"/> defaults to the
    /// Unity project at or above the file (else the one holding this program).</summary>
    public static LoadedScene Load(string scenePath, UnityProject project = null)
    {
        if (Directory.Exists(scenePath))
            throw new SceneException($"{scenePath}: is a folder, not a scene file");
        if (!File.Exists(scenePath))
            throw new SceneException($"{scenePath}: no such scene file");
        project ??= FindProject(scenePath);
        UnityScene scene;
        try
        {
            scene = UnityScene.Load(scenePath);
        }
        catch (UnityYamlException e)
        {
            throw new SceneException($"{e.Message} (not a readable Unity scene)", e);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new SceneException(e.Message.StartsWith(scenePath, StringComparison.Ordinal) ? e.Message : $"{scenePath}: {e.Message}", e);
        }
        // What Unity would refuse or silently break on (a duplicated fileID, a script guid no .meta has, a parent
        // cycle) would otherwise be simulated as some other scene: refuse it before reading a single field.
        var problems = AssetIntegrity.CheckScene(project.Root, scenePath, scene.File);
        if (problems.Count > 0)
            throw new SceneException($"{scenePath}: the integrity check refuses the scene ({problems.Count} problem(s)):\n  " +
                string.Join("\n  ", problems.Select(p => $"{scenePath}{(p.Line > 0 ? ":" + p.Line.ToString(CultureInfo.InvariantCulture) : "")}: {p.Message}")));
        return new Reader(scenePath, scene, project).Read();
    }

    static UnityProject FindProject(string scenePath)
    {
        foreach (string start in new[] { Path.GetDirectoryName(Path.GetFullPath(scenePath)), AppContext.BaseDirectory, Directory.GetCurrentDirectory() })
        {
            try { return UnityProject.Find(start); }
            catch (DirectoryNotFoundException) { }
        }
        throw new SceneException($"{scenePath}: no Unity project (Assets/ + ProjectSettings/) found above the scene to resolve its script guids");
    }

    sealed class Reader(string path, UnityScene scene, UnityProject project)
    {
        readonly List<(UnityGameObject Go, UnityDocument Behaviour)> _boxes = new();
        readonly List<(UnityGameObject Go, UnityDocument Behaviour)> _obstacles = new();
        UnityGameObject _simulatorGo, _containerGo;
        UnityDocument _simulator;

        public LoadedScene Read()
        {
            var simulators = Active(ScriptGuid(RuntimeScripts.FluidSimulator));
            if (simulators.Count == 0)
                throw new SceneException($"{path}: no active GameObject has a {RuntimeScripts.FluidSimulator} component");
            if (simulators.Count > 1)
                throw new SceneException($"{path}: {simulators.Count} active {RuntimeScripts.FluidSimulator} components (GameObjects {string.Join(", ", simulators.Select(s => $"'{s.Go.Name}'"))}); the runner simulates one fluid per scene");
            (_simulatorGo, _simulator) = simulators[0];
            CheckShaders();
            CheckTransforms();
            CheckDrawingSettings();

            var description = new FluidSceneDescription
            {
                Settings = ReadSettings(),
                Container = ReadContainer(),
            };
            foreach (var (go, mb) in Active(ScriptGuid(RuntimeScripts.SpawnBox)))
            {
                _boxes.Add((go, mb));
                description.SpawnBoxes.Add(ReadSpawnBox(go, mb));
            }
            foreach (var (go, mb) in Active(ScriptGuid(RuntimeScripts.SphereObstacle)))
            {
                _obstacles.Add((go, mb));
                description.Obstacles.Add(ReadObstacle(go, mb));
            }

            // The grid's cell limit first: a container too large for its grid is also too large for its wall
            // particles, and the grid's message names both the container and the support radius.
            var errors = description.Validate();
            bool settingsOk = !errors.Any(e => e.Field.StartsWith("Settings", StringComparison.Ordinal));
            if (settingsOk && SceneFit.GridProblem(description) is { } grid)
                throw new SceneException($"{path}:{_containerGo.Transform?.Root["m_LocalScale"]?.Line ?? _containerGo.Document.Line}: the fluid scene is invalid:\n  GameObject '{_containerGo.Name}', Transform.m_LocalScale and " +
                    $"{Where(_simulatorGo, RuntimeScripts.FluidSimulator, "smoothingRadius")}: {grid}");
            if (errors.Count > 0)
                throw new SceneException($"{path}: the fluid scene is invalid:\n  " + string.Join("\n  ", errors.Select(Locate)));

            return new LoadedScene
            {
                Path = path,
                ProjectRoot = project.Root,
                Name = scene.Name,
                Description = description,
                Motion = ReadMotion(),
                SimulatorObject = _simulatorGo.Name,
                SpawnBoxObjects = _boxes.Select(b => b.Go.Name).ToList(),
                ContainerObject = _containerGo.Name,
                ObstacleObjects = _obstacles.Select(o => o.Go.Name).ToList(),
            };
        }

        string ScriptGuid(string className)
        {
            try { return project.ScriptGuid(className); }
            catch (InvalidOperationException e) { throw new SceneException($"{path}: cannot find the {className} script in the project at {project.Root}: {e.Message}", e); }
        }

        /// <summary>Enabled behaviours with the script guid on active GameObjects (active ancestors too), in file order.</summary>
        List<(UnityGameObject Go, UnityDocument Behaviour)> Active(string guid)
        {
            var list = new List<(UnityGameObject, UnityDocument)>();
            foreach (var mb in scene.Behaviours(guid))
            {
                var go = scene.GameObjectOf(mb);
                if (go == null || !mb.Root.GetBool("m_Enabled", true) || !ActiveInHierarchy(go)) continue;
                list.Add((go, mb));
            }
            return list;
        }

        static bool ActiveInHierarchy(UnityGameObject go) => go.SelfAndAncestors.All(g => g.IsActive);

        string Where(UnityGameObject go, string component, string field) =>
            $"GameObject '{go?.Name}', {component}.{field}";

        float Float(UnityGameObject go, UnityDocument mb, string component, string field, float fallback)
        {
            var node = mb.Root[field];
            if (node == null) return fallback;
            if (node.IsScalar && UnityYamlNode.TryParseNumber(node.Value, out double v)) return (float)v;
            throw new SceneException($"{path}:{node.Line}: {Where(go, component, field)} must be a number (was '{node}')");
        }

        int Int(UnityGameObject go, UnityDocument mb, string component, string field, int fallback)
        {
            var node = mb.Root[field];
            if (node == null) return fallback;
            if (node.IsScalar && long.TryParse(node.Value, out long v) && v >= int.MinValue && v <= int.MaxValue) return (int)v;
            throw new SceneException($"{path}:{node.Line}: {Where(go, component, field)} must be a whole number (was '{node}')");
        }

        Vector3 Vector(UnityGameObject go, UnityDocument mb, string component, string field, Vector3 fallback)
        {
            var node = mb.Root[field];
            if (node == null) return fallback;
            try { return mb.Root.GetVector3(field); }
            catch (FormatException) { throw new SceneException($"{path}:{node.Line}: {Where(go, component, field)} must be a vector {{x, y, z}} (was '{node}')"); }
        }

        Vector4 Color(UnityGameObject go, UnityDocument mb, string component, string field, Vector4 fallback)
        {
            var node = mb.Root[field];
            if (node == null) return fallback;
            try { return mb.Root.GetColor(field); }
            catch (FormatException) { throw new SceneException($"{path}:{node.Line}: {Where(go, component, field)} must be a colour {{r, g, b, a}} (was '{node}')"); }
        }

        static readonly (string Field, string[] Axes)[] TransformFields =
        {
            ("m_LocalPosition", new[] { "x", "y", "z" }),
            ("m_LocalRotation", new[] { "x", "y", "z", "w" }),
            ("m_LocalScale", new[] { "x", "y", "z" }),
        };

        /// <summary>Every Transform's pose is finite numbers: a world pose is composed from any of them, and a bad one
        /// must be named where it is, not surface as a parse failure deep in the composition.</summary>
        void CheckTransforms()
        {
            foreach (var t in scene.Transforms)
                foreach (var (field, axes) in TransformFields)
                {
                    var node = t.Root[field];
                    if (node == null) continue;
                    foreach (string axis in axes)
                    {
                        var value = node.IsMapping ? node[axis] : null;
                        if (value != null && value.IsScalar && UnityYamlNode.TryParseNumber(value.Value, out double v) && double.IsFinite(v)) continue;
                        string was = value == null ? (node.IsMapping ? "missing" : $"'{node}'") : $"'{value}'";
                        throw new SceneException($"{path}:{(value ?? node).Line}: GameObject '{scene.GameObjectOf(t)?.Name}', Transform.{field}.{axis} must be a finite number (was {was})");
                    }
                }
        }

        /// <summary>
        /// The simulator's fields that only Unity uses (how the particles are drawn, the longest frame) are checked
        /// against the inspector's ranges too, so a scene the headless run accepts also starts in the editor.
        /// </summary>
        void CheckDrawingSettings()
        {
            const string c = RuntimeScripts.FluidSimulator;
            InRange(_simulatorGo, _simulator, c, "particleRadiusScale", 1.2f, 0.25f, 3f, "half spacings");
            InRange(_simulatorGo, _simulator, c, "maxFrameTime", 1f / 30f, 0.001f, 0.1f, "s");
        }

        void InRange(UnityGameObject go, UnityDocument mb, string component, string field, float fallback, float min, float max, string unit)
        {
            float v = Float(go, mb, component, field, fallback);
            if (!(v >= min && v <= max))
                throw new SceneException(string.Format(CultureInfo.InvariantCulture, "{0}:{1}: {2} must be in [{3}, {4}] {5} (was {6})",
                    path, mb.Root[field]?.Line ?? mb.Line, Where(go, component, field), min, max, unit, v));
        }

        /// <summary>Each channel of a SpawnBox colour is a fraction, as Unity's colour picker writes it.</summary>
        Vector4 UnitColor(UnityGameObject go, UnityDocument mb, string component, string field, Vector4 fallback)
        {
            var c = Color(go, mb, component, field, fallback);
            float[] channels = { c.X, c.Y, c.Z, c.W };
            string[] names = { "r", "g", "b", "a" };
            for (int i = 0; i < 4; i++)
                if (!(channels[i] >= 0f && channels[i] <= 1f))
                    throw new SceneException(string.Format(CultureInfo.InvariantCulture, "{0}:{1}: {2}.{3} must be in [0, 1] (was {4})",
                        path, mb.Root[field]?.Line ?? mb.Line, Where(go, component, field), names[i], channels[i]));
            return c;
        }

        string Text(UnityDocument mb, string field, string fallback) => mb.Root[field] is { IsScalar: true } n ? n.Value : fallback;

        void CheckShaders()
        {
            foreach (var (field, program) in RuntimeScripts.ShaderFields)
            {
                var reference = _simulator.Root.GetReference(field);
                if (reference == null || reference.IsNull)
                    throw new SceneException($"{path}: {Where(_simulatorGo, RuntimeScripts.FluidSimulator, field)} has no compute shader assigned (expected {program}.compute)");
                string asset = project.AssetPathOf(reference);
                if (asset == null)
                    throw new SceneException($"{path}: {Where(_simulatorGo, RuntimeScripts.FluidSimulator, field)} refers to guid {reference.Guid}, which no asset of the project has (expected {program}.compute)");
                if (Path.GetFileNameWithoutExtension(asset) != program || !asset.EndsWith(".compute", StringComparison.Ordinal))
                    throw new SceneException($"{path}: {Where(_simulatorGo, RuntimeScripts.FluidSimulator, field)} refers to {asset}; the pipeline runs {program}.compute there");
            }
        }

        FluidSettings ReadSettings()
        {
            var d = new FluidSettings();
            const string c = RuntimeScripts.FluidSimulator;
            var go = _simulatorGo;
            var mb = _simulator;
            return new FluidSettings
            {
                ParticleSpacing = Float(go, mb, c, "particleSpacing", d.ParticleSpacing),
                SmoothingRadius = Float(go, mb, c, "smoothingRadius", d.SmoothingRadius),
                MaxParticles = Int(go, mb, c, "maxParticles", d.MaxParticles),
                Stiffness = Float(go, mb, c, "stiffness", d.Stiffness),
                Gamma = Float(go, mb, c, "gamma", d.Gamma),
                Gravity = Vector(go, mb, c, "gravity", d.Gravity),
                XsphEpsilon = Float(go, mb, c, "xsphEpsilon", d.XsphEpsilon),
                VelocityDamping = Float(go, mb, c, "velocityDamping", d.VelocityDamping),
                ArtificialViscosity = Float(go, mb, c, "artificialViscosity", d.ArtificialViscosity),
                ParticleShifting = Float(go, mb, c, "particleShifting", d.ParticleShifting),
                CflNumber = Float(go, mb, c, "cflNumber", d.CflNumber),
                MaxSubsteps = Int(go, mb, c, "maxSubsteps", d.MaxSubsteps),
                MaxTimeStep = Float(go, mb, c, "maxTimeStep", d.MaxTimeStep),
            };
        }

        ContainerDescription ReadContainer()
        {
            string containerGuid = ScriptGuid(RuntimeScripts.FluidContainer);
            var reference = _simulator.Root.GetReference("container");
            if (reference is { IsNull: false })
            {
                var doc = scene.File.Find(reference);
                if (doc == null || doc.ScriptGuid != containerGuid)
                    throw new SceneException($"{path}: {Where(_simulatorGo, RuntimeScripts.FluidSimulator, "container")} refers to {reference}, which is not a {RuntimeScripts.FluidContainer} component of this scene");
                _containerGo = scene.GameObjectOf(doc);
            }
            else
            {
                var found = Active(containerGuid);
                if (found.Count == 0)
                    throw new SceneException($"{path}: the scene has no active {RuntimeScripts.FluidContainer} (assign {Where(_simulatorGo, RuntimeScripts.FluidSimulator, "container")} or add one)");
                _containerGo = found[0].Go;
            }
            var w = _containerGo.World;
            var container = new ContainerDescription(w.Position, w.Rotation, Abs(w.Scale));
            var component = Active(containerGuid).Find(found => found.Go == _containerGo).Behaviour;
            if (component != null)
                container.Friction = (WallFriction)Int(_containerGo, component, RuntimeScripts.FluidContainer, "friction", (int)container.Friction);
            return container;
        }

        SpawnBoxDescription ReadSpawnBox(UnityGameObject go, UnityDocument mb)
        {
            const string c = RuntimeScripts.SpawnBox;
            var d = new PhaseDescription();
            var phase = new PhaseDescription(Text(mb, "phaseName", d.Name), Float(go, mb, c, "restDensity", d.RestDensity), Float(go, mb, c, "viscosity", d.Viscosity))
            {
                ParticleMass = Float(go, mb, c, "particleMass", 0f),
                SurfaceTension = Float(go, mb, c, "surfaceTension", 0f),
                Color = ColorSpace.SrgbToLinear(UnitColor(go, mb, c, "color", new Vector4(0.2f, 0.45f, 0.9f, 0.8f))),
                FresnelF0 = Float(go, mb, c, "fresnelF0", d.FresnelF0),
                Absorption = Float(go, mb, c, "absorption", d.Absorption),
            };
            var w = go.World;
            var box = new SpawnBoxDescription();
            return new SpawnBoxDescription(go.Name, phase, w.Position, Abs(w.Scale))
            {
                Rotation = w.Rotation,
                InitialVelocity = Vector(go, mb, c, "initialVelocity", Vector3.Zero),
                Jitter = Float(go, mb, c, "jitter", box.Jitter),
                Seed = Int(go, mb, c, "seed", box.Seed),
            };
        }

        SphereObstacleDescription ReadObstacle(UnityGameObject go, UnityDocument mb)
        {
            var w = go.World;
            var s = Abs(w.Scale);
            float radius = Float(go, mb, RuntimeScripts.SphereObstacle, "radius", 0.5f) * MathF.Max(s.X, MathF.Max(s.Y, s.Z));
            return new SphereObstacleDescription(w.Position, radius, Vector3.Zero) { Name = go.Name };
        }

        SceneMotion ReadMotion()
        {
            ContainerSpin spin = null;
            foreach (var (go, mb) in Active(ScriptGuid(RuntimeScripts.ContainerSpinner)))
            {
                if (!IsSelfOrAncestor(go, _containerGo))
                    throw new SceneException($"{path}: GameObject '{go.Name}' has a {RuntimeScripts.ContainerSpinner} but is neither the container '{_containerGo.Name}' nor its parent; the runner turns only the container");
                if (spin != null)
                    throw new SceneException($"{path}: more than one {RuntimeScripts.ContainerSpinner} turns the container '{_containerGo.Name}'");
                const string c = RuntimeScripts.ContainerSpinner;
                spin = new ContainerSpin(Vector(go, mb, c, "axis", Vector3.UnitZ), Float(go, mb, c, "angularSpeed", 30f), Float(go, mb, c, "startDelay", 1f), go.World.Position);
                if (spin.Axis.LengthSquared() < 1e-12f)
                    throw new SceneException($"{path}: {Where(go, c, "axis")} must be non-zero (was {spin.Axis})");
                if (!float.IsFinite(spin.DegreesPerSecond) || Math.Abs(spin.DegreesPerSecond) > 360f)
                    throw new SceneException($"{path}: {Where(go, c, "angularSpeed")} must be in [-360, 360] degrees/s (was {spin.DegreesPerSecond})");
                if (!(spin.StartDelay >= 0f) || !float.IsFinite(spin.StartDelay))
                    throw new SceneException($"{path}: {Where(go, c, "startDelay")} must be >= 0 s (was {spin.StartDelay})");
            }

            var drives = new List<SphereDrive>();
            foreach (var (go, mb) in Active(ScriptGuid(RuntimeScripts.SphereDriver)))
            {
                int index = _obstacles.FindIndex(o => o.Go.FileId == go.FileId);
                if (index < 0)
                    throw new SceneException($"{path}: GameObject '{go.Name}' has a {RuntimeScripts.SphereDriver} but no active {RuntimeScripts.SphereObstacle}; the runner drives obstacles only");
                const string c = RuntimeScripts.SphereDriver;
                var drive = new SphereDrive(index, Vector(go, mb, c, "travel", new Vector3(0.3f, 0, 0)), Float(go, mb, c, "period", 4f), Float(go, mb, c, "startDelay", 1f));
                if (!(drive.Period >= 0.1f) || !float.IsFinite(drive.Period))
                    throw new SceneException($"{path}: {Where(go, c, "period")} must be at least 0.1 s (was {drive.Period})");
                if (!(drive.StartDelay >= 0f) || !float.IsFinite(drive.StartDelay))
                    throw new SceneException($"{path}: {Where(go, c, "startDelay")} must be >= 0 s (was {drive.StartDelay})");
                drives.Add(drive);
            }
            return new SceneMotion { ContainerSpin = spin, SphereDrives = drives };
        }

        static bool IsSelfOrAncestor(UnityGameObject candidate, UnityGameObject of) =>
            of.SelfAndAncestors.Any(g => g.FileId == candidate.FileId);

        /// <summary>Prefixes a core validation message with the GameObject, component and serialized field it came from.</summary>
        string Locate(ValidationError error)
        {
            string[] parts = error.Field.Split('.');
            string head = parts[0];
            string member = parts[^1];
            if (head == "Settings")
                return $"{Where(_simulatorGo, RuntimeScripts.FluidSimulator, CamelCase(member))}: {error.Message}";
            if (head == "Container")
                return $"GameObject '{_containerGo.Name}', {TransformField(member) ?? RuntimeScripts.FluidContainer}: {error.Message}";
            if (TryIndex(head, "SpawnBoxes", out int b) && b < _boxes.Count)
            {
                var go = _boxes[b].Go;
                string field = TransformField(member) ?? (member == "Name" ? "SpawnBox.phaseName" : member == "Phase" ? "SpawnBox.phaseName" : "SpawnBox." + CamelCase(member));
                return $"GameObject '{go.Name}', {field}: {error.Message}";
            }
            if (TryIndex(head, "Obstacles", out int o) && o < _obstacles.Count)
                return $"GameObject '{_obstacles[o].Go.Name}', {TransformField(member) ?? "SphereObstacle." + CamelCase(member)}: {error.Message}";
            return error.Message;
        }

        static string TransformField(string member) => member switch
        {
            "Center" or "Position" => "Transform.m_LocalPosition",
            "Rotation" => "Transform.m_LocalRotation",
            "Size" => "Transform.m_LocalScale",
            _ => null,
        };

        static bool TryIndex(string head, string name, out int index)
        {
            index = -1;
            if (!head.StartsWith(name + "[", StringComparison.Ordinal) || !head.EndsWith(']')) return false;
            return int.TryParse(head[(name.Length + 1)..^1], out index);
        }

        static string CamelCase(string name) => string.IsNullOrEmpty(name) ? name : char.ToLowerInvariant(name[0]) + name[1..];
    }

    static Vector3 Abs(Vector3 v) => Vector3.Abs(v);
}
