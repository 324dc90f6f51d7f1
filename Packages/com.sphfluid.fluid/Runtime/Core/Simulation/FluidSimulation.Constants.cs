using System;
using System.Numerics;
using SphFluid.Compute;
using SphFluid.Sorting;

namespace SphFluid.Simulation
{
    /// <summary>The constant buffer (<see cref="FluidConstants"/>, Include/FluidConstants.hlsl): what each value is set from,
    /// and its upload, recorded once between dispatches when a value changed, so that the dispatches after it read the new
    /// values and those before it the old.</summary>
    public sealed partial class FluidSimulation
    {
        /// <summary>The sub-step's dt, uploaded before its first dispatch when it changed (a frame's sub-steps share one).</summary>
        void SetTimeStep(float dt)
        {
            if (_constants[0].TimeStep != dt)
            {
                _constants[0].TimeStep = dt;
                _constants[0].DivergenceSolveTolerance = DivergenceSolveTolerance.At(_scene.Settings, dt);
                SetViscositySolve(dt);
                _constantsChanged = true;
            }
            PushConstants();
        }

        /// <summary>False: the viscous force stays explicit at any step, past its limit too (tests of that limit, which
        /// choose their steps with StepFixed: the step controller still plans with the solve). True by default.</summary>
        public bool ImplicitViscosityAllowed
        {
            get => _implicitViscosityAllowed;
            set
            {
                _implicitViscosityAllowed = value;
                SetViscositySolve(_constants[0].TimeStep);
                _constantsChanged = true;
            }
        }

        bool _implicitViscosityAllowed = true;

        /// <summary>The implicit viscosity solve for sub-steps of <paramref name="dt"/> beyond the explicit force's limit
        /// (<see cref="ImplicitViscosity"/>), or none: its interval tells the kernels which.</summary>
        void SetViscositySolve(float dt)
        {
            var solver = _scene.Settings.PressureSolver;
            double span = ImplicitViscosity.Span(solver, dt);
            _viscosity = _implicitViscosityAllowed && ImplicitViscosity.Needed(dt, _timeStep.ViscousTimeStep)
                ? ImplicitViscosity.For(_viscousRowSum, _timeStep.OperatorViscosity, span)
                : default;
            _constants[0].ViscositySolveLow = _viscosity.Rounds > 0 ? _viscosity.Low : 0f;
            _constants[0].ViscositySolveHigh = _viscosity.Rounds > 0 ? ImplicitViscosity.High : 0f;
            _constants[0].ViscositySolveStep = _viscosity.StageStep;
            _constants[0].ViscositySolveSpan = (float)span;
        }

        /// <summary>The rounds each DFSPH solve records (<see cref="SolveRounds"/>), which the fold counts against
        /// (FoldSolveErrors).</summary>
        void WriteSolveRounds()
        {
            ref FluidConstants c = ref _constants[0];
            uint density = (uint)_solveRounds[DensitySolveSlot], divergence = (uint)_solveRounds[DivergenceSolveSlot];
            if (c.DensitySolveRounds == density && c.DivergenceSolveRounds == divergence) return;
            c.DensitySolveRounds = density;
            c.DivergenceSolveRounds = divergence;
            _constantsChanged = true;
        }

        /// <summary>Values fixed for the simulation's lifetime (counts, kernel coefficients, material constants) and the wall
        /// friction, into the constants the next <see cref="PushConstants"/> uploads.</summary>
        void WriteConstants()
        {
            var s = _scene.Settings;
            double h = s.SmoothingRadius;
            ref FluidConstants c = ref _constants[0];
            c.ParticleCount = (uint)ParticleCount;
            c.NeighbourLanes = (uint)NeighbourLanes.For(ParticleCount, _device.RunsOnCpu);
            c.NeighbourListRows = (uint)NeighbourCapacity.ListRows(s.PressureSolver);
            UseNeighbourLists();
            c.PhaseCount = (uint)_phases.Count;
            c.ReductionGroupCount = (uint)_reductionGroups;
            c.ParticleSpacing = s.ParticleSpacing;
            c.SmoothingRadius = (float)h;
            c.SmoothingRadius2 = (float)(h * h);
            c.SmoothingKernel = (uint)s.SmoothingKernel;
            c.KernelCoefficient = (float)SmoothingKernels.Normalisation(s.SmoothingKernel, h);
            c.GradientCoefficient = (float)(SmoothingKernels.Normalisation(s.SmoothingKernel, h) / h);
            c.ArtificialViscosity = (float)(s.ArtificialViscosity * _timeStep.SpeedOfSound * 0.5 * h);
            c.WallArtificialViscosity = (float)(WallContactDamping * _timeStep.SpeedOfSound * 0.5 * h);
            c.WallContactNumberDensity = (float)SmoothingKernels.FlatWallNumberDensity(s.SmoothingKernel, s.ParticleSpacing, h);
            c.WallContactAtAnyDensity = _deltaSph ? 1u : 0u;
            c.SolverRelaxation = s.SolverRelaxation;
            double depth = SpawnLayout.Depth(_spawn, s.Gravity, s.ParticleSpacing);
            var (low, high) = _divergenceFree && s.SolverIteration == SolverIteration.Chebyshev
                ? ChebyshevBounds.For(s.SmoothingKernel, s.ParticleSpacing, h, s.SolverRelaxation, depth)
                : (0.0, 0.0);
            c.ChebyshevLow = (float)low;
            c.ChebyshevHigh = (float)high;
            c.AcceleratedDensitySolve = high > 0.0 && ChebyshevBounds.AcceleratesDensitySolve(s.DensityTolerance, depth, s.ParticleSpacing) ? 1u : 0u;
            c.WallFriction = _scene.Container.Friction == WallFriction.NoSlip ? 1f : 0f;
            c.StrainRateViscosity = s.ViscousStress == ViscousStress.StrainRate ? 1u : 0u;
            c.SurfaceForceScale = (float)(1.0 / (h * SurfaceLayerShare.For(s.SmoothingKernel, h / s.ParticleSpacing)));
            c.Stiffness = s.Stiffness;
            c.Gamma = s.Gamma;
            c.Gravity = s.Gravity;
            c.XsphEpsilon = s.XsphEpsilon;
            c.ShiftingCoefficient = (float)(s.ParticleShifting * 0.5 * h);
            c.VelocityDamping = s.VelocityDamping;
            c.DensityDiffusion = (float)(DensityDiffusionXi * 0.5 * h * _timeStep.SpeedOfSound);
            c.HydrostaticCompliance = (float)(1.0 / ((double)s.Gamma * s.Stiffness));
            c.DensitySolveTolerance = DensityPredictionMargin * 0.01f * s.DensityTolerance;
            c.DivergenceSolveTolerance = DivergenceSolveTolerance.At(s, c.TimeStep);
            _constantsChanged = true;
        }

        /// <summary>The container's transform and motion into the constants: as placed for this frame, moved by its
        /// velocity and angular velocity (about its centre) for <paramref name="elapsed"/> seconds (negative: before
        /// it got there).</summary>
        void WriteContainer(float elapsed)
        {
            var container = _scene.Container;
            var rotation = Quaternion.Normalize(container.Rotation);
            float spin = container.AngularVelocity.Length() * elapsed;
            if (spin != 0f)
                rotation = Quaternion.Normalize(Quaternion.Concatenate(rotation,
                    Quaternion.CreateFromAxisAngle(Vector3.Normalize(container.AngularVelocity), spin)));
            var position = container.Position + container.Velocity * elapsed;
            _containerPosition = position;
            _containerRotation = rotation;
            _gridBehind |= GridOffset(position, rotation, container.Size) > GridSlack * CellGrid.CellsPerSupport * _grid.CellSize;
            ref FluidConstants c = ref _constants[0];
            c.WorldToContainer = Matrix4x4.Transpose(
                Matrix4x4.CreateTranslation(-position) * Matrix4x4.CreateFromQuaternion(Quaternion.Conjugate(rotation)));
            c.ContainerToWorld = Matrix4x4.Transpose(
                Matrix4x4.CreateFromQuaternion(rotation) * Matrix4x4.CreateTranslation(position));
            c.ContainerCenter = position;
            c.ContainerClampExtent = container.Size * 0.5f - new Vector3(ClampInset * _scene.Settings.ParticleSpacing);
            c.ContainerHalfSize = container.Size * 0.5f;
            c.ContainerVelocity = container.Velocity;
            c.ContainerAngularVelocity = container.AngularVelocity;
            _constantsChanged = true;
            _containerChanged = false;
            _boundaryMoved = true;
        }

        /// <summary>How far the grid may lag its container, in support radii h, before the next sort places it again: well inside
        /// its margin (h), and a container that moves slowly or only wobbles does not make every sub-step sort its walls again.
        /// In h, not in cells: the margin kept its h when the cells became h/2 (CellGrid.CellsPerSupport), so the lag it
        /// absorbs did too, and a moving container's grid is placed again as often as before, not twice as often.</summary>
        const float GridSlack = 0.25f;

        /// <summary>An upper bound on how far any point of the container (<paramref name="size"/>) at this placement lies
        /// from where the grid's placement puts it, m: the centre's offset plus the turn between them times the half-diagonal.</summary>
        float GridOffset(Vector3 position, Quaternion rotation, Vector3 size)
        {
            float cosHalf = Math.Min(1f, Math.Abs(Quaternion.Dot(rotation, _grid.Rotation)));
            float turn = 2f * (float)Math.Acos(cosHalf);
            return Vector3.Distance(position, _grid.Centre) + turn * 0.5f * size.Length();
        }

        /// <summary>The grid as <see cref="Sort"/> last placed it into the constants.</summary>
        void WriteGrid()
        {
            ref FluidConstants c = ref _constants[0];
            c.WorldToGrid = _grid.WorldToGrid;
            c.GridDims = new UInt3((uint)_grid.DimX, (uint)_grid.DimY, (uint)_grid.DimZ);
            c.GridCellCount = (uint)_grid.CellCount;
            _constantsChanged = true;
        }

        /// <summary>Records the constants' upload when a value changed since the last one: the dispatches recorded after it
        /// read the new values, those before it the old.</summary>
        void PushConstants()
        {
            if (!_constantsChanged) return;
            _device.UpdateBuffer(_buffers.Constants, _constants);
            _constantsChanged = false;
        }
    }
}
