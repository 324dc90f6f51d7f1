using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using SphFluid.UnityFiles.Assets;
using SphFluid.UnityFiles.Scenes;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Headless.Scenes;

/// <summary>What the scene's instances are built from: each prefab read once (<see cref="PrefabReader"/>), for what it
/// holds, and built only where the fluid needs it.</summary>
public static partial class PrefabInstances
{
    /// <summary>
    /// What the reader knows of one prefab from reading it and the prefabs it nests: <see cref="Held"/> names the fluid's
    /// components in them; <see cref="Unreadable"/> says why a file of them could not be read, <see cref="NotBuilt"/> why
    /// they cannot be built. <see cref="Contents"/> is set once the prefab is built (<see cref="PrefabReader.Build"/>),
    /// which only a prefab the fluid needs is: a prop's is read for what it holds and left as it stands.
    /// </summary>
    sealed class Prefab
    {
        long? _rootObject;

        public Prefab(string path, string? guid, UnityYamlFile? raw, List<string> held, string? unreadable, string? notBuilt)
        {
            Path = path;
            Guid = guid;
            Raw = raw;
            Held = held;
            Unreadable = unreadable;
            NotBuilt = notBuilt;
        }

        public string Path { get; }
        public string? Guid { get; }
        /// <summary>The prefab's own file as read, its nested instances not built; null where it could not be read.</summary>
        public UnityYamlFile? Raw { get; }
        public List<string> Held { get; }
        public string? Unreadable { get; }
        public string? NotBuilt { get; set; }
        public PrefabContents? Contents { get; set; }

        /// <summary>The prefab's root GameObject: the built one's, else the one its own file holds (0 for a variant's,
        /// whose root is its base's).</summary>
        public long RootObject => Contents?.RootObject ?? (_rootObject ??= Raw == null ? 0
            : new UnityScene(Raw).RootTransforms.FirstOrDefault()?.GameObject?.FileId ?? 0);
    }

    /// <summary>A prefab built: its objects with every prefab it nests built in (its own fileIDs, as its instances'
    /// overrides name them); <see cref="Sources"/> are the files it is built from, for the integrity check;
    /// <see cref="UnusedOverrides"/> are what its nested instances override that Unity cannot apply.</summary>
    sealed record PrefabContents(UnityYamlFile File, long RootObject, long RootTransform,
        IReadOnlyList<(string Path, UnityYamlFile Yaml)> Sources, List<string> UnusedOverrides);

    /// <summary>Reads prefabs, each once per scene (a scene may hold a prop's instance hundreds of times), and builds those
    /// the fluid needs, the prefabs they nest first.</summary>
    sealed class PrefabReader
    {
        /// <summary>The objects one scene's prefabs may build, every level of nesting counted: about twice what the
        /// largest scene file the reader takes holds (<see cref="UnityTextFile.MaxBytes"/>, some 600 bytes an object); a run
        /// that built 100 000 held 720 MB. Nesting multiplies: a prefab holding two instances of one holding two, twenty levels down,
        /// is a million copies of the innermost, and a chain of 2 000 nested prefabs built 4 million objects in nearly
        /// 5 minutes.</summary>
        public const int MaxBuiltObjects = 50_000;

        /// <summary>Prefabs nested within prefabs, levels deep: each level is read within the one above it, and a chain of
        /// 20 000 exhausted the stack and ended the program. Unity sets no such limit; its users nest a few levels.</summary>
        public const int MaxNestingDepth = 64;

        readonly string _scenePath;
        readonly UnityProject _project;
        readonly Dictionary<string, Prefab> _read = new(StringComparer.Ordinal);
        readonly HashSet<string> _reading = new(StringComparer.Ordinal);
        int _built;

        public PrefabReader(string scenePath, UnityProject project, IReadOnlyDictionary<string, string> scripts)
        {
            _scenePath = scenePath;
            _project = project;
            Scripts = scripts;
        }

        /// <summary>The fluid's script names by the guid of their .cs.meta.</summary>
        public IReadOnlyDictionary<string, string> Scripts { get; }

        /// <summary>Counts <paramref name="objects"/> built from <paramref name="prefab"/> into <paramref name="into"/>
        /// against <see cref="MaxBuiltObjects"/>, refusing the scene past it.</summary>
        public void CountBuilt(int objects, string prefab, string into)
        {
            _built += objects;
            if (_built > MaxBuiltObjects)
                throw new SceneException($"{_scenePath}: its prefab instances build more than {MaxBuiltObjects} objects, every level of " +
                    $"nesting counted (the count passed it building {prefab} into {into}); the reader refuses prefabs nested that deep " +
                    $"or that many times over, as it refuses a scene file over {UnityTextFile.MaxBytes >> 20} MiB");
        }

        public Prefab Get(string path)
        {
            if (_read.TryGetValue(path, out var prefab)) return prefab;
            // Unity refuses a prefab that nests itself; following it would not end.
            if (!_reading.Add(path))
                return new Prefab(path, _project.GuidOf(path), null, new List<string>(), $"{path} nests itself", null);
            if (_reading.Count > MaxNestingDepth)
                throw new SceneException($"{_scenePath}: its prefab instances nest prefabs more than {MaxNestingDepth} levels deep " +
                    $"({path} at level {_reading.Count}); the reader refuses nesting that deep");
            try { prefab = Read(path); }
            finally { _reading.Remove(path); }
            return _read[path] = prefab;
        }

        Prefab Read(string path)
        {
            string? guid = _project.GuidOf(path);
            // A model (.fbx) stands in as a prefab too; its objects come from its importer, and it holds no scripts.
            if (!path.EndsWith(".prefab", StringComparison.OrdinalIgnoreCase))
                return new Prefab(path, guid, null, new List<string>(), null, IsModel(path)
                    ? $"{path} is a model, whose objects come from its importer, not from YAML"
                    : $"{path} is neither a prefab nor a model, so no objects can be built from it");
            UnityYamlFile raw;
            try { raw = UnityYamlFile.Load(_project.FullPath(path)); }
            catch (Exception e) when (e is FormatException or IOException or UnauthorizedAccessException)
            {
                return new Prefab(path, guid, null, new List<string>(), e.Message, null);
            }

            var held = new List<string>();
            foreach (var behaviour in raw.OfClass(UnityScene.MonoBehaviourClassId))
                if (!behaviour.IsStripped && behaviour.ScriptGuid is { } script && Scripts.TryGetValue(script, out string? name))
                    held.Add($"a {name} on its GameObject '{raw.Find(behaviour.GameObject)?.Root.GetString("m_Name", "") ?? ""}'");
            string? unreadable = null, notBuilt = null;
            foreach (var nested in raw.OfClass(UnityScene.PrefabInstanceClassId))
            {
                string? innerPath = _project.AssetPathOf(nested.Root.GetReference("m_SourcePrefab"));
                if (innerPath == null)
                {
                    notBuilt ??= $"{path}: its PrefabInstance &{nested.FileId} (line {nested.Line}) names a prefab no .meta of the project has";
                    continue;
                }
                var inner = Get(innerPath);
                held.AddRange(inner.Held.Select(h => h.EndsWith(", nested in it)", StringComparison.Ordinal) ? h : $"{h} (in {innerPath}, nested in it)"));
                if (inner.Unreadable != null) unreadable ??= inner.Unreadable;
                else if (inner.NotBuilt != null) notBuilt ??= inner.NotBuilt;
            }
            return new Prefab(path, guid, raw, held, unreadable, notBuilt);
        }

        /// <summary>Builds the prefab, the prefabs it nests first; null where it cannot be built, and then
        /// <see cref="Prefab.NotBuilt"/> (or <see cref="Prefab.Unreadable"/>) says why.</summary>
        public PrefabContents? Build(Prefab prefab)
        {
            if (prefab.Contents != null) return prefab.Contents;
            if (prefab.Raw is not { } raw || prefab.Unreadable != null || prefab.NotBuilt != null) return null;
            var documents = raw.Documents.Where(d => !d.IsStripped && d.ClassId != UnityScene.PrefabInstanceClassId).ToList();
            var sources = new List<(string, UnityYamlFile)> { (_project.FullPath(prefab.Path), raw) };
            var unused = new List<string>();
            var taken = new HashSet<long>(raw.Documents.Select(d => d.FileId));
            var standIns = StandIns(raw);
            foreach (var nested in raw.OfClass(UnityScene.PrefabInstanceClassId))
            {
                // Read found every nested prefab's path and readable (the prefab would be NotBuilt otherwise); the
                // nesting is no deeper than Get allows.
                var inner = Get(_project.AssetPathOf(nested.Root.GetReference("m_SourcePrefab"))!);
                if (Build(inner) is not { } contents)
                {
                    prefab.NotBuilt = inner.NotBuilt ?? inner.Unreadable;
                    return null;
                }
                documents.AddRange(Instantiate(prefab.Path, standIns, nested, inner, this, taken, unused));
                sources.AddRange(contents.Sources);
                unused.AddRange(contents.UnusedOverrides);
            }
            // A stand-in that no object was built for would leave what refers to it (a component added to a nested
            // instance's GameObject) on nothing.
            var builtIds = new HashSet<long>(documents.Select(d => d.FileId));
            if (raw.Documents.FirstOrDefault(d => d.IsStripped && !builtIds.Contains(d.FileId)) is { } orphan)
            {
                prefab.NotBuilt = $"{prefab.Path}: its stand-in &{orphan.FileId} (line {orphan.Line}) stands for no object of the prefabs it nests";
                return null;
            }

            var file = new UnityYamlFile(_project.FullPath(prefab.Path), raw.Headers, documents);
            var root = new UnityScene(file).RootTransforms.FirstOrDefault();
            return prefab.Contents = new PrefabContents(file, root?.GameObject?.FileId ?? 0, root?.FileId ?? 0, sources, unused);
        }

        /// <summary>Whether Unity imports the asset as a model (its .meta says ModelImporter).</summary>
        bool IsModel(string path)
        {
            try { return UnityMeta.Load(_project.FullPath(path) + ".meta").ImporterType == "ModelImporter"; }
            catch (Exception e) when (e is FormatException or IOException or UnauthorizedAccessException) { return false; }
        }
    }
}
