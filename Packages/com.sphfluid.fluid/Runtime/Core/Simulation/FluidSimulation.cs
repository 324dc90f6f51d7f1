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
    /// Buffers: two particle buffers (the sort writes the other one and they swap: <see cref="Particles"/> is
    /// always the cell-sorted current state), per-particle density/pressure, normals, accelerations and XSPH
    /// corrections (indexed like the current particles), the phase table, the obstacles, the sorter's
    /// CellStart/CellCount, the boundary particles (rest frame, placed, cell-sorted, with their own sorter),
    /// the clamp-hit counter, and the reduction partials and totals.
    /// </remarks>
    public sealed class FluidSimulation : IDisposable
    {
        public const string SolverProgramName = "FluidSolver";
        public const string DiagnosticsProgramName = "FluidDiagnostics";
        const int ReductionThreads = 256; // REDUCTION_THREADS in Include/SphTimeStep.hlsl
        const uint ParticleThreads = 128; // PARTICLE_THREADS in FluidSolver.compute

        /// <summary>alpha_w of the contact damping against boundary particles (SphBoundary.hlsl): Monaghan's artificial
        /// viscosity on the velocity into the wall only. 0.5 brought the clamp hits of a turning container and a driven
        /// sphere to zero without slowing a dam-break front along the floor.</summary>
        public const float WallContactDamping = 0.5f;

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
        readonly IComputeProgram _solver, _diagnostics;
        readonly int _halfStep, _placeBoundary, _densityPressure, _wallPressure, _normals, _forces, _fullStep;
        readonly int _densityFactor, _nonPressureForces, _predictVelocity, _beginSolve, _densitySolveError, _divergenceSolveError,
            _solveFinal, _applyStiffness, _drift, _divergenceRate;
        readonly bool _divergenceFree;
        readonly int _particleShift, _applyShift;
        readonly int _densityRate, _continuityDensity; // delta-SPH (SphDensityDiffusion.hlsl)
        readonly bool _deltaSph;
        readonly float[] _spawnNumberDensities;
        readonly int[] _solverKernels;
        readonly int _motionPartial, _motionFinal, _diagnosticsPartial, _diagnosticsFinal;
        readonly int _reductionGroups;
        readonly ShaderIds _ids;

        IComputeBuffer _particles, _particlesOther;
        IComputeBuffer _phaseBuffer, _densities, _normalsBuffer, _accelerations, _xsph, _obstacles, _shifts;
        IComputeBuffer _motionPartials, _motionTotals, _diagnosticsPartials, _diagnosticsTotals, _clampHits;
        IComputeBuffer _boundaryRest, _boundaryPlaced, _boundarySorted, _boundaryPressures;
        IComputeBuffer _factors, _solverStiffness, _warmStart, _solverPartials, _solverState, _solverArguments, _divergenceRates;
        IComputeBuffer _numberDensities, _numberDensitiesHalf, _densityRates; // delta-SPH
        ParticleSorter _sorter, _boundarySorter;
        CellGrid _grid;
        bool _containerChanged = true;
        bool _boundaryMoved = true;
        int _boundaryCount;
        IReadbackRequest _motionReadback, _diagnosticsReadback;
        double _diagnosticsRequestTime;
        readonly Vector4[] _motionRow = new Vector4[2]; // [0] vmax, amax; [1] the DFSPH solves' iterations (SolveBudget)
        readonly int[] _solveRounds = new int[2];       // rounds recorded per solve, by solve slot (SolveBudget)
        // Kept for the simulation's lifetime so that a steady frame makes no garbage (Unity's GC stalls show as hitches).
        readonly IComputeProgram[] _programs;
        readonly int[] _diagnosticsKernels;
        readonly SphereObstacleData[] _obstacleRows = new SphereObstacleData[FluidSceneDescription.MaxObstacles];
        readonly Vector4[] _diagnosticsRows;
        readonly SimulationPlan[] _plans = new SimulationPlan[2]; // [container unchanged, container moved]
        DiagnosticsReport _latestDiagnostics, _diagnosticsReport;
        readonly FluidSceneDescription _containerProbe = new FluidSceneDescription();
        readonly List<ValidationError> _containerErrors = new List<ValidationError>();
        readonly List<ValidationError> _obstacleErrors = new List<ValidationError>();
        string[,] _obstacleNames; // [sphere, 0] owner and [sphere, 1] path in messages, made for _obstacleNamesFor
        List<SphereObstacleDescription> _obstacleNamesFor;
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
            _spawnNumberDensities = HydrostaticNumberDensities(_spawn, spawnPressures);
            ParticleCount = _spawn.Length;
            _timeStep = TimeStepController.ForScene(_scene);
            _reductionGroups = (ParticleCount + ReductionThreads - 1) / ReductionThreads;
            _ids = new ShaderIds(device);

            _solver = device.LoadProgram(SolverProgramName);
            _diagnostics = device.LoadProgram(DiagnosticsProgramName);
            _halfStep = _solver.FindKernel("HalfStep");
            _placeBoundary = _solver.FindKernel("PlaceBoundary");
            _densityPressure = _solver.FindKernel("DensityPressure");
            _wallPressure = _solver.FindKernel("WallPressure");
            _normals = _solver.FindKernel("Normals");
            _forces = _solver.FindKernel("Forces");
            _fullStep = _solver.FindKernel("FullStep");
            _densityFactor = _solver.FindKernel("DensityFactor");
            _nonPressureForces = _solver.FindKernel("NonPressureForces");
            _predictVelocity = _solver.FindKernel("PredictVelocity");
            _beginSolve = _solver.FindKernel("BeginSolve");
            _densitySolveError = _solver.FindKernel("DensitySolveError");
            _divergenceSolveError = _solver.FindKernel("DivergenceSolveError");
            _solveFinal = _solver.FindKernel("SolveFinal");
            _applyStiffness = _solver.FindKernel("ApplyStiffness");
            _drift = _solver.FindKernel("Drift");
            _divergenceRate = _solver.FindKernel("DivergenceRate");
            _divergenceFree = _scene.Settings.PressureSolver == PressureSolver.Dfsph;
            _particleShift = _solver.FindKernel("ParticleShift");
            _applyShift = _solver.FindKernel("ApplyShift");
            _densityRate = _solver.FindKernel("DensityRate");
            _continuityDensity = _solver.FindKernel("ContinuityDensity");
            _deltaSph = !_divergenceFree && _scene.Settings.WcsphDensity == WcsphDensity.DeltaSph;
            _solverKernels = new[]
            {
                _halfStep, _placeBoundary, _densityPressure, _wallPressure, _normals, _forces, _fullStep, _densityFactor, _nonPressureForces,
                _predictVelocity, _beginSolve, _densitySolveError, _divergenceSolveError, _solveFinal, _applyStiffness, _drift, _divergenceRate,
                _particleShift, _applyShift, _densityRate, _continuityDensity,
            };
            _motionPartial = _diagnostics.FindKernel("MotionPartial");
            _motionFinal = _diagnostics.FindKernel("MotionFinal");
            _diagnosticsPartial = _diagnostics.FindKernel("DiagnosticsPartial");
            _diagnosticsFinal = _diagnostics.FindKernel("DiagnosticsFinal");
            _programs = new[] { _solver, _diagnostics };
            _diagnosticsKernels = new[] { _motionPartial, _motionFinal, _diagnosticsPartial, _diagnosticsFinal };
            _diagnosticsRows = new Vector4[3 + _phases.Count];

            try
            {
                CreateBuffers();
                CreateBoundary();
                UploadConstants();
                UploadObstacles();
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
        public IComputeBuffer Particles => _particles;

        /// <summary>The phase table (<see cref="PhaseProperties"/>), indexed by <see cref="Particle.Phase"/>. Shader name <c>_Phases</c>.</summary>
        public IComputeBuffer PhaseTable => _phaseBuffer;

        /// <summary>Per particle (same order as <see cref="Particles"/>): rho, p, delta, p / delta^2.</summary>
        public IComputeBuffer Densities => _densities;

        /// <summary>Per particle: acceleration (xyz) of the last force pass, m/s^2.</summary>
        public IComputeBuffer Accelerations => _accelerations;

        /// <summary>Per particle: colour-field normal (xyz) when surface tension is on.</summary>
        public IComputeBuffer Normals => _normalsBuffer;

        /// <summary>Per particle: XSPH velocity correction (xyz) when XSPH is on, m/s.</summary>
        public IComputeBuffer XsphCorrections => _xsph;

        /// <summary>DFSPH, by particle id (not sorted): float2 of the q the last constant-density (x) and divergence-free (y)
        /// solves applied in total, the next sub-step's warm start (DivergenceFreeSolver.hlsl).</summary>
        public IComputeBuffer WarmStart => _warmStart;

        /// <summary>delta-SPH (WcsphDensity.DeltaSph), by particle id (not sorted): the number density each particle carries, 1/m^3
        /// (SphDensityDiffusion.hlsl). Written before <see cref="ComputeForces"/>, it is the state the forces see.</summary>
        public IComputeBuffer NumberDensities => _numberDensities;

        /// <summary>delta-SPH, per particle (same order as <see cref="Particles"/>): float2 of the continuity and the diffusion
        /// term of D delta / Dt at the last sub-step's start (at the current state after <see cref="ComputeForces"/>), 1/(m^3 s).</summary>
        public IComputeBuffer DensityRates => _densityRates;

        /// <summary>Per particle: the particle shift (xyz) of the last sub-step when shifting is on, m (ParticleShifting.hlsl).</summary>
        public IComputeBuffer Shifts => _shifts;

        /// <summary>The boundary particles (<see cref="BoundaryParticle"/>) in world space, sorted by grid cell.</summary>
        public IComputeBuffer BoundaryParticles => _boundarySorted;

        /// <summary>Number of boundary particles (container walls and obstacles).</summary>
        public int BoundaryCount => _boundaryCount;

        /// <summary>The neighbour grid (container-local cells of size h).</summary>
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
            PassNames.UploadContainer, PassNames.PlaceBoundary, PassNames.HalfStep, PassNames.Sort, PassNames.DensityPressure, PassNames.WallPressure, PassNames.Normals,
            PassNames.Forces, PassNames.FullStep, PassNames.NonPressureForces, PassNames.PredictVelocity, PassNames.DensitySolve, PassNames.Drift,
            PassNames.DensityFactor, PassNames.DivergenceSolve, PassNames.ParticleShift, PassNames.ApplyShift, PassNames.MotionReduction, PassNames.Diagnostics,
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
            StepReport report = _timeStep.PlanFrame(frameSeconds);  // n sub-steps of dt
            BeginFrame();                                           // plan, keywords, container upload
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

        /// <summary>Runs <paramref name="substeps"/> sub-steps of exactly <paramref name="timeStep"/> seconds,
        /// bypassing the adaptive controller (tests and benchmarks).</summary>
        public void StepFixed(int substeps, float timeStep)
        {
            ThrowIfDisposed();
            if (substeps < 0) throw new ArgumentOutOfRangeException(nameof(substeps), substeps, "FluidSimulation: substeps must be >= 0");
            if (!(timeStep > 0f) || float.IsInfinity(timeStep))
                throw new ArgumentOutOfRangeException(nameof(timeStep), timeStep, "FluidSimulation: timeStep must be a finite number > 0 s");
            if (_divergenceFree && ReproducibleStepPlanning)
                ReadMotionIntoTimeStep(); // the solves' iterations for their budget (SolveRounds), as Step reads them
            BeginFrame();
            for (int s = 0; s < substeps; s++)
                Substep(timeStep);
            _device.Submit();
            SimulatedTime += (double)substeps * timeStep;
            LastStep = new StepReport(substeps, timeStep, substeps * timeStep, false, _timeStep.StableTimeStep(out string limit), limit,
                _scene.Settings.PressureSolver);
        }

        void BeginFrame()
        {
            // The plan depends on the container's motion and the obstacle count alone (phases and settings are
            // fixed for the simulation's lifetime): planned again only when those change.
            int moved = _containerChanged ? 1 : 0;
            var plan = _plans[moved];
            if (plan == null || plan.ObstacleCount != _scene.Obstacles.Count)
                _plans[moved] = plan = PipelinePlanner.Plan(_scene, _containerChanged, _forcedEffects);
            Plan = plan;
            foreach (string keyword in SolverKeywords.All)
                _device.SetKeyword(_solver, keyword, Plan.IsKeywordEnabled(keyword));
            if (Plan.UploadContainerTransform)
            {
                _device.BeginSample(PassNames.UploadContainer);
                UploadContainer();
                _device.EndSample(PassNames.UploadContainer);
            }
            if (_boundaryMoved)
            {
                _device.BeginSample(PassNames.PlaceBoundary);
                _device.DispatchThreads(_solver, _placeBoundary, _boundaryCount);
                _boundarySorter.Sort(_grid, _boundaryPlaced, _boundarySorted, _boundaryCount);
                _device.EndSample(PassNames.PlaceBoundary);
                _boundaryMoved = false;
            }
        }

        /// <summary>One sub-step of the chosen pressure solver.</summary>
        void Substep(float dt)
        {
            _device.SetFloat(_solver, _ids.TimeStep, dt);
            if (_divergenceFree)
                DivergenceFreeSubstep();
            else
                VerletSubstep();
        }

        /// <summary>One WCSPH Velocity Verlet sub-step: kick-drift, re-sort, forces, kick.</summary>
        void VerletSubstep()
        {
            if (_deltaSph) SolverPass(PassNames.DensityRate, _densityRate);

            SolverPass(PassNames.HalfStep, _halfStep);

            SortAndComputeForces();

            SolverPass(PassNames.FullStep, _fullStep);

            if (Plan.Shifting)
                Shift();
        }

        /// <summary>Particle shifting (ParticleShifting.hlsl): the shifts from the sorted state the forces saw, then
        /// applied in a second pass so that no particle moves while its neighbours still read it.</summary>
        void Shift()
        {
            SolverPass(PassNames.ParticleShift, _particleShift);
            SolverPass(PassNames.ApplyShift, _applyShift);
        }

        /// <summary>One DFSPH sub-step (Bender &amp; Koschier 2017, Algorithm 1): non-pressure forces, predicted velocity,
        /// constant-density solve, drift, re-sort, density and factor, divergence-free solve.</summary>
        void DivergenceFreeSubstep()
        {
            var s = _scene.Settings;
            if (Plan.SurfaceTension) SolverPass(PassNames.Normals, _normals);
            SolverPass(PassNames.NonPressureForces, _nonPressureForces);

            SolverPass(PassNames.PredictVelocity, _predictVelocity);

            _device.BeginSample(PassNames.DensitySolve);
            Solve(DensitySolveSlot, _densitySolveError, 0.01f * s.DensityTolerance);
            _device.EndSample(PassNames.DensitySolve);

            SolverPass(PassNames.Drift, _drift);

            SortAndComputeForces(false);

            _device.BeginSample(PassNames.DivergenceSolve);
            Solve(DivergenceSolveSlot, _divergenceSolveError, 0.01f * s.DivergenceTolerance);
            _device.EndSample(PassNames.DivergenceSolve);
        }

        const int DensitySolveSlot = 0, DivergenceSolveSlot = 1;

        /// <summary>Rounds (error pass, SolveFinal, correction) recorded for each DFSPH solve of the next sub-steps:
        /// [0] constant density, [1] divergence-free. At most MaxSolverIterations; see <see cref="SolveBudget"/>.</summary>
        public IReadOnlyList<int> SolveRounds => _solveRounds;

        /// <summary>
        /// The rounds a solve needs to converge after <paramref name="mostIterations"/> corrections (the most any solve of
        /// its kind made since the last motion read-back) are that many plus one, the round whose SolveFinal sees the
        /// error within tolerance. Twice that plus a margin is recorded, so that a flow that turns harder from one frame
        /// to the next still converges within the rounds of the frame planned before it was known; a solve that ran out
        /// of rounds anyway (<paramref name="cutOff"/> &gt; 0) at least doubles the budget. Never more than
        /// <paramref name="maxIterations"/> (the setting's hard limit), never fewer than the three rounds the first
        /// possible convergence takes; no solve since (0 and 0) keeps <paramref name="rounds"/>.
        /// </summary>
        public static int SolveBudget(int rounds, int mostIterations, int cutOff, int maxIterations)
        {
            if (mostIterations <= 0 && cutOff <= 0) return rounds;
            int next = 2 * mostIterations + 4;
            if (cutOff > 0) next = Math.Max(next, 2 * rounds);
            return Math.Min(maxIterations, Math.Max(3, next));
        }

        /// <summary>Sizes the next solves from the iterations the motion reduction read back (<see cref="SolveBudget"/>).</summary>
        void ReportSolveIterations(Vector4 solves)
        {
            if (!_divergenceFree) return;
            int max = _scene.Settings.MaxSolverIterations;
            _solveRounds[DensitySolveSlot] = SolveBudget(_solveRounds[DensitySolveSlot], (int)Math.Round(solves.X), (int)Math.Round(solves.Y), max);
            _solveRounds[DivergenceSolveSlot] = SolveBudget(_solveRounds[DivergenceSolveSlot], (int)Math.Round(solves.Z), (int)Math.Round(solves.W), max);
        }

        /// <summary>
        /// Records one DFSPH solve without reading anything back: the warm start's correction, then
        /// <see cref="SolveRounds"/> rounds of error pass, SolveFinal and correction. The error pass and the correction are
        /// indirect dispatches whose group count SolveFinal sets to zero once the solve has converged (FluidSolver.compute),
        /// so the rounds recorded beyond convergence cost the GPU an empty dispatch each; the budget keeps their number
        /// (and their recording) near what the solves have been using.
        /// </summary>
        void Solve(int slot, int errorKernel, float tolerance)
        {
            int rounds = _solveRounds[slot];
            _device.SetInt(_solver, _ids.SolveSlot, slot);
            _device.SetFloat(_solver, _ids.SolveTolerance, tolerance);
            _device.SetInt(_solver, _ids.SolveRounds, rounds);
            _device.Dispatch(_solver, _beginSolve, 1, 1, 1);
            _device.DispatchThreads(_solver, _applyStiffness, ParticleCount);
            for (int l = 0; l < rounds; l++)
            {
                _device.DispatchIndirect(_solver, errorKernel, _solverArguments, 0);
                _device.Dispatch(_solver, _solveFinal, 1, 1, 1);
                _device.DispatchIndirect(_solver, _applyStiffness, _solverArguments, 0);
            }
        }

        /// <summary>Sort by cell, then density and pressure, normals, forces: a valid acceleration for the
        /// current positions. Runs once before the first step and inside every sub-step (DFSPH: density and factor,
        /// and with <paramref name="withForces"/> the non-pressure forces the motion read-back needs).</summary>
        void SortAndComputeForces(bool withForces = true)
        {
            _device.BeginSample(PassNames.Sort);
            _sorter.Sort(_grid, _particles, _particlesOther, ParticleCount);
            SwapParticleBuffers();
            _device.EndSample(PassNames.Sort);

            if (_divergenceFree)
            {
                SolverPass(PassNames.DensityFactor, _densityFactor);
                if (!withForces) return;
                if (Plan.SurfaceTension) _device.DispatchThreads(_solver, _normals, ParticleCount);
                _device.DispatchThreads(_solver, _nonPressureForces, ParticleCount);
                return;
            }

            SolverPass(PassNames.DensityPressure, _deltaSph ? _continuityDensity : _densityPressure);

            SolverPass(PassNames.WallPressure, _wallPressure, _boundaryCount);

            if (Plan.SurfaceTension) SolverPass(PassNames.Normals, _normals);

            SolverPass(PassNames.Forces, _forces);
        }

        /// <summary>One timed solver pass: the kernel over <paramref name="threads"/> items (default: every particle),
        /// inside its GPU timing range.</summary>
        void SolverPass(string pass, int kernel, int threads = -1)
        {
            _device.BeginSample(pass);
            _device.DispatchThreads(_solver, kernel, threads < 0 ? ParticleCount : threads);
            _device.EndSample(pass);
        }

        /// <summary>Re-sorts and recomputes density, pressure and accelerations for the current particles
        /// without moving them (tests compare these with the CPU reference).</summary>
        public void ComputeForces()
        {
            ThrowIfDisposed();
            BeginFrame();
            if (_deltaSph)
            {
                // delta-SPH outside a step: dt = 0 keeps the carried delta; DensityRate runs on the sorted state for its rates.
                _device.SetFloat(_solver, _ids.TimeStep, 0f);
                _device.BeginSample(PassNames.Sort);
                _sorter.Sort(_grid, _particles, _particlesOther, ParticleCount);
                SwapParticleBuffers();
                _device.EndSample(PassNames.Sort);
                SolverPass(PassNames.DensityRate, _densityRate);
            }
            SortAndComputeForces();
            _device.Submit();
        }

        /// <summary>Replaces the particle state (same count; tests). Forces are recomputed for it.</summary>
        public void SetParticles(Particle[] particles)
        {
            ThrowIfDisposed();
            if (particles == null) throw new ArgumentNullException(nameof(particles));
            if (particles.Length != ParticleCount)
                throw new ArgumentException($"FluidSimulation: SetParticles needs exactly {ParticleCount} particles (was {particles.Length})", nameof(particles));
            _particles.SetData(particles);
            ComputeForces();
        }

        /// <summary>Moves (or resizes) the container; its transform is uploaded before the next step.
        /// Callers push the container every frame, so an unchanged one returns before anything is copied or
        /// validated (it was validated when it was set).</summary>
        public void UpdateContainer(ContainerDescription container)
        {
            ThrowIfDisposed();
            if (container == null) throw new ArgumentNullException(nameof(container));
            var old = _scene.Container;
            if (old.SamePlacement(container) && old.Velocity == container.Velocity && old.AngularVelocity == container.AngularVelocity
                && old.Friction == container.Friction)
                return;
            // The container's rules read only the settings (its least size), so the probe holds nothing else;
            // probe and list are kept because a turning container changes every frame.
            _containerProbe.Settings = _scene.Settings;
            _containerProbe.Container = container;
            _containerErrors.Clear();
            _containerProbe.ValidateContainer(_containerErrors);
            _containerProbe.Container = null;
            if (_containerErrors.Count > 0) throw new ArgumentException(Join(_containerErrors));
            if (old.Size == container.Size && old.Friction == container.Friction)
            {
                // Only placement and motion differ: copied into the simulation's own description, not cloned.
                old.Position = container.Position;
                old.Rotation = container.Rotation;
                old.Velocity = container.Velocity;
                old.AngularVelocity = container.AngularVelocity;
                _containerChanged = true;
                return;
            }
            _scene.Container = container.Clone();
            _containerChanged = true;
            if (old.Size != container.Size)
            {
                RebuildGrid();
                CreateBoundary();
            }
            if (old.Friction != container.Friction)
                UploadConstants();
        }

        /// <summary>Replaces the sphere obstacles (any count up to <see cref="FluidSceneDescription.MaxObstacles"/>).
        /// Callers push the obstacles every frame, so the same spheres as now return before anything is copied,
        /// validated or uploaded.</summary>
        public void UpdateObstacles(IReadOnlyList<SphereObstacleDescription> obstacles)
        {
            ThrowIfDisposed();
            int count = obstacles == null ? 0 : obstacles.Count;
            var current = _scene.Obstacles;
            bool same = current.Count == count;
            for (int i = 0; same && i < count; i++)
            {
                SphereObstacleDescription now = current[i], next = obstacles[i];
                same = next != null && now.Name == next.Name && now.Center == next.Center && now.Radius == next.Radius
                       && now.Velocity == next.Velocity;
            }
            if (same) return;
            if (MovedOnly(obstacles, count)) return;

            var list = new List<SphereObstacleDescription>(count);
            for (int i = 0; i < count; i++) list.Add(obstacles[i]?.Clone());
            // The obstacles' rules read nothing else of the scene, so the probe holds only them.
            var probe = new FluidSceneDescription { Obstacles = list };
            var errors = new List<string>();
            foreach (var e in probe.Validate())
                if (e.Field.StartsWith("Obstacles", StringComparison.Ordinal)) errors.Add(e.Message);
            if (errors.Count > 0) throw new ArgumentException(string.Join("\n", errors));
            bool reshaped = !SameShapes(_scene.Obstacles, list);
            _scene.Obstacles = list;
            UploadObstacles();
            if (reshaped) CreateBoundary();
        }

        /// <summary>The same spheres (count, names, radii) at new centres or speeds, as a driven sphere is every frame:
        /// checked with the sphere rules under names made once, and copied into the simulation's own descriptions, so
        /// that nothing is allocated. False when more than that changed (the caller then replaces the list).</summary>
        bool MovedOnly(IReadOnlyList<SphereObstacleDescription> obstacles, int count)
        {
            var current = _scene.Obstacles;
            if (current.Count != count) return false;
            for (int i = 0; i < count; i++)
            {
                SphereObstacleDescription now = current[i], next = obstacles[i];
                if (next == null || now.Name != next.Name || now.Radius != next.Radius) return false;
            }
            if (_obstacleNamesFor != current)
            {
                _obstacleNames = new string[count, 2];
                for (int i = 0; i < count; i++)
                {
                    _obstacleNames[i, 0] = FluidSceneDescription.ObstacleOwner(current[i]);
                    _obstacleNames[i, 1] = FluidSceneDescription.ObstaclePath(i);
                }
                _obstacleNamesFor = current;
            }
            _obstacleErrors.Clear();
            for (int i = 0; i < count; i++)
                FluidSceneDescription.ValidateObstacle(_obstacleErrors, obstacles[i], _obstacleNames[i, 0], _obstacleNames[i, 1]);
            if (_obstacleErrors.Count > 0) throw new ArgumentException(Join(_obstacleErrors));
            for (int i = 0; i < count; i++)
            {
                current[i].Center = obstacles[i].Center;
                current[i].Velocity = obstacles[i].Velocity;
            }
            UploadObstacles();
            return true;
        }

        /// <summary>Same count and radii: the boundary particles only move with the spheres.</summary>
        static bool SameShapes(IReadOnlyList<SphereObstacleDescription> a, IReadOnlyList<SphereObstacleDescription> b)
        {
            int na = a == null ? 0 : a.Count, nb = b == null ? 0 : b.Count;
            if (na != nb) return false;
            for (int i = 0; i < na; i++)
                if (a[i].Radius != b[i].Radius) return false;
            return true;
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
            _particles.SetData(_spawn);
            _numberDensities.SetData(_spawnNumberDensities);
            _clampHits.SetData(new uint[1]);
            _warmStart.SetData(new Vector2[ParticleCount]);
            _solverState.SetData(new uint[16]);
            _solveRounds[DensitySolveSlot] = _solveRounds[DivergenceSolveSlot] = _scene.Settings.MaxSolverIterations;
            ComputeForces();
            // The first frame plans with the acceleration the first force pass computed, not gravity alone.
            ReadMotion(out float firstSpeed, out float firstAcceleration);
            _timeStep.ReportMotion(firstSpeed, firstAcceleration);
        }

        // ---------------------------------------------------------------- diagnostics

        /// <summary>Latest diagnostics read back asynchronously (after <see cref="RequestDiagnostics"/>);
        /// null until one arrives, possibly a frame stale (see <see cref="DiagnosticsReport.SimulatedTime"/>).
        /// The simulation refills this one report in place when a newer read-back arrives (a report a frame would
        /// be garbage a frame): read its figures now, or use <see cref="ReadDiagnostics"/> for a report to keep.</summary>
        public DiagnosticsReport LatestDiagnostics
        {
            get
            {
                PollDiagnostics();
                return _latestDiagnostics;
            }
            private set => _latestDiagnostics = value;
        }

        /// <summary>Records the diagnostics reductions and starts their asynchronous read-back
        /// (ignored while the previous one is still in flight).</summary>
        public void RequestDiagnostics()
        {
            ThrowIfDisposed();
            PollDiagnostics();
            if (_diagnosticsReadback != null) return;
            DispatchDiagnostics();
            _diagnosticsReadback = _device.RequestReadback(_diagnosticsTotals);
            _diagnosticsRequestTime = SimulatedTime;
            _device.Submit();
        }

        /// <summary>Blocking diagnostics of the current state (tools and tests).</summary>
        public DiagnosticsReport ReadDiagnostics()
        {
            ThrowIfDisposed();
            DispatchDiagnostics();
            var rows = new Vector4[3 + _phases.Count];
            _diagnosticsTotals.GetData(rows);
            return ToReport(rows, SimulatedTime);
        }

        void DispatchDiagnostics()
        {
            _device.BeginSample(PassNames.Diagnostics);
            _device.DispatchThreads(_solver, _divergenceRate, ParticleCount);
            _device.Dispatch(_diagnostics, _diagnosticsPartial, _reductionGroups, 1, 1);
            _device.Dispatch(_diagnostics, _diagnosticsFinal, 1, 1, 1);
            _device.EndSample(PassNames.Diagnostics);
        }

        void PollDiagnostics()
        {
            if (_diagnosticsReadback == null || !_diagnosticsReadback.IsDone) return;
            var request = _diagnosticsReadback;
            _diagnosticsReadback = null;
            if (request.HasError) return;
            request.GetData(_diagnosticsRows);
            if (_diagnosticsReport == null)
            {
                _diagnosticsPhases = NewPhaseRows();
                _diagnosticsReport = new DiagnosticsReport(0, 0, 0f, 0, 0, _diagnosticsPhases, 0);
            }
            Refill(_diagnosticsReport, _diagnosticsPhases, _diagnosticsRows, _diagnosticsRequestTime);
            _latestDiagnostics = _diagnosticsReport;
        }

        PhaseDiagnostics[] NewPhaseRows()
        {
            var phases = new PhaseDiagnostics[_phases.Count];
            for (int k = 0; k < phases.Length; k++)
                phases[k] = new PhaseDiagnostics(_phases[k].Name, 0, 0f, 0f);
            return phases;
        }

        DiagnosticsReport ToReport(Vector4[] rows, double time)
        {
            var phases = NewPhaseRows();
            var report = new DiagnosticsReport(0, 0, 0f, 0, 0, phases, time);
            Refill(report, phases, rows, time);
            return report;
        }

        /// <summary>Rows of DiagnosticsFinal: [0] KE, vmax, NaN count, outside count; [1 + k] phase k's count,
        /// mean and max compression; [1 + phases] clamp hits; [2 + phases] mean |D delta / Dt| / delta0 (1/s) and the
        /// DFSPH solves' mean corrections per solve.</summary>
        void Refill(DiagnosticsReport report, PhaseDiagnostics[] phases, Vector4[] rows, double time)
        {
            double mass = 0;
            for (int k = 0; k < phases.Length; k++)
            {
                Vector4 row = rows[1 + k];
                int count = (int)Math.Round(row.X);
                mass += (double)count * _phaseTable[k].ParticleMass;
                phases[k].Refill(count, row.Y, row.Z);
            }
            report.Refill(mass, rows[0].X, rows[0].Y, (int)Math.Round(rows[0].Z), (int)Math.Round(rows[0].W), time,
                (int)Math.Round(rows[1 + _phases.Count].X));
            Vector4 solves = rows[2 + _phases.Count];
            report.DivergenceError = 100f * solves.X;
            report.DensitySolveIterations = solves.Y;
            report.DivergenceSolveIterations = solves.Z;
            report.PressureSolver = _scene.Settings.PressureSolver;
        }

        void RequestMotion()
        {
            if (_motionReadback != null) return; // one in flight: the controller plans with the older figures meanwhile
            _device.BeginSample(PassNames.MotionReduction);
            _device.Dispatch(_diagnostics, _motionPartial, _reductionGroups, 1, 1);
            _device.Dispatch(_diagnostics, _motionFinal, 1, 1, 1);
            _device.EndSample(PassNames.MotionReduction);
            _motionReadback = _device.RequestReadback(_motionTotals);
        }

        void PollMotion()
        {
            if (_motionReadback == null || !_motionReadback.IsDone) return;
            var request = _motionReadback;
            _motionReadback = null;
            if (request.HasError) return;
            request.GetData(_motionRow);
            _timeStep.ReportMotion(_motionRow[0].X, _motionRow[0].Y);
            ReportSolveIterations(_motionRow[1]);
        }

        /// <summary>Reads max |v| and max |a| now (blocking) and feeds the time-step controller.</summary>
        public void ReadMotion(out float maxSpeed, out float maxAcceleration)
        {
            ThrowIfDisposed();
            _device.Dispatch(_diagnostics, _motionPartial, _reductionGroups, 1, 1);
            _device.Dispatch(_diagnostics, _motionFinal, 1, 1, 1);
            _motionTotals.GetData(_motionRow);
            ReportSolveIterations(_motionRow[1]);
            maxSpeed = _motionRow[0].X;
            maxAcceleration = _motionRow[0].Y;
        }

        // ---------------------------------------------------------------- set-up

        void CreateBuffers()
        {
            int n = ParticleCount;
            _particles = _device.CreateBuffer("FluidSimulation.Particles", n, Particle.Stride);
            _particlesOther = _device.CreateBuffer("FluidSimulation.ParticlesSorted", n, Particle.Stride);
            _phaseBuffer = _device.CreateBuffer("FluidSimulation.Phases", _phaseTable.Length, PhaseProperties.Stride);
            _phaseBuffer.SetData(_phaseTable);
            _densities = _device.CreateBuffer("FluidSimulation.Densities", n, 16);
            _normalsBuffer = _device.CreateBuffer("FluidSimulation.Normals", n, 16);
            _accelerations = _device.CreateBuffer("FluidSimulation.Accelerations", n, 16);
            _xsph = _device.CreateBuffer("FluidSimulation.XsphCorrections", n, 16);
            _shifts = _device.CreateBuffer("FluidSimulation.Shifts", n, 16);
            _obstacles = _device.CreateBuffer("FluidSimulation.Obstacles", FluidSceneDescription.MaxObstacles, SphereObstacleData.Stride);
            _motionPartials = _device.CreateBuffer("FluidSimulation.MotionPartials", _reductionGroups, 16);
            _motionTotals = _device.CreateBuffer("FluidSimulation.MotionTotals", 2, 16);
            _diagnosticsPartials = _device.CreateBuffer("FluidSimulation.DiagnosticsPartials", _reductionGroups * (2 + _phases.Count), 16);
            _diagnosticsTotals = _device.CreateBuffer("FluidSimulation.DiagnosticsTotals", 3 + _phases.Count, 16);
            int particleGroups = ComputeDispatch.GroupsFor(n, ParticleThreads);
            _factors = _device.CreateBuffer("FluidSimulation.DivergenceFreeFactors", n, 4);
            _solverStiffness = _device.CreateBuffer("FluidSimulation.SolverStiffness", n, 4);
            _warmStart = _device.CreateBuffer("FluidSimulation.WarmStart", n, 8);
            _solverPartials = _device.CreateBuffer("FluidSimulation.SolverPartials", particleGroups, 4);
            _solverState = _device.CreateBuffer("FluidSimulation.SolverState", 16, 4);
            _solverArguments = _device.CreateArgumentsBuffer("FluidSimulation.SolverArguments", 3);
            _divergenceRates = _device.CreateBuffer("FluidSimulation.DivergenceRates", n, 4);
            _numberDensities = _device.CreateBuffer("FluidSimulation.NumberDensities", n, 4);
            _numberDensitiesHalf = _device.CreateBuffer("FluidSimulation.NumberDensitiesHalf", n, 4);
            _densityRates = _device.CreateBuffer("FluidSimulation.DensityRates", n, 8);
            _numberDensities.SetData(_spawnNumberDensities);
            _numberDensitiesHalf.SetData(_spawnNumberDensities);
            _densityRates.SetData(new Vector2[n]);
            _factors.SetData(new float[n]);
            _solverStiffness.SetData(new float[n]);
            _warmStart.SetData(new Vector2[n]);
            _solverPartials.SetData(new float[particleGroups]);
            _solverState.SetData(new uint[16]);
            _solverArguments.SetData(new uint[] { (uint)particleGroups, 1u, 1u });
            _divergenceRates.SetData(new float[n]);
            _clampHits = _device.CreateBuffer("FluidSimulation.ClampHits", 1, 4);
            _clampHits.SetData(new uint[1]);

            var zero = new Vector4[n];
            _accelerations.SetData(zero);
            _xsph.SetData(zero);
            _shifts.SetData(zero);
            _normalsBuffer.SetData(zero);
            _densities.SetData(zero);

            RebuildGrid();
            BindParticleBuffers();

            foreach (int k in _solverKernels)
            {
                _device.SetBuffer(_solver, k, _ids.ClampHits, _clampHits);
                _device.SetBuffer(_solver, k, _ids.Phases, _phaseBuffer);
                _device.SetBuffer(_solver, k, _ids.Densities, _densities);
                _device.SetBuffer(_solver, k, _ids.Normals, _normalsBuffer);
                _device.SetBuffer(_solver, k, _ids.Accelerations, _accelerations);
                _device.SetBuffer(_solver, k, _ids.XsphCorrections, _xsph);
                _device.SetBuffer(_solver, k, _ids.Shifts, _shifts);
                _device.SetBuffer(_solver, k, _ids.Obstacles, _obstacles);
                _device.SetBuffer(_solver, k, _ids.DivergenceFreeFactors, _factors);
                _device.SetBuffer(_solver, k, _ids.SolverStiffness, _solverStiffness);
                _device.SetBuffer(_solver, k, _ids.WarmStart, _warmStart);
                _device.SetBuffer(_solver, k, _ids.SolverPartials, _solverPartials);
                _device.SetBuffer(_solver, k, _ids.SolverState, _solverState);
                _device.SetBuffer(_solver, k, _ids.SolverArguments, _solverArguments);
                _device.SetBuffer(_solver, k, _ids.DivergenceRates, _divergenceRates);
                _device.SetBuffer(_solver, k, _ids.NumberDensities, _numberDensities);
                _device.SetBuffer(_solver, k, _ids.NumberDensitiesHalf, _numberDensitiesHalf);
                _device.SetBuffer(_solver, k, _ids.DensityRates, _densityRates);
            }
            foreach (int k in _diagnosticsKernels)
            {
                _device.SetBuffer(_diagnostics, k, _ids.Phases, _phaseBuffer);
                _device.SetBuffer(_diagnostics, k, _ids.Densities, _densities);
                _device.SetBuffer(_diagnostics, k, _ids.Accelerations, _accelerations);
                _device.SetBuffer(_diagnostics, k, _ids.MotionPartials, _motionPartials);
                _device.SetBuffer(_diagnostics, k, _ids.MotionTotals, _motionTotals);
                _device.SetBuffer(_diagnostics, k, _ids.DiagnosticsPartials, _diagnosticsPartials);
                _device.SetBuffer(_diagnostics, k, _ids.DiagnosticsTotals, _diagnosticsTotals);
                _device.SetBuffer(_diagnostics, k, _ids.Obstacles, _obstacles);
                _device.SetBuffer(_diagnostics, k, _ids.ClampHits, _clampHits);
                _device.SetBuffer(_diagnostics, k, _ids.DivergenceRates, _divergenceRates);
                _device.SetBuffer(_diagnostics, k, _ids.SolverState, _solverState);
            }
        }

        /// <summary>Samples the walls and obstacles (BoundarySampling) into new boundary buffers and a sorter for
        /// them; they are placed in the world and sorted before the next sub-step.</summary>
        void CreateBoundary()
        {
            ReleaseBoundary();
            var rest = BoundarySampling.Sample(_scene);
            _boundaryCount = rest.Length;
            _boundaryRest = _device.CreateBuffer("FluidSimulation.BoundaryRest", _boundaryCount, BoundaryParticle.Stride);
            _boundaryRest.SetData(rest);
            _boundaryPlaced = _device.CreateBuffer("FluidSimulation.BoundaryPlaced", _boundaryCount, BoundaryParticle.Stride);
            _boundarySorted = _device.CreateBuffer("FluidSimulation.BoundarySorted", _boundaryCount, BoundaryParticle.Stride);
            _boundaryPressures = _device.CreateBuffer("FluidSimulation.BoundaryPressures", _boundaryCount, 4);
            _boundaryPressures.SetData(new float[_boundaryCount]);
            _boundarySorter = new ParticleSorter(_device, _boundaryCount, _grid.CellCount);
            foreach (int k in _solverKernels)
            {
                _device.SetBuffer(_solver, k, _ids.BoundaryRest, _boundaryRest);
                _device.SetBuffer(_solver, k, _ids.BoundaryPlaced, _boundaryPlaced);
                _device.SetBuffer(_solver, k, _ids.BoundaryParticles, _boundarySorted);
                _device.SetBuffer(_solver, k, _ids.BoundaryPressures, _boundaryPressures);
                _device.SetBuffer(_solver, k, _ids.BoundaryCellStart, _boundarySorter.CellStart);
                _device.SetBuffer(_solver, k, _ids.BoundaryCellCount, _boundarySorter.CellCount);
            }
            _device.SetInt(_solver, _ids.BoundaryCount, _boundaryCount);
            _boundaryMoved = true;
        }

        void ReleaseBoundary()
        {
            foreach (var buffer in new[] { _boundaryRest, _boundaryPlaced, _boundarySorted, _boundaryPressures })
                buffer?.Dispose();
            _boundaryRest = _boundaryPlaced = _boundarySorted = _boundaryPressures = null;
            _boundarySorter?.Dispose();
            _boundarySorter = null;
        }

        /// <summary>A new grid for the container's size (and a larger sorter if it needs more cells).</summary>
        void RebuildGrid()
        {
            var c = _scene.Container;
            _grid = new CellGrid(c.Position, c.Rotation, c.Size, _scene.Settings.SmoothingRadius);
            if (_sorter == null || _grid.CellCount > _sorter.MaxCellCount)
            {
                _sorter?.Dispose();
                _sorter = null;
                _sorter = new ParticleSorter(_device, ParticleCount, _grid.CellCount);
                foreach (int k in _solverKernels)
                {
                    _device.SetBuffer(_solver, k, _ids.CellStart, _sorter.CellStart);
                    _device.SetBuffer(_solver, k, _ids.CellCount, _sorter.CellCount);
                }
            }
            _containerChanged = true;
        }

        void SwapParticleBuffers()
        {
            var t = _particles;
            _particles = _particlesOther;
            _particlesOther = t;
            BindParticleBuffers();
        }

        void BindParticleBuffers()
        {
            foreach (int k in _solverKernels)
                _device.SetBuffer(_solver, k, _ids.Particles, _particles);
            foreach (int k in _diagnosticsKernels)
                _device.SetBuffer(_diagnostics, k, _ids.Particles, _particles);
        }

        /// <summary>Values fixed for the simulation's lifetime: counts, kernel coefficients, material constants.</summary>
        void UploadConstants()
        {
            var s = _scene.Settings;
            double h = s.SmoothingRadius;
            foreach (var program in _programs)
            {
                _device.SetInt(program, _ids.ParticleCount, ParticleCount);
                _device.SetFloat(program, _ids.ParticleSpacing, s.ParticleSpacing);
            }
            _device.SetInt(_diagnostics, _ids.PhaseCount, _phases.Count);
            _device.SetInt(_diagnostics, _ids.ReductionGroupCount, _reductionGroups);

            _device.SetFloat(_solver, _ids.SmoothingRadius, (float)h);
            _device.SetFloat(_solver, _ids.SmoothingRadius2, (float)(h * h));
            _device.SetFloat(_solver, _ids.KernelCoefficient, (float)(8.0 / (Math.PI * h * h * h)));
            _device.SetFloat(_solver, _ids.GradientCoefficient, (float)(8.0 / (Math.PI * h * h * h * h)));
            _device.SetFloat(_solver, _ids.ArtificialViscosity, (float)(s.ArtificialViscosity * _timeStep.SpeedOfSound * 0.5 * h));
            _device.SetFloat(_solver, _ids.WallArtificialViscosity, (float)(WallContactDamping * _timeStep.SpeedOfSound * 0.5 * h));
            _device.SetFloat(_solver, _ids.WallFriction, _scene.Container.Friction == WallFriction.NoSlip ? 1f : 0f);
            _device.SetFloat(_solver, _ids.CohesionCoefficient, (float)(32.0 / (Math.PI * Math.Pow(h, 9))));
            _device.SetFloat(_solver, _ids.Stiffness, s.Stiffness);
            _device.SetFloat(_solver, _ids.Gamma, s.Gamma);
            _device.SetVector(_solver, _ids.Gravity, new Vector4(s.Gravity, 0f));
            _device.SetFloat(_solver, _ids.XsphEpsilon, s.XsphEpsilon);
            _device.SetFloat(_solver, _ids.ShiftingCoefficient, (float)(s.ParticleShifting * 0.5 * h));
            _device.SetFloat(_solver, _ids.VelocityDamping, s.VelocityDamping);
            _device.SetFloat(_solver, _ids.DensityDiffusion, (float)(DensityDiffusionXi * 0.5 * h * _timeStep.SpeedOfSound));
            _device.SetFloat(_solver, _ids.HydrostaticCompliance, (float)(1.0 / ((double)s.Gamma * s.Stiffness)));
            _device.SetFloat(_solver, _ids.TimeStep, 0f);
        }

        /// <summary>The container's transform and motion, and the grid built on it, to both programs.</summary>
        void UploadContainer()
        {
            var c = _scene.Container;
            var rotation = Quaternion.Normalize(c.Rotation);
            Matrix4x4 worldToContainer = Matrix4x4.Transpose(
                Matrix4x4.CreateTranslation(-c.Position) * Matrix4x4.CreateFromQuaternion(Quaternion.Conjugate(rotation)));
            Matrix4x4 containerToWorld = Matrix4x4.Transpose(
                Matrix4x4.CreateFromQuaternion(rotation) * Matrix4x4.CreateTranslation(c.Position));
            var clampExtent = c.Size * 0.5f - new Vector3(ClampInset * _scene.Settings.ParticleSpacing);
            foreach (var program in _programs)
            {
                _device.SetMatrix(program, _ids.WorldToContainer, worldToContainer);
                _device.SetMatrix(program, _ids.ContainerToWorld, containerToWorld);
                _device.SetVector(program, _ids.ContainerCenter, new Vector4(c.Position, 0f));
                _device.SetVector(program, _ids.ContainerClampExtent, new Vector4(clampExtent, 0f));
                _device.SetVector(program, _ids.ContainerHalfSize, new Vector4(c.Size * 0.5f, 0f));
                _device.SetVector(program, _ids.ContainerVelocity, new Vector4(c.Velocity, 0f));
                _device.SetVector(program, _ids.ContainerAngularVelocity, new Vector4(c.AngularVelocity, 0f));
            }
            _grid.SetOn(_device, _solver);
            _containerChanged = false;
            _boundaryMoved = true;
        }

        void UploadObstacles()
        {
            var rows = _obstacleRows;
            int count = _scene.Obstacles == null ? 0 : _scene.Obstacles.Count;
            for (int i = 0; i < count; i++)
                rows[i] = new SphereObstacleData(_scene.Obstacles[i]);
            if (count == 0) rows[0] = default;
            _obstacles.SetData(rows, 0, 0, Math.Max(count, 1));
            foreach (var program in _programs)
                _device.SetInt(program, _ids.ObstacleCount, count);
            _boundaryMoved = true;
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
            var obstacles = new List<SphereObstacleDescription>();
            if (scene.Obstacles != null)
                foreach (var o in scene.Obstacles) obstacles.Add(o?.Clone());
            return new FluidSceneDescription
            {
                Settings = scene.Settings?.Clone(),
                SpawnBoxes = scene.SpawnBoxes == null ? null : new List<SpawnBoxDescription>(scene.SpawnBoxes),
                Container = scene.Container?.Clone(),
                Obstacles = obstacles,
            };
        }

        static string Join(List<ValidationError> errors)
        {
            var messages = new string[errors.Count];
            for (int i = 0; i < messages.Length; i++) messages[i] = errors[i].Message;
            return string.Join("\n", messages);
        }

        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            _motionReadback = null;
            _diagnosticsReadback = null;
            foreach (var buffer in new[] { _particles, _particlesOther, _phaseBuffer, _densities, _normalsBuffer, _accelerations,
                         _xsph, _shifts, _obstacles, _motionPartials, _motionTotals, _diagnosticsPartials, _diagnosticsTotals, _clampHits,
                         _factors, _solverStiffness, _warmStart, _solverPartials, _solverState, _solverArguments, _divergenceRates,
                         _numberDensities, _numberDensitiesHalf, _densityRates })
                buffer?.Dispose();
            _numberDensities = _numberDensitiesHalf = _densityRates = null;
            _factors = _solverStiffness = _warmStart = _solverPartials = _solverState = _solverArguments = _divergenceRates = null;
            _particles = _particlesOther = _phaseBuffer = _densities = _normalsBuffer = _accelerations = null;
            _xsph = _shifts = _obstacles = _motionPartials = _motionTotals = _diagnosticsPartials = _diagnosticsTotals = _clampHits = null;
            ReleaseBoundary();
            _sorter?.Dispose();
            _sorter = null;
        }

        void ThrowIfDisposed()
        {
            if (_disposed) throw new ObjectDisposedException(nameof(FluidSimulation));
        }

        /// <summary>Property ids, looked up once.</summary>
        sealed class ShaderIds
        {
            public readonly int Particles, Phases, Densities, Normals, Accelerations, XsphCorrections, Shifts, Obstacles, CellStart, CellCount;
            public readonly int ShiftingCoefficient;
            public readonly int MotionPartials, MotionTotals, DiagnosticsPartials, DiagnosticsTotals;
            public readonly int ParticleCount, PhaseCount, ReductionGroupCount, ObstacleCount, TimeStep;
            public readonly int SmoothingRadius, SmoothingRadius2, KernelCoefficient, GradientCoefficient, CohesionCoefficient;
            public readonly int Stiffness, Gamma, Gravity, XsphEpsilon, VelocityDamping, ParticleSpacing, WallFriction, ArtificialViscosity, WallArtificialViscosity;
            public readonly int WorldToContainer, ContainerToWorld, ContainerCenter, ContainerClampExtent, ContainerHalfSize, ContainerVelocity, ContainerAngularVelocity;
            public readonly int BoundaryRest, BoundaryPlaced, BoundaryParticles, BoundaryPressures, BoundaryCellStart, BoundaryCellCount, BoundaryCount, ClampHits;
            public readonly int DivergenceFreeFactors, SolverStiffness, WarmStart, SolverPartials, SolverState, SolverArguments, DivergenceRates;
            public readonly int SolveSlot, SolveTolerance, SolveRounds;
            public readonly int NumberDensities, NumberDensitiesHalf, DensityRates, DensityDiffusion, HydrostaticCompliance;

            public ShaderIds(IComputeDevice d)
            {
                Particles = d.PropertyId("_Particles");
                Phases = d.PropertyId("_Phases");
                Densities = d.PropertyId("_Densities");
                Normals = d.PropertyId("_Normals");
                Accelerations = d.PropertyId("_Accelerations");
                XsphCorrections = d.PropertyId("_XsphCorrections");
                Shifts = d.PropertyId("_Shifts");
                ShiftingCoefficient = d.PropertyId("_ShiftingCoefficient");
                Obstacles = d.PropertyId("_Obstacles");
                CellStart = d.PropertyId(ParticleSorter.CellStartProperty);
                CellCount = d.PropertyId(ParticleSorter.CellCountProperty);
                MotionPartials = d.PropertyId("_MotionPartials");
                MotionTotals = d.PropertyId("_MotionTotals");
                DiagnosticsPartials = d.PropertyId("_DiagnosticsPartials");
                DiagnosticsTotals = d.PropertyId("_DiagnosticsTotals");
                ParticleCount = d.PropertyId("_ParticleCount");
                PhaseCount = d.PropertyId("_PhaseCount");
                ReductionGroupCount = d.PropertyId("_ReductionGroupCount");
                ObstacleCount = d.PropertyId("_ObstacleCount");
                TimeStep = d.PropertyId("_TimeStep");
                SmoothingRadius = d.PropertyId("_SmoothingRadius");
                SmoothingRadius2 = d.PropertyId("_SmoothingRadius2");
                KernelCoefficient = d.PropertyId("_KernelCoefficient");
                GradientCoefficient = d.PropertyId("_GradientCoefficient");
                WallFriction = d.PropertyId("_WallFriction");
                ArtificialViscosity = d.PropertyId("_ArtificialViscosity");
                WallArtificialViscosity = d.PropertyId("_WallArtificialViscosity");
                BoundaryRest = d.PropertyId("_BoundaryRest");
                BoundaryPlaced = d.PropertyId("_BoundaryPlaced");
                BoundaryParticles = d.PropertyId("_BoundaryParticles");
                BoundaryPressures = d.PropertyId("_BoundaryPressures");
                BoundaryCellStart = d.PropertyId("_BoundaryCellStart");
                BoundaryCellCount = d.PropertyId("_BoundaryCellCount");
                BoundaryCount = d.PropertyId("_BoundaryCount");
                ClampHits = d.PropertyId("_ClampHits");
                DivergenceFreeFactors = d.PropertyId("_DivergenceFreeFactors");
                SolverStiffness = d.PropertyId("_SolverStiffness");
                WarmStart = d.PropertyId("_WarmStart");
                SolverPartials = d.PropertyId("_SolverPartials");
                SolverState = d.PropertyId("_SolverState");
                SolverArguments = d.PropertyId("_SolverArguments");
                DivergenceRates = d.PropertyId("_DivergenceRates");
                SolveSlot = d.PropertyId("_SolveSlot");
                SolveTolerance = d.PropertyId("_SolveTolerance");
                SolveRounds = d.PropertyId("_SolveRounds");
                NumberDensities = d.PropertyId("_NumberDensities");
                NumberDensitiesHalf = d.PropertyId("_NumberDensitiesHalf");
                DensityRates = d.PropertyId("_DensityRates");
                DensityDiffusion = d.PropertyId("_DensityDiffusion");
                HydrostaticCompliance = d.PropertyId("_HydrostaticCompliance");
                CohesionCoefficient = d.PropertyId("_CohesionCoefficient");
                Stiffness = d.PropertyId("_Stiffness");
                Gamma = d.PropertyId("_Gamma");
                Gravity = d.PropertyId("_Gravity");
                XsphEpsilon = d.PropertyId("_XsphEpsilon");
                VelocityDamping = d.PropertyId("_VelocityDamping");
                ParticleSpacing = d.PropertyId("_ParticleSpacing");
                WorldToContainer = d.PropertyId("_WorldToContainer");
                ContainerToWorld = d.PropertyId("_ContainerToWorld");
                ContainerCenter = d.PropertyId("_ContainerCenter");
                ContainerHalfSize = d.PropertyId("_ContainerHalfSize");
                ContainerClampExtent = d.PropertyId("_ContainerClampExtent");
                ContainerVelocity = d.PropertyId("_ContainerVelocity");
                ContainerAngularVelocity = d.PropertyId("_ContainerAngularVelocity");
            }
        }
    }
}
