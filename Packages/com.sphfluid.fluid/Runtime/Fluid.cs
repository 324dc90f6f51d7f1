using System;
using System.Collections.Generic;
using SphFluid.Simulation;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// The SPH fluid of a scene. On enable it gathers the scene's <see cref="SpawnBox"/>es, its
    /// <see cref="FluidContainer"/> and <see cref="SphereObstacle"/>s into an engine-free scene description and
    /// starts a <see cref="FluidSimulation"/> (the same pipeline the headless runner drives); every frame it
    /// pushes the container's and obstacles' motion and steps, and every camera that renders draws the particles
    /// with one procedural call (<see cref="ParticleDrawing"/>), a paused editor's views too.
    /// GPU resources live exactly from OnEnable to OnDisable; nothing static holds them or the fluid after it.
    /// </summary>
    [AddComponentMenu("SPH Fluid/Fluid")]
    [DefaultExecutionOrder(100)] // after whatever moves the container or the spheres this frame
    [DisallowMultipleComponent]
    public sealed class Fluid : MonoBehaviour
    {
        /// <summary>One press of single-step advances this much simulated time, s.</summary>
        public const float SingleStepSeconds = 1f / 60f;

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
        FluidResources _resources; // the package's shaders and material (Resources), found at start
        FluidContainer _container;
        BoundaryMotion _motion;
        ParticleDrawing _drawing;
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
            FluidSceneDescription scene = DescribeSurroundings();
            foreach (SpawnBox spawn in FindObjectsByType<SpawnBox>(FindObjectsSortMode.InstanceID))
                if (IsLive(spawn)) scene.SpawnBoxes.Add(spawn.Describe());
            return scene;
        }

        /// <summary><see cref="DescribeScene"/> without its spawn boxes: all that one box's spawned count needs
        /// (<see cref="SpawnLayout.SpawnedCount"/>), without describing every other box for each.</summary>
        internal FluidSceneDescription DescribeSurroundings()
        {
            var scene = new FluidSceneDescription { Settings = DescribeSettings() };
            FluidContainer box = FindContainer();
            scene.Container = box != null ? box.Describe() : null;
            foreach (SphereObstacle sphere in ActiveObstacles())
                scene.Obstacles.Add(sphere.Describe(Vector3.zero));
            return scene;
        }

        /// <summary>The core's refusals of the settings fields.</summary>
        public IReadOnlyList<ValidationError> ValidationErrors() => ComponentValidation.SettingsErrors(DescribeSettings());

        /// <summary>How the world radius that a sphere's refusal quotes comes from its field; the scene's Obstacles[i] is
        /// the i-th of <paramref name="spheres"/>, as <see cref="DescribeScene"/> lists them.</summary>
        static string SphereRadiusNote(ValidationError e, List<SphereObstacle> spheres)
        {
            for (int i = 0; i < spheres.Count; i++)
                if (e.Field == $"Obstacles[{i}].{nameof(RigidSphere.Radius)}" && spheres[i].WorldRadiusNote() is { Length: > 0 } note)
                    return " " + note;
            return "";
        }

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
                List<SphereObstacle> spheres = ActiveObstacles();
                foreach (ValidationError e in errors)
                    Debug.LogError($"Fluid '{name}': {e.Message} [{e.Field}{SphereRadiusNote(e, spheres)}]", this);
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

            if (FreeVolume.Warning(scene) is string crowded) Debug.LogWarning($"Fluid '{name}': {crowded}", this);
            _health = new HealthCheck(scene, _simulation.ParticleCount);
            _cutOffs = new SolveCutOffs();
            _cutOffsWarned = false;
            _motion = new BoundaryMotion(_container, ActiveObstacles());
            _drawing = new ParticleDrawing(_resources, this, _container.transform);
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
            _drawing?.Dispose();
            _drawing = null;
            _motion = null;
        }

        // ------------------------------------------------------------------ per frame

        void Update()
        {
            if (_simulation == null) return;
            bool advance = !_paused || _stepRequested;
            float frame = FrameSeconds;
            _stepRequested = false;

            // Paused, the walls and spheres still follow their Transforms (their velocities over the wall-clock frame), so
            // that a resumed run sweeps them on from where they stand, not from where the pause found them.
            try
            {
                _motion.Push(_simulation, advance ? frame : Time.deltaTime);
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
        /// stands above the tolerance it asked for, which the Console should say though no inspector or readout is open.</summary>
        void WarnOfCutOffSolves(DiagnosticsReport report)
        {
            if (_cutOffs == null || _cutOffsWarned) return;
            _cutOffs.Observe(report);
            if (_cutOffs.ObservedSeconds < 1.0 || !(_cutOffs.Warning(_simulation.Scene.Settings) is string warning)) return;
            _cutOffsWarned = true;
            Debug.LogWarning($"Fluid '{name}': {warning}", this);
        }
    }
}
