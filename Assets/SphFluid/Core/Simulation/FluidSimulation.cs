using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Compute;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The whole SPH pipeline, written once against <see cref="IComputeDevice"/> so that Unity and the
    /// headless backend dispatch the very same kernels in the very same order. Read <see cref="Step"/>
    /// top to bottom for one frame.
    /// </summary>
    public sealed class FluidSimulation : IDisposable
    {
        const int ReductionGroupSize = 256;

        readonly IComputeDevice _device;
        readonly FluidSceneDescription _scene;
        readonly PhaseProperties[] _phaseTable;
        readonly IReadOnlyList<PhaseDescription> _phases;
        readonly TimeStepController _timeStep;
        bool _disposed;

        public FluidSimulation(IComputeDevice device, FluidSceneDescription scene)
        {
            _device = device ?? throw new ArgumentNullException(nameof(device));
            if (scene == null) throw new ArgumentNullException(nameof(scene));
            scene.ThrowIfInvalid();
            _scene = scene;
            _phases = scene.Phases();
            _phaseTable = scene.BuildPhaseTable();
            _timeStep = TimeStepController.ForScene(scene);
            ParticleCount = SpawnLayout.TotalCount(scene);
            Plan = PipelinePlanner.Plan(scene, true);
            LastStep = StepReport.None;
        }

        /// <summary>Number of particles (constant: none is ever created or lost).</summary>
        public int ParticleCount { get; }

        /// <summary>The particles (<see cref="Particle"/>), sorted by grid cell after every step. Shader name <c>_Particles</c>.</summary>
        public IComputeBuffer Particles { get; private set; }

        /// <summary>The phase table (<see cref="PhaseProperties"/>), indexed by <see cref="Particle.Phase"/>. Shader name <c>_Phases</c>.</summary>
        public IComputeBuffer PhaseTable { get; private set; }

        /// <summary>What the last frame ran (variants and passes).</summary>
        public SimulationPlan Plan { get; private set; }

        /// <summary>How the last frame was covered by sub-steps.</summary>
        public StepReport LastStep { get; private set; }

        /// <summary>Simulated time since spawn or <see cref="Reset"/>, s.</summary>
        public double SimulatedTime { get; private set; }

        /// <summary>The adaptive time-step state (speed of sound, motion last read back).</summary>
        public TimeStepController TimeStep => _timeStep;

        /// <summary>Phases in phase-table order.</summary>
        public IReadOnlyList<PhaseDescription> Phases => _phases;

        /// <summary>Host copy of the phase table.</summary>
        public IReadOnlyList<PhaseProperties> PhaseRows => _phaseTable;

        /// <summary>Latest diagnostics read back asynchronously (after <see cref="RequestDiagnostics"/>); may be null or a frame stale.</summary>
        public DiagnosticsReport LatestDiagnostics { get; private set; }

        /// <summary>Advances the simulation by one frame of <paramref name="frameSeconds"/> real time.</summary>
        public StepReport Step(float frameSeconds)
        {
            ThrowIfDisposed();
            LastStep = _timeStep.PlanFrame(frameSeconds);
            SimulatedTime += LastStep.SimulatedSeconds;
            return LastStep;
        }

        /// <summary>Moves the container; its transform is uploaded before the next step.</summary>
        public void UpdateContainer(ContainerDescription container)
        {
            ThrowIfDisposed();
            if (container == null) throw new ArgumentNullException(nameof(container));
        }

        /// <summary>Replaces the sphere obstacles (the count may not grow beyond the scene's).</summary>
        public void UpdateObstacles(IReadOnlyList<SphereObstacleDescription> obstacles)
        {
            ThrowIfDisposed();
        }

        /// <summary>Respawns every particle as at construction.</summary>
        public void Reset()
        {
            ThrowIfDisposed();
            SimulatedTime = 0;
            _timeStep.Reset();
        }

        /// <summary>Starts an asynchronous diagnostics reduction; the result appears in <see cref="LatestDiagnostics"/>.</summary>
        public void RequestDiagnostics()
        {
            ThrowIfDisposed();
        }

        /// <summary>Blocking diagnostics (tools and tests).</summary>
        public DiagnosticsReport ReadDiagnostics()
        {
            ThrowIfDisposed();
            return null;
        }

        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
        }

        void ThrowIfDisposed()
        {
            if (_disposed) throw new ObjectDisposedException(nameof(FluidSimulation));
        }
    }
}
