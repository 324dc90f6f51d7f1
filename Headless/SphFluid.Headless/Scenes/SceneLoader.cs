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
/// Reads a <c>.unity</c> file the way the Fluid component sees its scene at Play: its serialized
/// settings, every active SpawnBox (world transform = box), the FluidContainer (the assigned one, else the
/// scene's), every active SphereObstacle, and the ContainerSpinner / SphereDriver motions. Field names are
/// the C# field names of the package's Runtime/ (<see cref="FluidPackage"/>); scripts are matched by the guid of their .cs.meta.
/// </summary>
public static class SceneLoader
{
    /// <summary>Loads and validates <paramref name="scenePath"/>; <paramref name="project"/> defaults to the
    /// Unity project at or above the file (else the one holding this program). <paramref name="change"/>, what the
    /// command changes (<see cref="SceneChange"/>), is applied before the validation.</summary>
    public static LoadedScene Load(string scenePath, UnityProject? project = null, SceneChange? change = null) =>
        Open(scenePath, project).Read(change);

    /// <summary>
    /// A scene file read, held to the integrity check and its prefab instances built, once; each <see cref="Read"/>
    /// makes a fresh description of it under one change. A study reads the scene once per configuration and a bench
    /// once per size: loaded afresh, each read scanned the project's every .meta twice, and a bench of a thousand sizes
    /// sat without a line past the 10 s of <c>AThousandBenchSizesAreReadBeforeTheDeadline</c>.
    /// </summary>
    public sealed class CheckedScene
    {
        readonly string _path;
        readonly UnityScene _scene;
        readonly UnityProject _project;
        readonly string _package;

        internal CheckedScene(string path, UnityScene scene, UnityProject project, string package, string? unreadProblems) =>
            (_path, _scene, _project, _package, UnreadProblems) = (path, scene, project, package, unreadProblems);

        /// <summary>The integrity check's problems on objects the fluid is not read from, as a warning, or null for none
        /// (<see cref="FluidDocuments"/>).</summary>
        public string? UnreadProblems { get; }

        /// <summary>The scene's description with <paramref name="change"/> applied, validated so; each call's is its own.</summary>
        public LoadedScene Read(SceneChange? change = null) => new Reader(_path, _scene, _project, _package).Read(change);
    }

    /// <summary>Reads <paramref name="scenePath"/> and refuses what the integrity check or a prefab instance refuses,
    /// reading no field yet (<see cref="CheckedScene.Read"/> does); <paramref name="project"/> as for <see cref="Load"/>.</summary>
    public static CheckedScene Open(string scenePath, UnityProject? project = null)
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
        // Without the package, every script guid would be refused as unknown: name what is missing instead.
        string package = FluidPackage.FolderFor(scenePath, project);
        // What Unity would refuse or silently break on (a duplicated fileID, a script guid no .meta has, a parent
        // cycle) would otherwise be simulated as some other scene: refuse it before reading a single field.
        // Only what the fluid is read from is held to it: Unity plays a scene whose props have a stale field or a missing
        // script, and so does the run, with a warning.
        var fluidScripts = RuntimeScripts.Components.Select(c => FluidPackage.ScriptGuid(project, package, c)).OfType<string>().ToList();
        var (problems, unread) = FluidDocuments.Split(scene, project.Root, AssetIntegrity.CheckScene(project, scenePath, scene.File), fluidScripts);
        if (problems.Count > 0)
            throw new SceneException($"{scenePath}: the integrity check refuses the scene ({problems.Count} problem(s)):\n  " +
                string.Join("\n  ", problems.Select(p => FluidDocuments.Located(scenePath, p))));
        return new CheckedScene(scenePath, PrefabInstances.Build(scenePath, scene, project, package), project, package,
            FluidDocuments.Warning(scenePath, unread));
    }

    static UnityProject FindProject(string scenePath)
    {
        // The scene's folder is null only for a root directory, which Load has refused as a folder.
        foreach (string? start in new[] { Path.GetDirectoryName(Path.GetFullPath(scenePath)), AppContext.BaseDirectory, Directory.GetCurrentDirectory() })
        {
            if (start == null) continue;
            try { return UnityProject.Find(start); }
            catch (DirectoryNotFoundException) { }
        }
        throw new SceneException($"{scenePath}: no Unity project (Assets/ + ProjectSettings/) found above the scene to resolve its script guids");
    }

    /// <summary>One scene's reading. The Fluid is found first (without it there is nothing to read); the container only
    /// after the shaders, transforms and settings are checked, so that a scene with several faults is refused for the
    /// first in that order, and its GameObject is then handed to what names it.</summary>
    sealed class Reader
    {
        readonly string path;
        readonly UnityScene scene;
        readonly UnityProject project;
        readonly string packageFolder;
        readonly List<(UnityGameObject Go, UnityDocument Behaviour)> _boxes = new();
        readonly List<(UnityGameObject Go, UnityDocument Behaviour)> _obstacles = new();
        readonly UnityGameObject _simulatorGo;
        readonly UnityDocument _simulator;
        UnityDocument? _container; // the FluidContainer component the fluid runs in, once ReadContainer has found it

        public Reader(string path, UnityScene scene, UnityProject project, string packageFolder)
        {
            this.path = path;
            this.scene = scene;
            this.project = project;
            this.packageFolder = packageFolder;
            var simulators = Active(RuntimeScripts.Fluid);
            if (simulators.Count == 0)
                throw new SceneException($"{path}: no active GameObject has a {RuntimeScripts.Fluid} component");
            if (simulators.Count > 1)
                throw new SceneException($"{path}: {simulators.Count} active {RuntimeScripts.Fluid} components (on GameObjects {string.Join(", ", simulators.Select(s => $"'{s.Go.Name}' at line {s.Behaviour.Line}"))}); the runner simulates one fluid per scene");
            (_simulatorGo, _simulator) = simulators[0];
        }

        public LoadedScene Read(SceneChange? change)
        {
            CheckShaders();
            CheckTransforms();
            CheckDrawingSettings();

            var settings = ReadSettings();
            var (container, containerGo) = ReadContainer();
            var description = new FluidSceneDescription
            {
                Settings = settings,
                Container = container,
            };
            foreach (var (go, mb) in Active(RuntimeScripts.SpawnBox))
            {
                _boxes.Add((go, mb));
                description.SpawnBoxes.Add(ReadSpawnBox(go, mb));
            }
            foreach (var (go, mb) in Active(RuntimeScripts.SphereObstacle))
            {
                _obstacles.Add((go, mb));
                description.Obstacles.Add(ReadObstacle(go, mb));
            }

            change?.Apply(description);
            string invalid = change == null ? "the fluid scene is invalid" : $"the fluid scene is invalid as {change.Label} runs it";

            // The grid's cell limit first: a container too large for its grid is also too large for its wall
            // particles, and the grid's message names both the container and the support radius. A container outside
            // its own size range is refused for that: the grid would ask a support radius of kilometres for it.
            var errors = description.Validate();
            bool settingsOk = !errors.Any(e => e.Field.StartsWith("Settings", StringComparison.Ordinal));
            if (settingsOk && FluidSceneDescription.ContainerSizeInRange(description.Container.Size, description.Settings.ParticleSpacing)
                && SceneFit.GridProblem(description) is { } grid)
                throw new SceneException($"{At(containerGo.Transform?.Root["m_LocalScale"], containerGo.Transform ?? containerGo.Document)}: {invalid}:\n  GameObject '{containerGo.Name}', Transform.m_LocalScale and " +
                    $"{Where(_simulatorGo, RuntimeScripts.Fluid, RuntimeScripts.Settings + "." + nameof(FluidSettings.SmoothingRadius))}: {grid}");
            if (errors.Count > 0)
                throw new SceneException($"{path}: {invalid}:\n  " + string.Join("\n  ", errors.Select(e => Locate(e, containerGo))));

            return new LoadedScene
            {
                Path = path,
                PackageFolder = packageFolder,
                Name = scene.Name,
                Description = description,
                Motion = ReadMotion(containerGo),
                SimulatorObject = Shown(_simulatorGo),
                SpawnBoxObjects = _boxes.Select(b => Shown(b.Go)).ToList(),
                ContainerObject = Shown(containerGo),
                ObstacleObjects = _obstacles.Select(o => Shown(o.Go)).ToList(),
            };
        }

        /// <summary>A GameObject's name as the run prints it, in its lines and in summary.txt: Unity lets a name hold any
        /// character, and a control character in it would act on the terminal (<see cref="PrintableText"/>).</summary>
        static string Shown(UnityGameObject go) => PrintableText.Escape(go.Name);

        string ScriptGuid(string className) => FluidPackage.ScriptGuid(project, packageFolder, className) ?? throw new SceneException(
            $"{path}: cannot find the {className} script in the project at {project.Root}: no Runtime/{className}.cs with a .meta in {packageFolder}");

        /// <summary>Enabled <paramref name="script"/> behaviours on active GameObjects (active ancestors too), in file order;
        /// with <paramref name="enabledOnly"/> false, disabled ones too, as Unity's FindObjectsByType finds them.</summary>
        List<(UnityGameObject Go, UnityDocument Behaviour)> Active(string script, bool enabledOnly = true)
        {
            var list = new List<(UnityGameObject, UnityDocument)>();
            foreach (var mb in scene.Behaviours(ScriptGuid(script)))
            {
                var go = scene.GameObjectOf(mb);
                if (go == null) continue;
                bool enabled = Flag(go, mb, script, "m_Enabled");
                if (enabledOnly && !enabled || !go.SelfAndAncestors.All(g => Flag(g, g.Document, "GameObject", "m_IsActive"))) continue;
                list.Add((go, mb));
            }
            return list;
        }

        /// <summary>A bool as Unity writes it, 0 or 1. The integrity check holds the scene's own flags to that; a prefab
        /// instance's override is not checked there, and an m_IsActive of 2 on it was read as active.</summary>
        bool Flag(UnityGameObject go, UnityDocument document, string component, string key)
        {
            if (document.Root[key] is not { } node) return true;
            return node.AsFlag ?? throw new SceneException($"{At(node, document)}: {Where(go, component, key)} must be 0 or 1, as Unity writes a bool (was '{node}')");
        }

        string Where(UnityGameObject go, string component, string field) =>
            $"GameObject '{go?.Name}', {component}.{field}";

        /// <summary>Where a value stands, as <c>scene:line</c>: the node's own line, else its document's. A value a prefab
        /// instance keeps from its prefab is at the instance's line, and at its own line in the .prefab, where it can be
        /// mended for every instance; one the instance overrides in part (one axis of a rotation) is at its first override.
        /// Every refusal starts with the scene, whichever file holds the value.</summary>
        string At(UnityYamlNode? node, UnityDocument document)
        {
            if (node == null) return $"{path}:{document.Line}";
            if (node.SourceFile is not { } prefab) return $"{path}:{node.Line}";
            if (node.DescendantsAndSelf().FirstOrDefault(n => n.SourceFile != prefab) is { } overridden) return At(overridden, document);
            return $"{path}:{document.Line} (the value at {prefab}:{node.Line}, which the instance does not override)";
        }

        // Each reader below quotes `allowed` when the text is not even of the field's type, so that the message says what
        // to write: a declared setting's range (SettingRules.Allowed), else the bare type.
        float Float(UnityGameObject go, UnityDocument mb, string component, string field, float fallback, string allowed = "a number")
        {
            var node = mb.Root.At(field);
            if (node == null) return fallback;
            if (node.IsScalar && UnityYamlNode.TryParseNumber(node.Value, out double v)) return (float)v;
            throw new SceneException($"{At(node, mb)}: {Where(go, component, field)} must be {allowed} (was '{node}')");
        }

        int Int(UnityGameObject go, UnityDocument mb, string component, string field, int fallback, string allowed = "a whole number")
        {
            var node = mb.Root.At(field);
            if (node == null) return fallback;
            if (node.IsScalar && long.TryParse(node.Value, out long v) && v >= int.MinValue && v <= int.MaxValue) return (int)v;
            throw new SceneException($"{At(node, mb)}: {Where(go, component, field)} must be {allowed} (was '{node}')");
        }

        Vector3 Vector(UnityGameObject go, UnityDocument mb, string component, string field, Vector3 fallback, string allowed = "a vector {x, y, z}")
        {
            var node = mb.Root.At(field);
            if (node == null) return fallback;
            RequireComponents(go, mb, component, field, node, "x", "y", "z");
            try { return mb.Root.GetVector3(field); }
            catch (FormatException) { throw new SceneException($"{At(Unreadable(node, "x", "y", "z"), mb)}: {Where(go, component, field)} must be {allowed} (was '{node}')"); }
        }

        Vector4 Color(UnityGameObject go, UnityDocument mb, string component, string field, Vector4 fallback, string allowed = "a colour {r, g, b, a}")
        {
            var node = mb.Root.At(field);
            if (node == null) return fallback;
            RequireComponents(go, mb, component, field, node, "r", "g", "b", "a");
            try { return mb.Root.GetColor(field); }
            catch (FormatException) { throw new SceneException($"{At(Unreadable(node, "r", "g", "b", "a"), mb)}: {Where(go, component, field)} must be {allowed} (was '{node}')"); }
        }

        /// <summary>A vector or colour as Unity writes it, every component and no other: a misspelt component (<c>alpha:</c>)
        /// was dropped and the colour's alpha read as 1. The values themselves are the reader's to parse.</summary>
        void RequireComponents(UnityGameObject go, UnityDocument mb, string component, string field, UnityYamlNode node, params string[] components)
        {
            if (!node.IsMapping) return;
            string written = string.Join(", ", components);
            foreach (var (key, value) in node.Entries)
                if (Array.IndexOf(components, key) < 0)
                    throw new SceneException($"{At(value, mb)}: {Where(go, component, field)} has no component '{key}' (Unity writes {written})");
            foreach (string c in components)
                if (node[c] == null)
                    throw new SceneException($"{At(node, mb)}: {Where(go, component, field)} lacks its '{c}' (Unity writes {written})");
        }

        /// <summary>The first component that holds no number, else the whole value.</summary>
        static UnityYamlNode Unreadable(UnityYamlNode node, params string[] components) =>
            components.Select(c => node[c]).FirstOrDefault(c => c != null && !(c.IsScalar && UnityYamlNode.TryParseNumber(c.Value, out _))) ?? node;

        static readonly (string Field, string[] Axes)[] TransformFields =
        {
            ("m_LocalPosition", new[] { "x", "y", "z" }),
            ("m_LocalRotation", new[] { "x", "y", "z", "w" }),
            ("m_LocalScale", new[] { "x", "y", "z" }),
        };

        /// <summary>Every Transform's pose is finite numbers and its rotation a unit quaternion, as Unity writes them: a
        /// world pose is composed from any of them, and a bad one must be named where it is, not surface as a parse
        /// failure or a degenerate rotation deep in the composition (a zero quaternion was reported as the container's
        /// scale, a tiny one as a spawn box's NaN rotation with no line).</summary>
        void CheckTransforms()
        {
            foreach (var t in scene.Transforms)
                foreach (var (field, axes) in TransformFields)
                {
                    var node = t.Root[field];
                    if (node == null) continue;
                    // A scalar in the mapping's place was reported as its first axis "must be a finite number (was '-0')",
                    // which blamed a number that was finite.
                    if (!node.IsMapping)
                        throw new SceneException($"{At(node, t)}: GameObject '{scene.GameObjectOf(t)?.Name}', Transform.{field} must be {{{string.Join(", ", Array.ConvertAll(axes, a => a + ": <number>"))}}} (was '{node}')");
                    double squares = 0;
                    foreach (string axis in axes)
                    {
                        var value = node[axis];
                        if (value != null && value.IsScalar && UnityYamlNode.TryParseNumber(value.Value, out double v) && double.IsFinite(v))
                        {
                            squares += v * v;
                            continue;
                        }
                        string was = value == null ? "missing" : $"'{value}'";
                        throw new SceneException($"{At(value ?? node, t)}: GameObject '{scene.GameObjectOf(t)?.Name}', Transform.{field}.{axis} must be a finite number (was {was})");
                    }
                    double length = Math.Sqrt(squares);
                    if (field == "m_LocalRotation" && !(Math.Abs(length - 1) <= FluidSceneDescription.RotationLengthTolerance))
                        throw new SceneException(FormattableString.Invariant(
                            $"{At(node, t)}: GameObject '{scene.GameObjectOf(t)?.Name}', Transform.{field} must be a unit quaternion (length in {FluidSceneDescription.RotationLengthRange}) (was {node}, length {length:G4})"));
                }
        }

        /// <summary>
        /// The simulator's fields that only Unity uses (how the particles are drawn, the longest frame) are checked
        /// against the inspector's ranges too, so a scene the headless run accepts also starts in the editor.
        /// </summary>
        void CheckDrawingSettings()
        {
            const string c = RuntimeScripts.Fluid;
            InRange(_simulatorGo, _simulator, c, "particleRadiusScale", 1.2f, 0.25f, 3f, "half spacings");
            InRange(_simulatorGo, _simulator, c, "maxFrameTime", 1f / 30f, 0.001f, 0.1f, "s");
        }

        void InRange(UnityGameObject go, UnityDocument mb, string component, string field, float fallback, float min, float max, string unit)
        {
            string range = string.Format(CultureInfo.InvariantCulture, "[{0}, {1}] {2}", min, max, unit);
            float v = Float(go, mb, component, field, fallback, "a number in " + range);
            if (!(v >= min && v <= max))
                throw new SceneException(string.Format(CultureInfo.InvariantCulture, "{0}: {1} must be in {2} (was {3})",
                    At(mb.Root[field], mb), Where(go, component, field), range, v));
        }

        string Text(UnityGameObject go, UnityDocument mb, string component, string field, string fallback, string allowed = "text")
        {
            var node = mb.Root.At(field);
            if (node == null) return fallback;
            if (node.IsScalar) return node.Value;
            throw new SceneException($"{At(node, mb)}: {Where(go, component, field)} must be {allowed} (was '{node}')");
        }

        /// <summary>The compute shaders Unity would run: those the package's resources asset names, which must be the
        /// programs the headless pipeline loads by name (a renamed or re-pointed shader fails here, not mid-run).</summary>
        void CheckShaders()
        {
            string? resources = project.AssetPathOfResource(RuntimeScripts.ResourcesAsset + ".asset");
            if (resources == null)
                throw new SceneException($"{path}: the project has no Resources/{RuntimeScripts.ResourcesAsset}.asset (the fluid package's shaders and material)");
            var root = UnityYamlFile.Load(project.FullPath(resources)).Documents.FirstOrDefault()?.Root;
            foreach (var (field, program) in RuntimeScripts.ShaderFields)
            {
                var reference = root?.GetReference(field);
                int line = root?[field]?.Line ?? 1;
                if (reference == null || reference.IsNull)
                    throw new SceneException($"{resources}:{line}: {field} has no compute shader assigned (expected {program}.compute)");
                string? asset = project.AssetPathOf(reference);
                if (asset == null)
                    throw new SceneException($"{resources}:{line}: {field} refers to guid {reference.Guid}, which no asset of the project has (expected {program}.compute)");
                if (Path.GetFileNameWithoutExtension(asset) != program || !asset.EndsWith(".compute", StringComparison.Ordinal))
                    throw new SceneException($"{resources}:{line}: {field} refers to {asset}; the pipeline runs {program}.compute there");
            }
        }

        /// <summary>The simulator's <c>settings</c>, field by declared field (<see cref="SettingRules"/>).</summary>
        FluidSettings ReadSettings() => ReadDeclared<FluidSettings>(_simulatorGo, _simulator, RuntimeScripts.Fluid, RuntimeScripts.Settings);

        /// <summary>A component's serialized settings object, field by declared field, through the declared blocks it
        /// holds (<see cref="SettingRules.DeclaredPaths"/>): the names, types and defaults are the core class's own, so
        /// a new setting needs no line here. A missing field keeps its default, as in Unity; a key no field declares is
        /// refused (<see cref="RefuseUndeclaredKeys"/>).</summary>
        T ReadDeclared<T>(UnityGameObject go, UnityDocument mb, string component, string prefix) where T : new()
        {
            var values = new T();
            RefuseUndeclaredKeys(go, mb, component, prefix, SettingRules.DeclaredPaths(typeof(T)), typeof(T).Name);
            foreach (var declared in SettingRules.DeclaredPaths(typeof(T)))
            {
                var type = declared.Field.FieldType;
                string key = prefix + "." + declared.Path;
                object value = declared.GetValue(values);
                string allowed = SettingRules.Allowed(type, declared.Declaration);
                if (type == typeof(float)) value = Float(go, mb, component, key, (float)value, allowed);
                else if (type == typeof(int)) value = Int(go, mb, component, key, (int)value, allowed);
                else if (type == typeof(string)) value = Text(go, mb, component, key, (string)value, allowed);
                else if (type == typeof(SettingVector)) value = (SettingVector)Vector(go, mb, component, key, (SettingVector)value, allowed);
                else if (type == typeof(SettingColor)) value = (SettingColor)Color(go, mb, component, key, (SettingColor)value, allowed);
                else if (type.IsEnum) value = Enum.ToObject(type, Int(go, mb, component, key, Convert.ToInt32(value), allowed));
                else throw new NotSupportedException($"{typeof(T).Name}.{declared.Path}: no scene reading for {type.Name}");
                declared.SetValue(values, value);
            }
            return values;
        }

        /// <summary>
        /// Unity drops a key that no field declares and the field keeps its default, so in a hand-edited scene a misspelt
        /// setting (<c>ParticleSpaceing: 0.015</c>) ran silently at the default spacing. Unity writes only declared fields,
        /// so such a key is refused where it stands, with the fields its block declares. A vector's or colour's own
        /// components are their readers' to check (<see cref="RequireComponents"/>).
        /// </summary>
        void RefuseUndeclaredKeys(UnityGameObject go, UnityDocument mb, string component, string prefix,
            IReadOnlyList<SettingPath> declared, string typeName)
        {
            var block = mb.Root.At(prefix);
            if (block == null || !block.IsMapping) return;
            Refuse(block, "");

            void Refuse(UnityYamlNode node, string within)
            {
                foreach (var (key, child) in node.Entries)
                {
                    string keyPath = within + key;
                    if (declared.Any(d => d.Path == keyPath)) continue;
                    if (child.IsMapping && declared.Any(d => d.Path.StartsWith(keyPath + ".", StringComparison.Ordinal)))
                    {
                        Refuse(child, keyPath + ".");
                        continue;
                    }
                    var fields = declared.Where(d => d.Path.StartsWith(within, StringComparison.Ordinal))
                        .Select(d => d.Path.Substring(within.Length).Split('.')[0]).Distinct();
                    throw new SceneException($"{At(child, mb)}: {Where(go, component, prefix + "." + keyPath)}: no field of {typeName}{(within.Length > 0 ? "." + within.TrimEnd('.') : "")} " +
                        $"is named '{key}', so Unity would drop it and keep the field's default (its fields: {string.Join(", ", fields)})");
                }
            }
        }

        /// <summary>Refuses a motion law's first out-of-range field, naming the file, line, GameObject and field.</summary>
        void RequireValid(IReadOnlyList<ValidationError> errors, UnityGameObject go, UnityDocument mb, string component, string prefix)
        {
            if (errors.Count == 0) return;
            string key = prefix + "." + errors[0].Field;
            throw new SceneException($"{At(mb.Root.At(key), mb)}: {Where(go, component, key)}: {errors[0].Rule}");
        }

        /// <summary>The container (the Fluid's assigned one, else the scene's first on an active GameObject) and its GameObject; its
        /// component is kept in <see cref="_container"/> for the refusals that name its fields.</summary>
        (ContainerDescription Container, UnityGameObject Go) ReadContainer()
        {
            string containerGuid = ScriptGuid(RuntimeScripts.FluidContainer);
            var reference = _simulator.Root.GetReference("container");
            UnityGameObject containerGo;
            UnityDocument component;
            if (reference is { IsNull: false })
            {
                var doc = scene.File.Find(reference);
                string at = At(_simulator.Root.At("container"), _simulator);
                if (doc == null || doc.ScriptGuid != containerGuid)
                    throw new SceneException($"{at}: {Where(_simulatorGo, RuntimeScripts.Fluid, "container")} refers to {reference}, which is not a {RuntimeScripts.FluidContainer} component of this scene");
                containerGo = scene.GameObjectOf(doc)
                    ?? throw new SceneException($"{at}: {Where(_simulatorGo, RuntimeScripts.Fluid, "container")} refers to {reference}, a {RuntimeScripts.FluidContainer} on no GameObject of this scene (its m_GameObject is missing or dangling)");
                component = doc;
            }
            else
            {
                // Fluid.FindContainer's FindFirstObjectByType skips inactive GameObjects, not disabled components.
                var found = Active(RuntimeScripts.FluidContainer, enabledOnly: false);
                if (found.Count == 0)
                    throw new SceneException($"{path}: the scene has no active {RuntimeScripts.FluidContainer} (assign {Where(_simulatorGo, RuntimeScripts.Fluid, "container")} or add one)");
                (containerGo, component) = found[0];
            }
            var w = containerGo.World;
            var container = new ContainerDescription(w.Position, w.Rotation, Abs(w.Scale));
            // Fluid.FindContainer takes the assigned container as it is, active or not, and reads its friction: so does
            // the reader (it read an inactive one's as the default, NoSlip, where Unity runs the Slip it holds).
            container.Friction = (WallFriction)Int(containerGo, component, RuntimeScripts.FluidContainer, "friction", (int)container.Friction,
                "one of " + SettingRules.EnumValues(typeof(WallFriction)));
            _container = component;
            return (container, containerGo);
        }

        /// <summary>The box's declared values (its phase among them) from its serialized block; the placement from its
        /// GameObject, as SpawnBox.Describe takes it.</summary>
        FluidBlock ReadSpawnBox(UnityGameObject go, UnityDocument mb)
        {
            var box = ReadDeclared<FluidBlock>(go, mb, RuntimeScripts.SpawnBox, RuntimeScripts.Spawn);
            var w = go.World;
            box.Name = Shown(go);
            box.Center = w.Position;
            box.Rotation = w.Rotation;
            box.Size = Abs(w.Scale);
            return box;
        }

        RigidSphere ReadObstacle(UnityGameObject go, UnityDocument mb)
        {
            var w = go.World;
            var s = Abs(w.Scale);
            float radius = Float(go, mb, RuntimeScripts.SphereObstacle, "radius", 0.5f) * MathF.Max(s.X, MathF.Max(s.Y, s.Z));
            return new RigidSphere(w.Position, radius, Vector3.Zero) { Name = Shown(go) };
        }

        SceneMotion ReadMotion(UnityGameObject containerGo)
        {
            SpinLaw? spin = null;
            Vector3 pivot = Vector3.Zero;
            foreach (var (go, mb) in Active(RuntimeScripts.ContainerSpinner))
            {
                if (!IsSelfOrAncestor(go, containerGo))
                    throw new SceneException($"{At(null, mb)}: GameObject '{go.Name}' has a {RuntimeScripts.ContainerSpinner} but is neither the container '{containerGo.Name}' nor its parent; the runner turns only the container");
                if (spin != null)
                    throw new SceneException($"{At(null, mb)}: more than one {RuntimeScripts.ContainerSpinner} turns the container '{containerGo.Name}'");
                const string c = RuntimeScripts.ContainerSpinner;
                spin = ReadDeclared<SpinLaw>(go, mb, c, RuntimeScripts.Spin);
                RequireValid(spin.Validate(c), go, mb, c, RuntimeScripts.Spin);
                pivot = go.World.Position;
            }

            var drives = new List<DrivenSphere>();
            foreach (var (go, mb) in Active(RuntimeScripts.SphereDriver))
            {
                int index = _obstacles.FindIndex(o => o.Go.FileId == go.FileId);
                if (index < 0)
                    throw new SceneException($"{At(null, mb)}: GameObject '{go.Name}' has a {RuntimeScripts.SphereDriver} but no active {RuntimeScripts.SphereObstacle}; the runner drives obstacles only");
                const string c = RuntimeScripts.SphereDriver;
                var drive = ReadDeclared<DriveLaw>(go, mb, c, RuntimeScripts.Drive);
                RequireValid(drive.Validate(c), go, mb, c, RuntimeScripts.Drive);
                drives.Add(new DrivenSphere(index, drive));
            }
            return new SceneMotion { ContainerSpin = spin, SpinPivot = pivot, SphereDrives = drives };
        }

        static bool IsSelfOrAncestor(UnityGameObject candidate, UnityGameObject of) =>
            of.SelfAndAncestors.Any(g => g.FileId == candidate.FileId);

        /// <summary>Prefixes a core validation message with the GameObject, component and serialized field it came from.</summary>
        string Locate(ValidationError error, UnityGameObject containerGo)
        {
            string[] parts = error.Field.Split('.');
            string head = parts[0];
            string member = parts[^1];
            if (head == "Settings")
            {
                string key = RuntimeScripts.Settings + "." + member;
                return $"{At(_simulator.Root.At(key), _simulator)}: {Where(_simulatorGo, RuntimeScripts.Fluid, key)}: {error.Rule}";
            }
            if (head == "Container")
            {
                if (TransformField(member) is { } containerPlacement)
                    return Placed(containerGo, containerPlacement, error);
                if (member == nameof(ContainerDescription.Friction) && _container is { } component)
                    return $"{At(component.Root.At("friction"), component)}: {Where(containerGo, RuntimeScripts.FluidContainer, "friction")}: {error.Rule}";
                return $"{path}:{containerGo.Document.Line}: GameObject '{containerGo.Name}', {RuntimeScripts.FluidContainer}: {error.Rule}";
            }
            if (TryIndex(head, "SpawnBoxes", out int b) && b < _boxes.Count)
            {
                var (go, mb) = _boxes[b];
                if (parts.Length == 2 && TransformField(member) is { } placement)
                    return Placed(go, placement, error);
                // The core's path below the box is the serialized one: SpawnBoxes[0].Phase.RestDensity is spawn.Phase.RestDensity.
                string key = RuntimeScripts.Spawn + "." + string.Join(".", parts.Skip(1));
                return $"{At(mb.Root.At(key), mb)}: {Where(go, RuntimeScripts.SpawnBox, key)}: {error.Rule}";
            }
            if (TryIndex(head, "Obstacles", out int o) && o < _obstacles.Count)
            {
                var (go, mb) = _obstacles[o];
                if (TransformField(member) is { } spherePlacement) return Placed(go, spherePlacement, error);
                string key = CamelCase(member);
                string scaled = member == nameof(RigidSphere.Radius) ? ScaledRadius(go, mb) : "";
                return $"{At(mb.Root.At(key), mb)}: GameObject '{go.Name}', SphereObstacle.{key}{scaled}: {error.Rule}";
            }
            return error.Message;
        }

        /// <summary>Where the sphere's scale is not 1, how its world radius, which the rule quotes, comes from the field.</summary>
        string ScaledRadius(UnityGameObject go, UnityDocument mb)
        {
            var s = Abs(go.World.Scale);
            float radius = Float(go, mb, RuntimeScripts.SphereObstacle, "radius", 0.5f);
            var parents = go.SelfAndAncestors.Skip(1).Select(g => g.Name).ToList();
            string note = RigidSphere.WorldRadiusNote(radius, MathF.Max(s.X, MathF.Max(s.Y, s.Z)), parents);
            return note.Length == 0 ? "" : " " + note;
        }

        /// <summary>A message about a world-space placement, at the line of the GameObject's own Transform field. The value
        /// the message quotes is the world one, so a GameObject under others names them: the field to change may be theirs.</summary>
        string Placed(UnityGameObject go, string transformField, ValidationError error)
        {
            string key = transformField.Substring(transformField.IndexOf('.') + 1);
            var parents = go.SelfAndAncestors.Skip(1).Select(g => $"'{g.Name}'").ToList();
            string under = parents.Count == 0 ? "" : $" (in the world, under {string.Join(", ", parents)}, whose Transforms count too)";
            return $"{At(go.Transform?.Root[key], go.Transform ?? go.Document)}: GameObject '{go.Name}', {transformField}{under}: {error.Rule}";
        }

        static string? TransformField(string member) => member switch
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
