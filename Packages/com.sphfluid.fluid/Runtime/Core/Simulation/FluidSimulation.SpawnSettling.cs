using System;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>A DFSPH spawn moved to rest density before the first step, instead of kicked there by it.</summary>
    public sealed partial class FluidSimulation
    {
        /// <summary>Constant-density solves that settle a DFSPH spawn (<see cref="SettledSpawn"/>): in OilAndWater one left
        /// 0.10 % average compression and a third changed nothing measurable.</summary>
        const int SpawnSettlingSolves = 2;

        /// <summary>The settling solves' tolerance, a fraction of the scene's: at the scene's own the settled spawn kept
        /// 0.10 % average compression (0.55 % at most), which a short first step still turned into a kick.</summary>
        const float SpawnSettlingTolerance = 0.1f;

        /// <summary>
        /// The spawn, its particles moved apart where its jitter packed them above rest density. The spawn lattice sits at
        /// rest density, but its jitter packs some particles closer (OilAndWater: 0.38 % on average, up to 3.08 %). The
        /// first constant-density solve would remove that within one sub-step, so the velocity it left went as the error
        /// over the step: the shorter the step, the harder the kick. Here the solves run on the spawn held still, without
        /// forces: their drift is kept and their velocity dropped, so the particles start where the solve would have moved
        /// them, at their box's velocity, whatever the step. A solve from rest drifts the step times a velocity that goes
        /// as one over the step, so the step they run at does not matter; they run at the longest the scene allows.
        /// Once, at construction (two blocking read-backs of the particles): <see cref="Reset"/> respawns the result.
        /// </summary>
        Particle[] SettledSpawn(Particle[] spawn)
        {
            var held = new Particle[spawn.Length];
            Array.Copy(spawn, held, spawn.Length);
            float sceneTolerance = _constants[0].DensitySolveTolerance;
            _constants[0].DensitySolveTolerance = SpawnSettlingTolerance * sceneTolerance;
            _constantsChanged = true;
            _solveRounds[DensitySolveSlot] = _scene.Settings.MaxSolverIterations;
            WriteSolveRounds();
            BeginFrame(0f);
            SetTimeStep(_scene.Settings.MaxTimeStep);
            for (int s = 0; s < SpawnSettlingSolves; s++)
            {
                for (int i = 0; i < held.Length; i++) held[i].Velocity = Vector3.Zero;
                _buffers.Particles.SetData(held);
                _buffers.ClearForRespawn(); // no warm start: each solve starts from the particles at rest
                SortAndComputeForces(false); // density and factor where the particles stand
                Solve(DensitySolveSlot, _kernels.BeginDensitySolve, _kernels.DensitySolveError);
                SolverPass(PassNames.Drift, _kernels.Drift);
                _buffers.Particles.GetData(held);
            }
            _constants[0].DensitySolveTolerance = sceneTolerance;
            _constantsChanged = true;
            var settled = new Particle[spawn.Length];
            foreach (var p in held)
                settled[p.Id] = new Particle(p.Position, spawn[p.Id].Velocity, p.Phase, p.Id);
            return settled;
        }
    }
}
