using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Compute;
using SphFluid.Sorting;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The whole SPH pipeline, written once against <see cref="IComputeDevice"/> so that Unity and the
    /// headless backend dispatch the very same kernels in the very same order. One frame, top to bottom,
    /// is <see cref="Step"/>; one sub-step is <see cref="Substep"/>.
    /// </summary>
    /// <remarks>
    /// Concerns kept elsewhere: the solver's kernels in <see cref="SolverKernels"/>, the rounds each DFSPH solve records in
    /// <see cref="SolveBudget"/>, the GPU buffers and their bindings in <see cref="SolverBuffers"/>, the constant buffer
    /// (<see cref="FluidConstants"/>, recorded as one upload when a value changes) in FluidSimulation.Constants.cs, the
    /// motion and diagnostics read-backs in FluidSimulation.Readbacks.cs, and the container and obstacle updates in
    /// FluidSimulation.SceneUpdates.cs.
    /// </remarks>
    public sealed partial class FluidSimulation : IDisposable
    {
        public const string SolverProgramName = "FluidSolver";
        public const string DiagnosticsProgramName = "FluidDiagnostics";
        const int ReductionThreads = 256; // REDUCTION_THREADS in Include/SphTimeStep.hlsl

        /// <summary>alpha_w of the contact damping against boundary particles (SphBoundary.hlsl): Monaghan's artificial
        /// viscosity on the velocity into the wall only. 0.5 brought the clamp hits of a turning container and a driven
        /// sphere to zero without slowing a dam-break front along the floor.</summary>
        public const float WallContactDamping = 0.5f;

        /// <summary>The constant-density solve stops when the density it predicts (delta + dt D delta / Dt, first order in dt)
        /// is within this fraction of the tolerance, so that the density measured after the drift, which the prediction
        /// misses by its second-order part, is within the tolerance itself: at 1.0 a settled tank measured 0.1047 % at a
        /// 0.1 % tolerance, at 0.9 it measures 0.089 % for one more iteration per sub-step (DivergenceFreeTankTests).</summary>
        public const float DensityPredictionMargin = 0.9f;

        /// <summary>xi of delta-SPH's diffusive term (SphDensityDiffusion.hlsl): 0.1, the value Antuono et al. 2010 use throughout.</summary>
        public const double DensityDiffusionXi = 0.1;

        /// <summary>The last-resort clamp surface lies this many particle spacings inside the walls (SphBoundary.hlsl).</summary>
        public const float ClampInset = 0.01f;

        readonly IComputeDevice _device;
        readonly FluidSceneDescription _scene; // the simulation's own copy: container and obstacles change
        readonly PhaseProperties[] _phaseTable;
        readonly IReadOnlyList<PhaseDescription> _phases;
        readonly Particle[] _spawn;
        readonly TimeStepController _timeStep;
        ImplicitViscosity _viscosity; // the sub-steps' implicit viscosity solve, none (0 rounds) while the force is explicit
        readonly double _viscousRowSum; // ImplicitViscosity.LatticeRowSum of the scene's lattice, 1/m^2
        readonly IComputeProgram _solver, _diagnostics;
        readonly SolverKernels _kernels;
        readonly bool _divergenceFree;
        readonly bool _deltaSph; // delta-SPH's continuity density (SphDensityDiffusion.hlsl)
        readonly float[] _spawnNumberDensities;
        readonly int _motionPartial, _motionFinal, _diagnosticsPartial, _diagnosticsFinal;
        readonly int _reductionGroups;

        SolverBuffers _buffers;
        // The constant buffer's contents (Include/FluidConstants.hlsl); an array of one so that the upload allocates nothing.
        readonly FluidConstants[] _constants = new FluidConstants[1];
        bool _constantsChanged = true;
        CellGrid _grid;
        bool _containerChanged = true;
        bool _boundaryMoved = true;
        // DFSPH: the walls were sorted again since the last FindNeighbours, so the neighbour lists and the walls' density and
        // factor (kept per sorted slot) belong to other wall particles; their warm start is kept by boundary id and follows them.
        bool _wallsResorted;
        // The neighbour lists hold the neighbours of the particles and walls where they stand and in their sorted order:
        // found since the last sort, wall placement or shift (FindNeighbours does nothing while this holds).
        bool _neighboursFound;
        // Entries per neighbour list in the buffers (NeighbourCapacity.For); the constants carry it while the passes read
        // the lists (NeighbourCapacity.InUse at the present lanes), 0 while they walk the grid.
        int _listCapacity;
        bool _listsAllowed = true;
        // Walls whose placement this frame came with a velocity (a carried container, a driven sphere) sweep through the
        // frame's sub-steps to that placement, placed again before every sort: their time relative to the placement
        // (negative until the frame's last sub-step brings it to 0), and the container transform they are at, which the
        // grid follows at the next sort (_gridBehind until it has).
        bool _wallsFollowVelocity, _obstaclesMoved, _gridBehind;
        float _wallTime;
        Vector3 _containerPosition;
        Quaternion _containerRotation;
        int _boundaryCount;
        IReadbackRequest _motionReadback, _diagnosticsReadback;
        double _diagnosticsRequestTime;
        readonly Vector4[] _motionRow = new Vector4[2]; // [0] vmax, amax; [1] the DFSPH solves' iterations (SolveBudget.Next)
        readonly int[] _solveRounds = new int[2];       // rounds recorded per solve, by solve slot (SolveBudget.Next)
        // Kept for the simulation's lifetime so that a steady frame makes no garbage (Unity's GC stalls show as hitches).
        readonly int[] _diagnosticsKernels;
        readonly Obstacle[] _obstacleRows = new Obstacle[FluidSceneDescription.MaxObstacles];
        readonly Vector4[] _diagnosticsRows;
        readonly SimulationPlan[] _plans = new SimulationPlan[2]; // [container unchanged, container moved]
        DiagnosticsReport _latestDiagnostics, _diagnosticsReport;
        readonly FluidSceneDescription _containerProbe = new FluidSceneDescription();
        readonly List<ValidationError> _containerErrors = new List<ValidationError>();
        readonly List<ValidationError> _obstacleErrors = new List<ValidationError>();
        string[,] _obstacleNames; // [sphere, 0] owner and [sphere, 1] path in messages, made for _obstacleNamesFor
        List<RigidSphere> _obstacleNamesFor;
        PhaseDiagnostics[] _diagnosticsPhases;
        bool _disposed;

        /// <param name="device">The GPU (Unity's command buffer or the headless Vulkan device).</param>
        /// <param name="scene">Validated here: an invalid scene throws <see cref="ArgumentException"/> listing every message.</param>
        public FluidSimulation(IComputeDevice device, FluidSceneDescription scene)
        {
            _device = device ?? throw new ArgumentNullException(nameof(device));
            if (scene == null) throw new ArgumentNullException(nameof(scene));
            scene.ThrowIfInvalid();
            _scene = CopyOf(scene);
            _phases = _scene.Phases();
            _phaseTable = _scene.BuildPhaseTable();
            _spawn = SpawnLayout.Generate(_scene, out double[] spawnPressures);
            CountPhases(_phaseTable, _spawn);
            _spawnNumberDensities = HydrostaticNumberDensities(_spawn, spawnPressures);
            ParticleCount = _spawn.Length;
            if (DeviceCapacity.Problem(ParticleCount, 0, device) is string tooMany)
                throw new ArgumentException("FluidSimulation: " + tooMany, nameof(scene));
            _timeStep = TimeStepController.ForScene(_scene);
            _viscousRowSum = ImplicitViscosity.LatticeRowSum(_scene.Settings.SmoothingKernel, _scene.Settings.ParticleSpacing,
                _scene.Settings.SmoothingRadius);
            if (_scene.Settings.PressureSolver == PressureSolver.Dfsph)
                _timeStep.GravityWaveSpeed = (float)Math.Sqrt(_scene.Settings.Gravity.Length() *
                    SpawnLayout.Depth(_spawn, _scene.Settings.Gravity, _scene.Settings.ParticleSpacing));
            _reductionGroups = (ParticleCount + ReductionThreads - 1) / ReductionThreads;

            _solver = device.LoadProgram(SolverProgramName);
            _diagnostics = device.LoadProgram(DiagnosticsProgramName);
            _kernels = new SolverKernels(_solver);
            _divergenceFree = _scene.Settings.PressureSolver == PressureSolver.Dfsph;
            _deltaSph = !_divergenceFree && _scene.Settings.WcsphDensity == WcsphDensity.DeltaSph;
            _motionPartial = _diagnostics.FindKernel("MotionPartial");
            _motionFinal = _diagnostics.FindKernel("MotionFinal");
            _diagnosticsPartial = _diagnostics.FindKernel("DiagnosticsPartial");
            _diagnosticsFinal = _diagnostics.FindKernel("DiagnosticsFinal");
            _diagnosticsKernels = new[] { _motionPartial, _motionFinal, _diagnosticsPartial, _diagnosticsFinal };
            _diagnosticsRows = new Vector4[3 + _phases.Count];

            try
            {
                _buffers = new SolverBuffers(device, _solver, _kernels.All, _diagnostics, _diagnosticsKernels, ParticleCount, _phaseTable,
                    _reductionGroups, device.PropertyId("FluidConstants"), _spawnNumberDensities);
                RebuildGrid();
                CreateBoundary();
                WriteConstants();
                UploadObstacles();
                if (_divergenceFree) _spawn = SettledSpawn(_spawn);
                Reset();
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        /// <summary>Number of particles (constant: none is ever created or lost).</summary>
        public int ParticleCount { get; }

        /// <summary>The particles (<see cref="Particle"/>), sorted by grid cell. Shader name <c>_Particles</c>.
        /// The buffer object alternates between two after every sort: fetch it each frame.</summary>
        public IComputeBuffer Particles => _buffers.Particles;

        /// <summary>The phase table (<see cref="PhaseProperties"/>), indexed by <see cref="Particle.Phase"/>. Shader name <c>_Phases</c>.</summary>
        public IComputeBuffer PhaseTable => _buffers.Phases;

        /// <summary>Per particle (same order as <see cref="Particles"/>): rho, p, delta, p / delta^2.</summary>
        public IComputeBuffer Densities => _buffers.Densities;

        /// <summary>Per particle: acceleration (xyz) of the last force pass, m/s^2.</summary>
        public IComputeBuffer Accelerations => _buffers.Accelerations;

        /// <summary>Per particle: colour-field normal (xyz) when surface tension is on.</summary>
        public IComputeBuffer Normals => _buffers.Normals;

        /// <summary>Per particle: the local rigid rotation Omega = curl v / 2 (xyz), rad/s, when the viscous stress is the
        /// strain rate's (<see cref="SimulationPlan.StrainRateViscosity"/>).</summary>
        public IComputeBuffer Rotations => _buffers.Rotations;

        /// <summary>Per particle: the velocity change (xyz) the next full step adds, m/s: XSPH's when XSPH is on, plus the
        /// wall contact of a particle below rest density (SphBoundary.hlsl).</summary>
        public IComputeBuffer VelocityCorrections => _buffers.VelocityCorrections;

        /// <summary>DFSPH, by particle id (not sorted): float2 of the q the last constant-density (x) and divergence-free (y)
        /// solves applied in total, the next sub-step's warm start (DivergenceFreeSolver.hlsl).</summary>
        public IComputeBuffer WarmStart => _buffers.WarmStart;

        /// <summary>delta-SPH (WcsphDensity.DeltaSph), by particle id (not sorted): the number density each particle carries, 1/m^3
        /// (SphDensityDiffusion.hlsl). Written before <see cref="ComputeForces"/>, it is the state the forces see.</summary>
        public IComputeBuffer NumberDensities => _buffers.NumberDensities;

        /// <summary>delta-SPH, per particle (same order as <see cref="Particles"/>): float2 of the continuity and the diffusion
        /// term of D delta / Dt at the last sub-step's start (at the current state after <see cref="ComputeForces"/>), 1/(m^3 s).</summary>
        public IComputeBuffer DensityRates => _buffers.DensityRates;

        /// <summary>Per particle: the particle shift (xyz) of the last sub-step when shifting is on, m (ParticleShifting.hlsl).</summary>
        public IComputeBuffer Shifts => _buffers.Shifts;

        /// <summary>DFSPH: the last error pass's sums of its particles' errors, one per phase and thread group, phase-major
        /// (<c>[phase * SolverPartialGroups + group]</c>), which the walls' error pass folds into each phase's average error
        /// to stop the solve (DivergenceFreeConvergence.hlsl's StoreGroupErrors and FoldSolveErrors).</summary>
        public IComputeBuffer SolverPartials => _buffers.SolverPartials;

        /// <summary>Thread groups of a DFSPH error pass, each of which writes one sum per phase to <see cref="SolverPartials"/>:
        /// <see cref="LanesPerParticle"/> threads for each particle.</summary>
        public int SolverPartialGroups => ComputeDispatch.GroupsFor(ParticleCount * LanesPerParticle, ParticleThreads);

        /// <summary>Threads of a group of the solver's particle passes (PARTICLE_THREADS in FluidSolver.compute).</summary>
        public const uint ParticleThreads = 128;

        /// <summary>The boundary particles (<see cref="BoundaryParticle"/>) in world space, sorted by grid cell.</summary>
        public IComputeBuffer BoundaryParticles => _buffers.BoundarySorted;

        /// <summary>DFSPH, per fluid particle (sorted) and then per sorted boundary particle: the neighbours its list holds, fluid
        /// ones in the low 16 bits and wall ones in the high 16, or <see cref="uint.MaxValue"/> for a particle with more than
        /// <see cref="NeighbourListCapacity"/> that walks the grid instead (SphNeighbourhood.hlsl).</summary>
        public IComputeBuffer NeighbourCounts => _buffers.NeighbourCounts;

        /// <summary>The neighbour lists' entries, sorted indices: entry k of owner o (fluid particle i, or
        /// <see cref="ParticleCount"/> + boundary particle b) at k * (ParticleCount + BoundaryCount) + o
        /// (SphNeighbourhood.hlsl).</summary>
        public IComputeBuffer NeighbourLists => _buffers.NeighbourLists;

        /// <summary>Entries of each neighbour list; 0 without lists (WCSPH; see <see cref="Simulation.NeighbourCapacity"/>).</summary>
        public int NeighbourListCapacity => (int)_constants[0].NeighbourCapacity;

        /// <summary>Whether DFSPH's Chebyshev solve accelerates the constant-density solve as well as the divergence-free
        /// one at this tolerance and depth (<see cref="ChebyshevBounds.AcceleratesDensitySolve"/>).</summary>
        public bool AcceleratesDensitySolve => _constants[0].AcceleratedDensitySolve != 0;

        /// <summary>Number of boundary particles (container walls and obstacles).</summary>
        public int BoundaryCount => _boundaryCount;

        /// <summary>Threads per particle in the neighbour loops of density, wall pressure and forces, and of DFSPH's factor,
        /// error and correction passes: <see
        /// cref="NeighbourLanes.For"/> of the particle count and the device, or a count set here (1, 2, 4 or 8; tests
        /// compare them). Results differ only by float rounding.</summary>
        public int LanesPerParticle
        {
            get => (int)_constants[0].NeighbourLanes;
            set
            {
                if (!NeighbourLanes.IsValid(value))
                    throw new ArgumentOutOfRangeException(nameof(value), value, $"lanes per particle must be 1, 2, 4 or 8 (at most {NeighbourLanes.Max})");
                _constants[0].NeighbourLanes = (uint)value;
                _constantsChanged = true;
                UseNeighbourLists();
            }
        }

        /// <summary>The neighbour grid (container-local cells of h / <see cref="CellGrid.CellsPerSupport"/>).</summary>
        public CellGrid Grid => _grid;

        /// <summary>Effects run although the scene does not need them (the benchmark's measure of the planner's savings);
        /// null for none, as every simulation but the benchmark's.</summary>
        public PlanOverrides ForcedEffects
        {
            get => _forcedEffects;
            set
            {
                _forcedEffects = value;
                _plans[0] = _plans[1] = null;
            }
        }

        PlanOverrides _forcedEffects;

        /// <summary>What the last frame ran (variants and passes).</summary>
        public SimulationPlan Plan { get; private set; }

        /// <summary>How the last frame was covered by sub-steps.</summary>
        public StepReport LastStep { get; private set; } = StepReport.None;

        /// <summary>Simulated time since spawn or <see cref="Reset"/>, s.</summary>
        public double SimulatedTime { get; private set; }

        /// <summary>The adaptive time-step state (speed of sound, motion last read back).</summary>
        public TimeStepController TimeStep => _timeStep;

        /// <summary>Phases in phase-table order.</summary>
        public IReadOnlyList<PhaseDescription> Phases => _phases;

        /// <summary>Host copy of the phase table.</summary>
        public IReadOnlyList<PhaseProperties> PhaseRows => _phaseTable;

        /// <summary>The scene as currently simulated (container and obstacles as last updated).</summary>
        public FluidSceneDescription Scene => _scene;

        /// <summary>Names of the GPU timing ranges a frame may record (device.TryGetSampleMilliseconds).</summary>
        public static IReadOnlyList<string> SampleNames { get; } = new[]
        {
            PassNames.UploadContainer, PassNames.PlaceBoundary, PassNames.DensityRate, PassNames.HalfStep, PassNames.HalfKick, PassNames.HalfDrift, PassNames.Sort, PassNames.DensityPressure, PassNames.WallPressure, PassNames.Normals, PassNames.Rotations,
            PassNames.Forces, PassNames.FullStep, PassNames.NonPressureForces, PassNames.PredictVelocity, PassNames.DensitySolve, PassNames.ViscositySolve, PassNames.Drift,
            PassNames.FindNeighbours, PassNames.DensityFactor, PassNames.DivergenceSolve, PassNames.ParticleShift, PassNames.ApplyShift, PassNames.MotionReduction, PassNames.Diagnostics,
        };

        /// <summary>Advances the simulation by one frame of <paramref name="frameSeconds"/> real time, in as
        /// many sub-steps as stability needs (up to MaxSubsteps; see <see cref="LastStep"/>).</summary>
        public StepReport Step(float frameSeconds)
        {
            ThrowIfDisposed();
            if (ReproducibleStepPlanning)
                ReadMotionIntoTimeStep();                           // vmax, amax of the last frame's end, waited for
            else
                PollMotion();                                       // vmax, amax of an earlier frame
            _timeStep.BoundarySpeed = FastestBoundarySpeed();
            StepReport report = _timeStep.PlanFrame(frameSeconds);  // n sub-steps of dt
            BeginFrame(report.SimulatedSeconds);                    // plan, keywords, walls where the frame starts
            for (int s = 0; s < report.Substeps; s++)
                Substep(report.TimeStep);
            if (report.Substeps > 0 && !ReproducibleStepPlanning)
                RequestMotion();                                    // GPU max-reduction, read back async
            _device.Submit();
            SimulatedTime += report.SimulatedSeconds;
            LastStep = report;
            return report;
        }

        /// <summary>
        /// Plan every frame from the motion at the end of the frame before, waiting for its read-back (true, the
        /// default), or from whichever asynchronous read-back has arrived (false). The asynchronous way never stalls a
        /// frame on the GPU, which a real-time player needs (the Unity component turns this off), but when a read-back
        /// arrives depends on timing, so two runs of one scene can take different sub-steps and drift apart. Waiting
        /// makes a run reproducible bit for bit on one device, which the headless runner and the tests rely on.
        /// </summary>
        public bool ReproducibleStepPlanning { get; set; } = true;

        void ReadMotionIntoTimeStep()
        {
            if (LastStep.Substeps == 0) return; // nothing moved since Reset, which read the first force pass already
            ReadMotion(out float maxSpeed, out float maxAcceleration);
            _timeStep.ReportMotion(maxSpeed, maxAcceleration);
        }

        /// <summary>The fastest point of the container's walls or of any obstacle, m/s (no garbage: Unity steps every frame).</summary>
        float FastestBoundarySpeed()
        {
            float fastest = _scene.Container.FastestWallSpeed;
            var obstacles = _scene.Obstacles;
            for (int i = 0; i < obstacles.Count; i++)
                fastest = Math.Max(fastest, obstacles[i].Velocity.Length());
            return ValidationRules.IsFinite(fastest) ? fastest : 0f;
        }

        /// <summary>Runs <paramref name="substeps"/> sub-steps of exactly <paramref name="timeStep"/> seconds,
        /// bypassing the adaptive controller (tests and benchmarks).</summary>
        public void StepFixed(int substeps, float timeStep)
        {
            ThrowIfDisposed();
            if (substeps < 0) throw new ArgumentOutOfRangeException(nameof(substeps), substeps, "FluidSimulation: substeps must be >= 0");
            CheckTimeStep(timeStep);
            if (_divergenceFree && ReproducibleStepPlanning)
                ReadMotionIntoTimeStep(); // the solves' iterations for their budget (SolveRounds), as Step reads them
            BeginFrame(substeps * timeStep);
            for (int s = 0; s < substeps; s++)
                Substep(timeStep);
            _device.Submit();
            SimulatedTime += (double)substeps * timeStep;
            LastStep = new StepReport(substeps, timeStep, substeps * timeStep, false, _timeStep.StableTimeStep(out string limit), limit,
                _scene.Settings.PressureSolver);
        }

        static void CheckTimeStep(float timeStep)
        {
            if (!(timeStep > 0f) || float.IsInfinity(timeStep))
                throw new ArgumentOutOfRangeException(nameof(timeStep), timeStep, "FluidSimulation: timeStep must be a finite number > 0 s");
        }

        /// <summary>The plan and keywords for this frame, and the walls where it starts: <paramref name="sweepSeconds"/>
        /// (the time the frame simulates) before their placement when they came with a velocity.</summary>
        void BeginFrame(float sweepSeconds)
        {
            // The plan depends on the container's motion, the obstacle count and whether the passes read neighbour lists
            // (the lanes, which tests set) alone (phases and settings are fixed for the simulation's lifetime): planned
            // again only when those change.
            int moved = _containerChanged ? 1 : 0;
            var plan = _plans[moved];
            if (plan == null || plan.ObstacleCount != _scene.Obstacles.Count || plan.NeighbourLists != ReadsNeighbourLists)
                _plans[moved] = plan = PipelinePlanner.Plan(_scene, _containerChanged, _forcedEffects, ReadsNeighbourLists);
            Plan = plan;
            foreach (string keyword in SolverKeywords.All)
                _device.SetKeyword(_solver, keyword, Plan.IsKeywordEnabled(keyword));
            var container = _scene.Container;
            bool containerCarried = _containerChanged && (container.Velocity != Vector3.Zero || container.AngularVelocity != Vector3.Zero);
            bool obstaclesCarried = false;
            if (_obstaclesMoved)
                foreach (var sphere in _scene.Obstacles) obstaclesCarried |= sphere.Velocity != Vector3.Zero;
            // A placement pushed with a velocity is where the walls stand at the frame's end, reached at that velocity: they
            // start the frame that far behind it, where the last frame left them (UpdateContainer), and sweep up to it.
            bool carried = containerCarried || obstaclesCarried;
            bool placeAgain = carried || _wallsFollowVelocity; // last frame's walls stand where its sweep ended
            _wallTime = carried ? -sweepSeconds : 0f;
            if (Plan.UploadContainerTransform || placeAgain)
            {
                _device.BeginSample(PassNames.UploadContainer);
                WriteContainer(_wallTime);
                _device.EndSample(PassNames.UploadContainer);
            }
            if (placeAgain) WriteObstacles(_wallTime);
            _wallsFollowVelocity = carried;
            _obstaclesMoved = false;
            PushConstants();
            if (_boundaryMoved) PlaceWalls();
        }

        /// <summary>Places the boundary particles in the world and sorts them on the grid (DFSPH: their density and factor are
        /// summed again where they now stand, and the next neighbour search sees them).</summary>
        void PlaceWalls()
        {
            _device.BeginSample(PassNames.PlaceBoundary);
            _device.DispatchThreads(_solver, _kernels.PlaceBoundary, _boundaryCount);
            _buffers.BoundarySorter.Sort(_grid, _buffers.BoundaryPlaced, _buffers.BoundarySorted, _boundaryCount);
            _neighboursFound = false;
            if (_divergenceFree)
            {
                _device.DispatchThreads(_solver, _kernels.WallNumberDensity, _boundaryCount);
                _wallsResorted = true;
            }
            _device.EndSample(PassNames.PlaceBoundary);
            _boundaryMoved = false;
        }

        /// <summary>
        /// Walls that came with a velocity move on by <paramref name="dt"/>, to where they are at the end of the sub-step
        /// whose drift just ran: the container's transform and the spheres' centres advance as rigid motions, and
        /// <see cref="Sort"/> places the walls there. Placed once per frame instead, a carried tank's fluid drifted a
        /// frame's travel into its leading wall between placements (CarriedTankTests).
        /// </summary>
        void AdvanceWalls(float dt)
        {
            if (!_wallsFollowVelocity) return;
            _wallTime += dt;
            if (_scene.Container.Velocity != Vector3.Zero || _scene.Container.AngularVelocity != Vector3.Zero)
                WriteContainer(_wallTime);
            WriteObstacles(_wallTime);
        }

        /// <summary>One sub-step of the chosen pressure solver.</summary>
        void Substep(float dt)
        {
            SetTimeStep(dt); // once per frame: its sub-steps share one dt
            if (_divergenceFree)
                DivergenceFreeSubstep();
            else
                VerletSubstep();
        }

        /// <summary>One WCSPH Velocity Verlet sub-step: kick-drift, re-sort, forces, kick; beyond the explicit viscous limit
        /// each kick followed by the implicit viscosity solve over its half of the step.</summary>
        void VerletSubstep()
        {
            if (_viscosity.Rounds > 0)
            {
                // Each half kick is damped before the particles drift with it (ImplicitViscosity.SolvesPerStep); the
                // solve reads the neighbours where the last sort left them, unless a shift has moved them since.
                // delta-SPH's rate follows the solve, so that its continuity sees the velocity the drift takes.
                SolverPass(PassNames.HalfKick, _kernels.HalfKick);
                FindNeighbours();
                SolveViscosity();
                if (_deltaSph)
                    LanedPass(PassNames.DensityRate, _kernels.DensityRate, ParticleCount);
                SolverPass(PassNames.HalfDrift, _kernels.HalfDrift);
            }
            else
            {
                if (_deltaSph)
                {
                    FindNeighbours(); // found after the last sort, unless a shift or the walls' placement moved them since
                    LanedPass(PassNames.DensityRate, _kernels.DensityRate, ParticleCount);
                }
                SolverPass(PassNames.HalfStep, _kernels.HalfStep);
            }

            AdvanceWalls(_constants[0].TimeStep);
            SortAndComputeForces();

            SolverPass(PassNames.FullStep, _kernels.FullStep);
            if (_viscosity.Rounds > 0)
                SolveViscosity();

            if (Plan.Shifting)
                Shift();
        }

        /// <summary>Particle shifting (ParticleShifting.hlsl): the shifts from the sorted state the forces saw, then
        /// applied in a second pass so that no particle moves while its neighbours still read it.</summary>
        void Shift()
        {
            LanedPass(PassNames.ParticleShift, _kernels.ParticleShift, ParticleCount);
            SolverPass(PassNames.ApplyShift, _kernels.ApplyShift);
            _neighboursFound = false;
        }

        /// <summary>One DFSPH sub-step (Bender &amp; Koschier 2017, Algorithm 1): non-pressure forces, predicted velocity,
        /// constant-density solve, drift, re-sort, density and factor, divergence-free solve.</summary>
        void DivergenceFreeSubstep()
        {
            if (_wallsResorted)
            {
                // The fluid's density and factor were last summed with the walls where they stood before this frame.
                FindNeighbours();
                _device.DispatchThreads(_solver, _kernels.WallMovedDensityFactor, ParticleCount * LanesPerParticle);
                _device.DispatchThreads(_solver, _kernels.BoundaryDensityFactor, _boundaryCount * LanesPerParticle);
            }
            if (Plan.SurfaceTension) LanedPass(PassNames.Normals, _kernels.Normals, ParticleCount);
            if (Plan.StrainRateViscosity) LanedPass(PassNames.Rotations, _kernels.Rotations, ParticleCount);
            LanedPass(PassNames.NonPressureForces, _kernels.NonPressureForces, ParticleCount);

            SolverPass(PassNames.PredictVelocity, _kernels.PredictVelocity);

            _device.BeginSample(PassNames.DensitySolve);
            Solve(DensitySolveSlot, _kernels.BeginDensitySolve, _kernels.DensitySolveError);
            _device.EndSample(PassNames.DensitySolve);

            // After the pressure's kick, so that it is damped in the step it is given (SphViscositySolve.hlsl).
            if (_viscosity.Rounds > 0)
                SolveViscosity();

            LanedPass(PassNames.Drift, _kernels.Drift, ParticleCount);

            AdvanceWalls(_constants[0].TimeStep);
            SortAndComputeForces(false);

            _device.BeginSample(PassNames.DivergenceSolve);
            Solve(DivergenceSolveSlot, _kernels.BeginDivergenceSolve, _kernels.DivergenceSolveError);
            _device.EndSample(PassNames.DivergenceSolve);
        }

        /// <summary>The implicit viscosity solve (SphViscositySolve.hlsl) on the predicted velocities: for each of its two
        /// stages its target, then the recorded rounds of the viscous Jacobi step, Chebyshev-accelerated, and its
        /// application.</summary>
        void SolveViscosity()
        {
            _device.BeginSample(PassNames.ViscositySolve);
            for (int stage = 0; stage < ImplicitViscosity.Stages; stage++)
            {
                _device.DispatchThreads(_solver, _kernels.ViscosityStage, ParticleCount);
                for (int k = 0; k < _viscosity.Rounds; k++)
                {
                    _device.DispatchThreads(_solver, _kernels.ViscosityStep, ParticleCount * LanesPerParticle);
                    _device.DispatchThreads(_solver, _kernels.ViscosityApply, ParticleCount);
                }
            }
            _device.EndSample(PassNames.ViscositySolve);
        }

        /// <summary>Rounds of the implicit viscosity solve each sub-step of the last frame recorded, every solve and stage; 0
        /// while the viscosity was explicit (<see cref="ImplicitViscosity"/>).</summary>
        public int ViscositySolveRounds =>
            ImplicitViscosity.SolvesPerStep(_scene.Settings.PressureSolver) * ImplicitViscosity.Stages * _viscosity.Rounds;

        const int DensitySolveSlot = 0, DivergenceSolveSlot = 1;

        /// <summary>Rounds (error passes with the fold, correction) recorded for each DFSPH solve of the next sub-steps:
        /// [0] constant density, [1] divergence-free. At most MaxSolverIterations; see <see cref="SolveBudget.Next"/>.</summary>
        public IReadOnlyList<int> SolveRounds => _solveRounds;

        /// <summary>Sizes the next solves from the iterations the motion reduction read back (<see cref="SolveBudget.Next"/>).</summary>
        void ReportSolveIterations(Vector4 solves)
        {
            if (!_divergenceFree) return;
            int max = _scene.Settings.MaxSolverIterations;
            _solveRounds[DensitySolveSlot] = SolveBudget.Next(_solveRounds[DensitySolveSlot], (int)Math.Round(solves.X), (int)Math.Round(solves.Y), max);
            _solveRounds[DivergenceSolveSlot] = SolveBudget.Next(_solveRounds[DivergenceSolveSlot], (int)Math.Round(solves.Z), (int)Math.Round(solves.W), max);
            WriteSolveRounds();
        }

        /// <summary>
        /// Records one DFSPH solve without reading anything back: its opening, the warm start's correction, then
        /// <see cref="SolveRounds"/> rounds of the fluid's error pass, the walls' (whose last group folds the round's errors
        /// and decides whether the solve goes on) and the correction: indirect dispatches whose group count the fold sets to
        /// zero once the solve has converged (FluidSolver.compute), so the rounds recorded beyond convergence cost the GPU
        /// three empty dispatches each; the budget keeps their number (and their recording) near what the solves have been
        /// using (<see cref="SolveBudget"/>).
        /// </summary>
        void Solve(int slot, int beginKernel, int errorKernel)
        {
            int rounds = _solveRounds[slot];
            // The constant-density solve's opening gives the walls their warm start too, a thread each (at least one: its
            // first thread opens the solve); the divergence-free solve's walls took theirs in BoundaryDensityFactor.
            _device.DispatchThreads(_solver, beginKernel, slot == DensitySolveSlot ? Math.Max(1, _boundaryCount) : 1);
            _device.DispatchThreads(_solver, _kernels.ApplyStiffness, ParticleCount * LanesPerParticle);
            for (int l = 0; l < rounds; l++)
            {
                _device.DispatchIndirect(_solver, errorKernel, _buffers.SolverArguments, 0);
                _device.DispatchIndirect(_solver, _kernels.BoundarySolveError, _buffers.SolverArguments, 12);
                _device.DispatchIndirect(_solver, _kernels.ApplyStiffness, _buffers.SolverArguments, 0);
            }
        }

        /// <summary>Sort by cell, then density and pressure, normals, forces: a valid acceleration for the
        /// current positions. Runs once before the first step and inside every sub-step (DFSPH: density and factor,
        /// and with <paramref name="withForces"/> the non-pressure forces the motion read-back needs).</summary>
        void SortAndComputeForces(bool withForces = true)
        {
            Sort();
            DensityAndForces(withForces);
        }

        /// <summary>Counting sort of the particles by grid cell (ParticleSort.compute) into the other particle buffer. The grid
        /// follows the container here and nowhere else, since every neighbour loop reads the fluid in the order of its last
        /// sort; walls that moved are placed and sorted on the same grid first.</summary>
        void Sort()
        {
            if (_gridBehind)
            {
                _grid.Place(_containerPosition, _containerRotation);
                WriteGrid();
                _gridBehind = false;
                _boundaryMoved = true;
            }
            PushConstants();
            if (_boundaryMoved) PlaceWalls();
            _device.BeginSample(PassNames.Sort);
            _buffers.Sorter.Sort(_grid, _buffers.Particles, _buffers.ParticlesOther, ParticleCount);
            _buffers.SwapParticles();
            _device.EndSample(PassNames.Sort);
            _neighboursFound = false;
        }

        /// <summary>The passes of <see cref="SortAndComputeForces"/> after the sort, for particles already sorted.</summary>
        void DensityAndForces(bool withForces = true)
        {
            if (_divergenceFree)
            {
                FindNeighbours();
                LanedPass(PassNames.DensityFactor, _kernels.DensityFactor, ParticleCount);
                _device.DispatchThreads(_solver, _kernels.BoundaryDensityFactor, _boundaryCount * LanesPerParticle);
                if (!withForces) return;
                if (Plan.SurfaceTension) _device.DispatchThreads(_solver, _kernels.Normals, ParticleCount * LanesPerParticle);
                if (Plan.StrainRateViscosity) _device.DispatchThreads(_solver, _kernels.Rotations, ParticleCount * LanesPerParticle);
                _device.DispatchThreads(_solver, _kernels.NonPressureForces, ParticleCount * LanesPerParticle);
                return;
            }

            FindNeighbours();
            LanedPass(PassNames.DensityPressure, _deltaSph ? _kernels.ContinuityDensity : _kernels.DensityPressure, ParticleCount);

            LanedPass(PassNames.WallPressure, _kernels.WallPressure, _boundaryCount);

            if (Plan.SurfaceTension) LanedPass(PassNames.Normals, _kernels.Normals, ParticleCount);
            if (Plan.StrainRateViscosity) LanedPass(PassNames.Rotations, _kernels.Rotations, ParticleCount);

            LanedPass(PassNames.Forces, _kernels.Forces, ParticleCount);
        }

        /// <summary>The neighbour lists (SphNeighbourhood.hlsl) of every fluid and boundary particle where they stand, unless
        /// they were found since the particles or walls last moved or were sorted; while no lists are in use
        /// (<see cref="ReadsNeighbourLists"/>) the kernels walk the grid and nothing is dispatched. Laned, as the passes that
        /// read them (DFSPH's order only: WCSPH reads lists in one lane, NeighbourCapacity.InUse).</summary>
        void FindNeighbours()
        {
            if (!_neighboursFound && ReadsNeighbourLists)
                LanedPass(PassNames.FindNeighbours, _kernels.FindNeighbours, ParticleCount + _boundaryCount);
            _neighboursFound = true;
            _wallsResorted = false;
        }

        /// <summary>Whether the neighbour passes read the lists (<see cref="NeighbourCapacity.InUse"/> at the present lanes,
        /// and lists that fit in a buffer) rather than walk the grid.</summary>
        public bool ReadsNeighbourLists => _constants[0].NeighbourCapacity > 0;

        /// <summary>False: every pass walks the grid, lists or not (tests compare the two). True by default.</summary>
        public bool NeighbourListsAllowed
        {
            get => _listsAllowed;
            set
            {
                _listsAllowed = value;
                UseNeighbourLists();
            }
        }

        /// <summary>Lists in use or not, for the solver at the present lanes: the constants say which to the kernels.</summary>
        void UseNeighbourLists()
        {
            bool inUse = _listsAllowed && NeighbourCapacity.InUse(_scene.Settings.PressureSolver, LanesPerParticle);
            uint capacity = inUse ? (uint)_listCapacity : 0u;
            if (_constants[0].NeighbourCapacity == capacity) return;
            _constants[0].NeighbourCapacity = capacity;
            _constantsChanged = true;
            _neighboursFound = false;
        }

        /// <summary>One timed solver pass: the kernel over <paramref name="threads"/> items (default: every particle),
        /// inside its GPU timing range.</summary>
        void SolverPass(string pass, int kernel, int threads = -1)
        {
            _device.BeginSample(pass);
            _device.DispatchThreads(_solver, kernel, threads < 0 ? ParticleCount : threads);
            _device.EndSample(pass);
        }

        /// <summary>One timed pass of a laned kernel (NeighbourLanes.hlsl): <see cref="LanesPerParticle"/> threads for each
        /// of <paramref name="owners"/> particles.</summary>
        void LanedPass(string pass, int kernel, int owners) => SolverPass(pass, kernel, owners * LanesPerParticle);

        /// <summary>Re-sorts and recomputes density, pressure and accelerations for the current particles
        /// without moving them (tests compare these with the CPU reference).</summary>
        public void ComputeForces()
        {
            ThrowIfDisposed();
            BeginFrame(0f);
            if (_deltaSph)
            {
                // delta-SPH outside a step: dt = 0 keeps the carried delta; DensityRate runs on the sorted state for its
                // rates, and nothing moves before the density and forces.
                SetTimeStep(0f);
                Sort();
                FindNeighbours();
                LanedPass(PassNames.DensityRate, _kernels.DensityRate, ParticleCount);
                DensityAndForces();
            }
            else
            {
                SortAndComputeForces();
            }
            _device.Submit();
        }

        /// <summary>DFSPH: a sub-step of <paramref name="timeStep"/> s up to its drift, without the constant-density solve, on
        /// the current particles re-sorted: the non-pressure forces, the predicted velocity and, beyond the explicit viscous
        /// limit, the implicit viscosity solve (tests compare the velocities with the CPU reference). Nothing moves.</summary>
        public void PredictVelocities(float timeStep)
        {
            ThrowIfDisposed();
            if (!_divergenceFree) throw new InvalidOperationException("FluidSimulation: PredictVelocities is DFSPH's sub-step start");
            CheckTimeStep(timeStep);
            BeginFrame(0f);
            SetTimeStep(timeStep);
            SortAndComputeForces();
            SolverPass(PassNames.PredictVelocity, _kernels.PredictVelocity);
            if (_viscosity.Rounds > 0)
                SolveViscosity();
            _device.Submit();
        }

        /// <summary>DFSPH: the drift alone, wall contact included, over <paramref name="timeStep"/> s on the current particles
        /// re-sorted, with their density and factor but no solve (tests compare the contact's laned sums with one lane's).
        /// </summary>
        public void Drift(float timeStep)
        {
            ThrowIfDisposed();
            if (!_divergenceFree) throw new InvalidOperationException("FluidSimulation: Drift is DFSPH's drift");
            CheckTimeStep(timeStep);
            BeginFrame(0f);
            SetTimeStep(timeStep);
            SortAndComputeForces(false);
            LanedPass(PassNames.Drift, _kernels.Drift, ParticleCount);
            _device.Submit();
        }

        /// <summary>Replaces the particle state (same count; tests). Forces are recomputed for it.</summary>
        public void SetParticles(Particle[] particles)
        {
            ThrowIfDisposed();
            if (particles == null) throw new ArgumentNullException(nameof(particles));
            if (particles.Length != ParticleCount)
                throw new ArgumentException($"FluidSimulation: SetParticles needs exactly {ParticleCount} particles (was {particles.Length})", nameof(particles));
            _buffers.Particles.SetData(particles);
            ComputeForces();
        }

        /// <summary>Respawns every particle as at construction and computes the first forces.</summary>
        public void Reset()
        {
            ThrowIfDisposed();
            SimulatedTime = 0;
            LastStep = StepReport.None;
            _timeStep.Reset();
            float speed = 0f;
            foreach (var box in _scene.SpawnBoxes) speed = Math.Max(speed, box.InitialVelocity.Length());
            _timeStep.ReportMotion(speed, _scene.Settings.Gravity.Length());
            _motionReadback = null;
            _diagnosticsReadback = null;
            LatestDiagnostics = null;
            _buffers.Particles.SetData(_spawn);
            _buffers.NumberDensities.SetData(_spawnNumberDensities);
            _buffers.ClearForRespawn();
            _solveRounds[DensitySolveSlot] = _solveRounds[DivergenceSolveSlot] = _scene.Settings.MaxSolverIterations;
            WriteSolveRounds();
            ComputeForces();
            // The first frame plans with the acceleration the first force pass computed, not gravity alone.
            ReadMotion(out float firstSpeed, out float firstAcceleration);
            _timeStep.ReportMotion(firstSpeed, firstAcceleration);
        }

        // ---------------------------------------------------------------- set-up

        /// <summary>Samples the walls and obstacles (BoundarySampling) into new boundary buffers; they are placed in the
        /// world and sorted before the next sub-step.</summary>
        void CreateBoundary()
        {
            var rest = BoundarySampling.Sample(_scene);
            _boundaryCount = rest.Length;
            if (DeviceCapacity.Problem(0, _boundaryCount, _device) is string tooMany)
                throw new ArgumentException("FluidSimulation: " + tooMany, "scene");
            _listCapacity = NeighbourCapacity.For(_scene.Settings, ParticleCount + _boundaryCount, _device.MaxBufferBytes);
            _buffers.MakeBoundary(rest, BoundarySampling.OwnNumberDensities(_scene, rest), _grid.CellCount, _listCapacity);
            _constants[0].BoundaryCount = (uint)_boundaryCount;
            _constantsChanged = true;
            UseNeighbourLists();
            _boundaryMoved = true;
        }

        /// <summary>A new grid for the container's size (and a larger sorter if it needs more cells).</summary>
        void RebuildGrid()
        {
            var c = _scene.Container;
            _grid = CellGrid.ForSupport(c.Position, c.Rotation, c.Size, _scene.Settings.SmoothingRadius);
            _buffers.MakeSorter(_grid.CellCount);
            WriteGrid();
            _containerChanged = true;
        }

        /// <summary>Each phase's <see cref="PhaseProperties.InverseParticleCount"/>, from the spawn: nothing is lost after it.</summary>
        static void CountPhases(PhaseProperties[] table, Particle[] spawn)
        {
            var counts = new int[table.Length];
            foreach (var p in spawn) counts[p.Phase]++;
            for (int k = 0; k < table.Length; k++)
                table[k].InverseParticleCount = counts[k] > 0 ? 1f / counts[k] : 0f;
        }

        /// <summary>delta-SPH's starting number densities by particle id: delta0 (1 + p / k)^(1 / gamma) of each particle's phase at
        /// the hydrostatic pressure it was spawned under (HydrostaticSpawn), so the Tait pressure starts exactly hydrostatic
        /// whatever the spawn jitter did to the kernel sums.</summary>
        float[] HydrostaticNumberDensities(Particle[] spawn, double[] pressures)
        {
            var s = _scene.Settings;
            var result = new float[spawn.Length];
            foreach (var p in spawn)
            {
                var phase = _phaseTable[p.Phase];
                double restNumberDensity = (double)phase.RestDensity / phase.ParticleMass;
                result[p.Id] = (float)(restNumberDensity * Math.Pow(1.0 + pressures[p.Id] / s.Stiffness, 1.0 / s.Gamma));
            }
            return result;
        }

        static FluidSceneDescription CopyOf(FluidSceneDescription scene)
        {
            var obstacles = new List<RigidSphere>();
            if (scene.Obstacles != null)
                foreach (var o in scene.Obstacles) obstacles.Add(o?.Clone());
            return new FluidSceneDescription
            {
                Settings = scene.Settings?.Clone(),
                SpawnBoxes = scene.SpawnBoxes == null ? null : new List<FluidBlock>(scene.SpawnBoxes),
                Container = scene.Container?.Clone(),
                Obstacles = obstacles,
            };
        }

        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            _motionReadback = null;
            _diagnosticsReadback = null;
            _buffers?.Dispose();
        }

        void ThrowIfDisposed()
        {
            if (_disposed) throw new ObjectDisposedException(nameof(FluidSimulation));
        }
    }
}
