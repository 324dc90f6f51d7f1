using System;
using System.Collections.Generic;
using SphFluid.Simulation;
using Unity.Mathematics;
using UnityEngine;
using UnityEngine.Rendering;

namespace SphFluid.Runtime
{
    /// <summary>
    /// The SPH fluid of a scene. On enable it gathers the scene's <see cref="SpawnBox"/>es, its
    /// <see cref="FluidContainer"/> and <see cref="SphereObstacle"/>s into an engine-free scene description and
    /// starts a <see cref="FluidSimulation"/> (the same pipeline the headless runner drives); every frame it
    /// pushes the container's and obstacles' motion, steps, and draws the particles with one procedural call.
    /// GPU resources live exactly from OnEnable to OnDisable; nothing static holds them.
    /// </summary>
    [DefaultExecutionOrder(100)] // after whatever moves the container or the spheres this frame
    [DisallowMultipleComponent]
    public sealed class Fluid : MonoBehaviour
    {
        /// <summary>One press of single-step advances this much simulated time, s.</summary>
        public const float SingleStepSeconds = 1f / 60f;

        /// <summary>Fastest wall or sphere motion passed on, m/s and rad/s.</summary>
        const float MaxWallSpeed = 50f, MaxWallSpin = 50f;

        [Header("Rendering")]
        [SerializeField, Range(0.25f, 3f), Tooltip("Drawn particle radius in half particle spacings (1 = spheres just touching).")]
        float particleRadiusScale = 1.2f;

        [Header("Scene")]
        [SerializeField, Tooltip("The box the fluid lives in; empty = the scene's FluidContainer.")]
        FluidContainer container = null;

        [SerializeField, Tooltip("The solver's settings; each field's range, unit and meaning are declared once, in FluidSettings.")]
        FluidSettings settings = new FluidSettings();

        [Header("Time stepping")]
        [SerializeField, Range(0.001f, 0.1f), Tooltip("Longest frame simulated, s: a slower frame (a hitch, the editor) is simulated as this long.")]
        float maxFrameTime = 1f / 30f;

        [Header("Diagnostics")]
        [SerializeField, Tooltip("Read back mass, energy, density error per phase... asynchronously every frame (for the readout).")]
        bool requestDiagnostics = true;

        UnityComputeDevice _device;
        FluidSimulation _simulation;
        MaterialPropertyBlock _properties;
        FluidResources _resources; // the package's shaders and material (Resources), found at start
        Material _universalMaterial; // the particle material's values on the URP shader, made on the first URP frame
        bool _pipelineWarned;
        FluidContainer _container;
        readonly List<SphereObstacle> _obstacles = new List<SphereObstacle>();
        readonly List<Vector3> _obstaclePositions = new List<Vector3>();
        // Refilled every frame, never remade: the per-frame push is free of garbage (the simulation copies what changed).
        readonly ContainerDescription _containerDescription = new ContainerDescription();
        readonly List<RigidSphere> _obstacleRows = new List<RigidSphere>();
        readonly List<RigidSphere> _obstacleDescriptions = new List<RigidSphere>();
        Vector3 _containerPosition;
        Quaternion _containerRotation;
        bool _paused, _stepRequested;
        string _failure, _lastMotionError;
        HealthCheck _health;
        HealthProblem _healthProblem;
        double _lastCheckedTime = double.NaN;
        SolveCutOffs _cutOffs;
        bool _cutOffsWarned;

        // ------------------------------------------------------------------ read-only state

        /// <summary>True while a simulation runs (enabled, valid scene, GPU resources alive).</summary>
        public bool IsRunning => _simulation != null;

        /// <summary>Why no simulation runs, or null.</summary>
        public string FailureReason => _failure;

        public bool IsPaused => _paused;

        /// <summary>The first problem the health check found since start or reset (the simulator paused on it), or null.</summary>
        public HealthProblem HealthProblem => _healthProblem;

        public int ParticleCount => _simulation != null ? _simulation.ParticleCount : 0;

        public StepReport LastStep => _simulation != null ? _simulation.LastStep : StepReport.None;

        public SimulationPlan Plan => _simulation?.Plan;

        public double SimulatedTime => _simulation != null ? _simulation.SimulatedTime : 0.0;

        /// <summary>
        /// Simulated seconds this frame's Update advances: the frame time capped at the longest frame simulated, one
        /// <see cref="SingleStepSeconds"/> after <see cref="StepOnce"/>, 0 while paused or not running; it simulates less
        /// when the sub-step cap binds (<see cref="LastStep"/>). A law of motion (<see cref="ContainerSpinner"/>,
        /// <see cref="SphereDriver"/>) reads it from an Update that runs before the fluid's to place its Transform where
        /// the fluid will stand after the frame (<see cref="FluidClock"/>).
        /// </summary>
        public float FrameSeconds
        {
            get
            {
                if (_simulation == null || (_paused && !_stepRequested)) return 0f;
                return _stepRequested ? SingleStepSeconds : Mathf.Min(Time.deltaTime, maxFrameTime);
            }
        }

        /// <summary>Latest asynchronous diagnostics (a frame or two stale), or null.</summary>
        public DiagnosticsReport LatestDiagnostics => _simulation?.LatestDiagnostics;

        public IReadOnlyList<PhaseDescription> Phases => _simulation?.Phases;

        /// <summary>Drawn particle radius, m.</summary>
        public float ParticleRadius => 0.5f * settings.ParticleSpacing * particleRadiusScale;

        /// <summary>The running simulation (tests and tools); null when not running.</summary>
        public FluidSimulation Simulation => _simulation;

        /// <summary>The device of the running simulation (tests count its live buffers); null when not running.</summary>
        public UnityComputeDevice Device => _device;

        /// <summary>GPU time of the solver passes over a recent frame, ms; false where the platform cannot time them.</summary>
        public bool TryGetGpuMilliseconds(out double milliseconds)
        {
            milliseconds = 0;
            if (_device == null) return false;
            bool any = false;
            IReadOnlyList<string> passes = FluidSimulation.SampleNames;
            for (int i = 0; i < passes.Count; i++) // not foreach: an interface's enumerator is garbage on every call
            {
                string pass = passes[i];
                if (pass == PassNames.Diagnostics) continue;
                if (_device.TryGetSampleMilliseconds(pass, out double ms))
                {
                    milliseconds += ms;
                    any = true;
                }
            }
            return any;
        }

        // ------------------------------------------------------------------ controls

        public void Pause() => _paused = true;

        public void Resume() => _paused = false;

        public void TogglePause() => _paused = !_paused;

        /// <summary>Pauses and advances exactly one frame of <see cref="SingleStepSeconds"/>.</summary>
        public void StepOnce()
        {
            _paused = true;
            _stepRequested = true;
        }

        /// <summary>Respawns from the components as they are now (edited spawn boxes, settings and all).</summary>
        public void ResetSimulation()
        {
            Shutdown();
            if (isActiveAndEnabled) Startup();
        }

        // ------------------------------------------------------------------ description

        /// <summary>The inspector's settings, for scripts; a change takes effect at the next <see cref="ResetSimulation"/>.</summary>
        public FluidSettings Settings => settings;

        /// <summary>A copy of the inspector's settings: the running simulation keeps its own.</summary>
        public FluidSettings DescribeSettings() => settings.Clone();

        /// <summary>The fluid a driver follows: <paramref name="assigned"/>, else the scene's (null: none).</summary>
        internal static Fluid AssignedOrFound(Fluid assigned) => assigned != null ? assigned : FindFirstObjectByType<Fluid>();

        /// <summary>The container this simulator uses: the assigned one, else the scene's.</summary>
        public FluidContainer FindContainer() => container != null ? container : FindFirstObjectByType<FluidContainer>();

        /// <summary>The scene as the core sees it: settings, every active SpawnBox and SphereObstacle, the container (or null).</summary>
        public FluidSceneDescription DescribeScene()
        {
            var scene = new FluidSceneDescription { Settings = DescribeSettings() };
            FluidContainer box = FindContainer();
            scene.Container = box != null ? box.Describe() : null;
            foreach (SpawnBox spawn in FindObjectsByType<SpawnBox>(FindObjectsSortMode.InstanceID))
                if (IsLive(spawn)) scene.SpawnBoxes.Add(spawn.Describe());
            foreach (SphereObstacle sphere in ActiveObstacles())
                scene.Obstacles.Add(sphere.Describe(Vector3.zero));
            return scene;
        }

        /// <summary>The core's refusals of the settings fields.</summary>
        public IReadOnlyList<ValidationError> ValidationErrors() => ComponentValidation.SettingsErrors(DescribeSettings());

        static List<SphereObstacle> ActiveObstacles()
        {
            var list = new List<SphereObstacle>();
            foreach (SphereObstacle sphere in FindObjectsByType<SphereObstacle>(FindObjectsSortMode.InstanceID))
                if (IsLive(sphere)) list.Add(sphere);
            return list;
        }

        /// <summary>Enabled on an active GameObject. Not isActiveAndEnabled: that turns true only once the component's
        /// OnEnable has run, which during a scene load may come after this simulator's, and never in edit mode.</summary>
        static bool IsLive(Behaviour behaviour) => behaviour.enabled && behaviour.gameObject.activeInHierarchy;

        // ------------------------------------------------------------------ lifetime

        void OnEnable() => Startup();

        void OnDisable() => Shutdown();

        void OnDestroy() => Shutdown();

        void OnValidate() => ComponentValidation.Log(ValidationErrors(), this);

        void Startup()
        {
            _failure = null;
            _lastMotionError = null;
            if (!SystemInfo.supportsComputeShaders)
            {
                Fail("this graphics device has no compute shaders");
                return;
            }
            _resources = FluidResources.Load();
            if (_resources == null)
            {
                Fail($"the package's Resources/{FluidResources.ResourceName}.asset is missing; reinstall com.sphfluid.fluid");
                return;
            }
            string missing = _resources.MissingField();
            if (missing != null)
            {
                Fail($"{FluidResources.ResourceName}.asset has no '{missing}' assigned (Packages/com.sphfluid.fluid/Runtime/Resources)");
                return;
            }
            _container = FindContainer();
            if (_container == null)
            {
                Fail("the scene has no FluidContainer (assign field 'container')");
                return;
            }

            FluidSceneDescription scene = DescribeScene();
            IReadOnlyList<ValidationError> errors = scene.Validate();
            if (errors.Count > 0)
            {
                foreach (ValidationError e in errors)
                    Debug.LogError($"Fluid '{name}': {e.Message} [{e.Field}]", this);
                Fail($"{errors.Count} invalid value(s) in the scene, listed in the Console; the simulation did not start");
                return;
            }

            _device = new UnityComputeDevice(_resources.ComputeShaders());
            try
            {
                // A player frame must never wait on the GPU: plan from asynchronous read-backs.
                _simulation = new FluidSimulation(_device, scene) { ReproducibleStepPlanning = false };
            }
            catch (Exception e)
            {
                Debug.LogException(e, this);
                Shutdown();
                Fail(e.Message);
                return;
            }

            _health = new HealthCheck(scene, _simulation.ParticleCount);
            _cutOffs = new SolveCutOffs();
            _cutOffsWarned = false;
            _properties = new MaterialPropertyBlock();
            _containerPosition = _container.transform.position;
            _containerRotation = _container.transform.rotation;
            _obstacles.Clear();
            _obstacles.AddRange(ActiveObstacles());
            _obstaclePositions.Clear();
            _obstacleRows.Clear();
            foreach (SphereObstacle sphere in _obstacles)
            {
                _obstaclePositions.Add(sphere.transform.position);
                _obstacleRows.Add(sphere.Describe(Vector3.zero)); // its Name is read here, once
            }
        }

        void Fail(string reason)
        {
            _failure = reason;
            Debug.LogError($"Fluid '{name}': {reason}", this);
        }

        void Shutdown()
        {
            if (_healthProblem != null) _paused = false; // the pause was the health check's; a new start is healthy
            _health = null;
            _healthProblem = null;
            _lastCheckedTime = double.NaN;
            _cutOffs = null;
            _simulation?.Dispose();
            _simulation = null;
            _device?.Dispose(); // releases any buffer the simulation did not
            _device = null;
            if (_universalMaterial != null) Destroy(_universalMaterial);
            _universalMaterial = null;
            _pipelineWarned = false;
            _obstacles.Clear();
            _obstaclePositions.Clear();
            _obstacleRows.Clear();
            _obstacleDescriptions.Clear();
        }

        // ------------------------------------------------------------------ per frame

        void Update()
        {
            if (_simulation == null) return;
            bool advance = !_paused || _stepRequested;
            float frame = FrameSeconds;
            _stepRequested = false;

            // Walls and spheres go where their Transforms stand now, with the velocity that brought them there over the
            // simulated frame: the simulation sweeps them there from where the last frame left them.
            float motionSeconds = advance ? frame : Time.deltaTime;
            try
            {
                PushContainer(motionSeconds);
                PushObstacles(motionSeconds);
                _lastMotionError = null;
            }
            catch (ArgumentException e)
            {
                if (e.Message != _lastMotionError) Debug.LogError($"Fluid '{name}': {e.Message}", this);
                _lastMotionError = e.Message;
            }

            _health.ObserveDrivers(_simulation.Scene.Container, _simulation.Scene.Obstacles);
            try
            {
                if (frame > 0f) _simulation.Step(frame);
                if (requestDiagnostics) _simulation.RequestDiagnostics();
                DiagnosticsReport report = _simulation.LatestDiagnostics;
                if (report != null && report.SimulatedTime != _lastCheckedTime) CheckHealth(report);
            }
            catch (Exception e)
            {
                Debug.LogException(e, this);
                Shutdown();
                Fail("the simulation stopped: " + e.Message);
                return;
            }
            Draw();
        }

        /// <summary>Checks one diagnostics report (each arriving one, from Update; tests pass a made-up one): the
        /// first problem pauses the simulation and is logged once. Nothing is checked after it until a reset.</summary>
        internal void CheckHealth(DiagnosticsReport report)
        {
            if (_health == null || _healthProblem != null || report == null) return;
            _lastCheckedTime = report.SimulatedTime;
            HealthProblem problem = _health.Check(report);
            WarnOfCutOffSolves(report);
            if (problem == null) return;
            _healthProblem = problem;
            _paused = true;
            Debug.LogError($"Fluid '{name}': {problem.Message}; paused (Reset respawns)", this);
        }

        /// <summary>Logs once per start when DFSPH's solves ran out of iterations in more than a tenth of the time since,
        /// once a second of it has been seen (a settling start alone does not speak): a healthy run, but one whose error
        /// stands above the tolerance it asked for, which nothing else in the package shows.</summary>
        void WarnOfCutOffSolves(DiagnosticsReport report)
        {
            if (_cutOffs == null || _cutOffsWarned) return;
            _cutOffs.Observe(report);
            if (_cutOffs.ObservedSeconds < 1.0 || !(_cutOffs.Warning(_simulation.Scene.Settings) is string warning)) return;
            _cutOffsWarned = true;
            Debug.LogWarning($"Fluid '{name}': {warning}", this);
        }

        void PushContainer(float seconds)
        {
            if (_container == null) return;
            Transform t = _container.transform;
            Vector3 position = t.position;
            Quaternion rotation = t.rotation;
            ContainerDescription description = _container.DescribeInto(_containerDescription);
            description.Velocity = System.Numerics.Vector3.Zero;
            description.AngularVelocity = System.Numerics.Vector3.Zero;
            if (seconds > 0f)
            {
                // A teleport (editing the Transform) is not a motion the walls should fling fluid with.
                description.Velocity = Vector3.ClampMagnitude((position - _containerPosition) / seconds, MaxWallSpeed).ToNumerics();
                description.AngularVelocity = Vector3.ClampMagnitude(AngularVelocity(_containerRotation, rotation) / seconds, MaxWallSpin).ToNumerics();
            }
            _containerPosition = position;
            _containerRotation = rotation;
            _simulation.UpdateContainer(description);
        }

        /// <summary>Rotation from <paramref name="from"/> to <paramref name="to"/> as axis times angle, rad (shortest way).</summary>
        static Vector3 AngularVelocity(Quaternion from, Quaternion to)
        {
            // The quaternion logarithm of the frame-to-frame turn is half its rotation vector; q and -q are the same
            // turn, so the short way round is the one with w >= 0.
            quaternion delta = math.mul(to, math.inverse(from));
            if (delta.value.w < 0f) delta.value = -delta.value;
            float3 rotation = 2f * math.log(delta).value.xyz;
            return math.all(math.isfinite(rotation)) ? (Vector3)rotation : Vector3.zero; // no turn: log is 0/0
        }

        void PushObstacles(float seconds)
        {
            if (_obstacles.Count == 0) return;
            _obstacleDescriptions.Clear();
            for (int i = 0; i < _obstacles.Count; i++)
            {
                SphereObstacle sphere = _obstacles[i];
                if (sphere == null) continue; // destroyed while running: it simply stops pushing
                Vector3 position = sphere.transform.position;
                Vector3 velocity = seconds > 0f ? Vector3.ClampMagnitude((position - _obstaclePositions[i]) / seconds, MaxWallSpeed) : Vector3.zero;
                _obstaclePositions[i] = position;
                _obstacleDescriptions.Add(sphere.DescribeInto(_obstacleRows[i], velocity));
            }
            _simulation.UpdateObstacles(_obstacleDescriptions);
        }

        void Draw()
        {
            Material material = MaterialForPipeline();
            if (material == null || _container == null) return;
            var particles = (UnityComputeBuffer)_simulation.Particles; // alternates every sort: fetch each frame
            var phases = (UnityComputeBuffer)_simulation.PhaseTable;
            _properties.SetBuffer(ShaderIds.Particles, particles.Buffer);
            _properties.SetBuffer(ShaderIds.Phases, phases.Buffer);
            _properties.SetFloat(ShaderIds.ParticleRadius, ParticleRadius);

            Transform box = _container.transform;
            float reach = box.lossyScale.magnitude + 4f * ParticleRadius; // any rotation of the box fits
            var parameters = new RenderParams(material)
            {
                worldBounds = new Bounds(box.position, new Vector3(reach, reach, reach)),
                matProps = _properties,
                layer = gameObject.layer,
                shadowCastingMode = ShadowCastingMode.Off,
                receiveShadows = false,
            };
            Graphics.RenderPrimitives(parameters, MeshTopology.Triangles, 6, _simulation.ParticleCount);
        }

        /// <summary>
        /// The material for the active render pipeline: the resources' particle material itself in the Built-in
        /// pipeline (no pipeline asset), a copy of its values on the URP particle shader in URP, null (not drawn, one
        /// warning) for any other pipeline. Asked every frame: the pipeline asset may change with the quality level.
        /// </summary>
        Material MaterialForPipeline()
        {
            Material particleMaterial = _resources.ParticleMaterial;
            RenderPipelineAsset pipeline = GraphicsSettings.currentRenderPipeline;
            if (pipeline == null) return particleMaterial;
            if (pipeline.renderPipelineShaderTag != UniversalPipelineTag)
            {
                if (!_pipelineWarned)
                    Debug.LogWarning($"Fluid '{name}': render pipeline '{pipeline.name}' (shader tag '{pipeline.renderPipelineShaderTag}') is neither Built-in nor URP ('{UniversalPipelineTag}'); the fluid is simulated but not drawn", this);
                _pipelineWarned = true;
                return null;
            }
            if (_universalMaterial == null)
            {
                _universalMaterial = new Material(_resources.UniversalParticleShader) { name = particleMaterial.name + " (URP)", hideFlags = HideFlags.DontSave };
                string missing = UniversalOpaqueTexture.MissingReason(pipeline, Camera.main);
                if (missing != null)
                    Debug.LogWarning($"Fluid '{name}': {missing}; the liquid shows no scene behind it", this);
            }
            _universalMaterial.CopyPropertiesFromMaterial(particleMaterial); // inspector edits of the material carry over
            return _universalMaterial;
        }

        /// <summary>The "RenderPipeline" SubShader tag URP's asset reports; FluidParticlesUniversal.shader carries it.</summary>
        const string UniversalPipelineTag = "UniversalPipeline";

        /// <summary>Material property ids, looked up once (on first use, on the main thread).</summary>
        static class ShaderIds
        {
            public static readonly int Particles = Shader.PropertyToID("_Particles");
            public static readonly int Phases = Shader.PropertyToID("_Phases");
            public static readonly int ParticleRadius = Shader.PropertyToID("_ParticleRadius");
        }
    }
}
