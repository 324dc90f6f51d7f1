using System;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>A DFSPH spawn moved to rest density before the first step, instead of kicked there by it.</summary>
    public sealed partial class FluidSimulation
    {
        /// <summary>Constant-density solves that always settle a DFSPH spawn (<see cref="SettledSpawn"/>): in OilAndWater one
        /// left 0.10 % average compression and a third changed nothing measurable at the scene's own step.</summary>
        const int SpawnSettlingSolves = 2;

        /// <summary>The most solves a spawn gets while what they leave would still kick the first step harder than gravity
        /// does (<see cref="SettledSpawn"/>): OilAndWater at a 0.039 ms step needs all of them.</summary>
        const int MaxSpawnSettlingSolves = 20;

        /// <summary>The settling solves' tolerance, a fraction of the scene's: at the scene's own the settled spawn kept
        /// 0.10 % average compression (0.55 % at most), which a short first step still turned into a kick.</summary>
        const float SpawnSettlingTolerance = 0.1f;

        /// <summary>The tolerance of the solves beyond <see cref="SpawnSettlingSolves"/>, a fraction of the scene's. After
        /// twenty solves OilAndWater's most compressed particle stood 0.005 % over rest density at a hundredth, and its
        /// first frame at 0.039 ms steps still gained 1.0 mJ of mechanical energy; at a thousandth 0.001 %, and it lost
        /// 0.07 mJ. (At a tenth ten solves left 0.05 %.)</summary>
        const float FineSpawnSettlingTolerance = 0.001f;

        /// <summary>
        /// The spawn, its particles moved apart where its jitter packed them above rest density. The spawn lattice sits at
        /// rest density, but its jitter packs some particles closer (OilAndWater: 0.38 % on average, up to 3.08 %). The
        /// first constant-density solve would remove that within one sub-step, so the velocity it left went as the error
        /// over the step: the shorter the step, the harder the kick. Here the solves run on the spawn held still, without
        /// forces: their drift is kept and their velocity dropped, so the particles start where the solve would have moved
        /// them, at their box's velocity, whatever the step. A solve from rest drifts the step times a velocity that goes
        /// as one over the step, so the step they run at does not matter; they run at the longest the scene allows.
        /// What they leave is still removed within the first step, so a short enough step turns even that into a kick:
        /// OilAndWater at a 0.039 ms step (which MaxTimeStep allows) was left 0.26 % compressed at most, took 0.85 J of
        /// kinetic energy within its first 1.25 ms, and boiled, both liquids 4 % expanded. So the settling goes on while
        /// the most compressed particle, removed within the first step, would be kicked by more than gravity adds in that
        /// step: compression e over a step dt moves a particle about e times the spacing s in it, so it stops once
        /// e s / dt is within g dt, dt the stable step at rest (MaxTimeStep, unless the gravity wave, the viscosity or
        /// the tension bounds it shorter), or e / dt within the divergence-free setting's rate (the only bound without
        /// gravity, which otherwise ran all the solves). That rate is what the solve itself stops at on sub-steps of
        /// <see cref="DivergenceSolveTolerance.ReferenceStep"/> and longer; on shorter ones the solve stops at a higher rate
        /// (the same density change a sub-step), so there this bound is the stricter of the two, and the 0.039 ms spawn
        /// below was measured with it. At OilAndWater's 5 ms that allows
        /// 1.6 %, which two solves meet, so the shipped scenes start as before; at 0.039 ms twenty leave 0.001 %, and the
        /// first 1.25 ms holds 0.03 mJ.
        /// Once, at construction (blocking read-backs of the particles and of the diagnostics): <see cref="Reset"/>
        /// respawns the result.
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
            float step = _timeStep.StableTimeStep();
            // Gravity's bound, or the divergence-free setting's rate over the step, whichever is larger: without gravity the
            // first is zero, and any compression left ran all the solves; a kick within the second moves a particle no
            // faster than the solve lets the fluid move anyway (on sub-steps under DivergenceSolveTolerance.ReferenceStep
            // the solve allows more, so this stays the stricter there).
            float allowed = Math.Max(_scene.Settings.Gravity.Length() * step * step / _scene.Settings.ParticleSpacing,
                0.01f * _scene.Settings.DivergenceTolerance * step);
            for (int s = 0; s < MaxSpawnSettlingSolves; s++)
            {
                for (int i = 0; i < held.Length; i++) held[i].Velocity = Vector3.Zero;
                _buffers.Particles.SetData(held);
                _buffers.ClearForRespawn(); // no warm start: each solve starts from the particles at rest
                SortAndComputeForces(false); // density and factor where the particles stand
                if (s >= SpawnSettlingSolves)
                {
                    if (MostCompressed(ReadDiagnostics()) <= allowed) break;
                    _constants[0].DensitySolveTolerance = FineSpawnSettlingTolerance * sceneTolerance;
                    _constantsChanged = true;
                }
                Solve(DensitySolveSlot, _kernels.BeginDensitySolve, _kernels.DensitySolveError);
                LanedPass(PassNames.Drift, _kernels.Drift, ParticleCount);
                _buffers.Particles.GetData(held);
            }
            _constants[0].DensitySolveTolerance = sceneTolerance;
            _constantsChanged = true;
            var settled = new Particle[spawn.Length];
            foreach (var p in held)
                settled[p.Id] = new Particle(p.Position, spawn[p.Id].Velocity, p.Phase, p.Id);
            return settled;
        }

        static float MostCompressed(DiagnosticsReport report)
        {
            float most = 0f;
            foreach (var phase in report.Phases) most = Math.Max(most, phase.MaxDensityError);
            return most;
        }
    }
}
