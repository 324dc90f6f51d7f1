#ifndef SPHFLUID_PASSES_DIVERGENCE_FREE_CONVERGENCE_INCLUDED
#define SPHFLUID_PASSES_DIVERGENCE_FREE_CONVERGENCE_INCLUDED

// How a divergence-free solve opens and stops, all on the GPU so that no frame waits on a read-back: the slot of the
// solve under way, the error pass's per-phase sums, and the indirect arguments that become zero groups once every
// phase is within tolerance (DivergenceFreeSolver.hlsl).

// Thread groups of a laned pass over `owners` particles (NeighbourLanes.hlsl).
uint LanedGroups(uint owners)
{
    return (owners * _NeighbourLanes + PARTICLE_THREADS - 1u) / PARTICLE_THREADS;
}

// The slot of the solve under way: kept on the GPU (BeginSolve), so a sub-step's two solves change no constant.
uint OpenSolve()
{
    return _SolverState[OPEN_SOLVE_WORD];
}

// Opens a solve: no iteration yet, not converged, the groups of every laned particle (fluid, then wall) in the
// indirect arguments.
void BeginSolve(uint solve)
{
    _SolverState[OPEN_SOLVE_WORD] = solve;
    uint slot = solve * 8u;
    _SolverState[slot] = 0u;
    _SolverState[slot + 1u] = 0u;
    _SolverState[slot + 3u] += 1u;
    _SolverState[CHEBYSHEV_WORD] = 0u;
    _SolverArguments[0] = LanedGroups(_ParticleCount);
    _SolverArguments[1] = 1u;
    _SolverArguments[2] = 1u;
    _SolverArguments[3] = LanedGroups(_BoundaryCount);
    _SolverArguments[4] = 1u;
    _SolverArguments[5] = 1u;
}

// The divergence-free solve's walls took their warm start in BoundaryDensityFactor, so one thread opens it
// (BeginDensitySolve, which also starts the walls, is in DivergenceFreeRounds.hlsl).
[numthreads(1, 1, 1)]
void BeginDivergenceSolve(uint3 id : SV_DispatchThreadID)
{
    BeginSolve(DIVERGENCE_SOLVE);
}

// Whether `solve` takes accelerated steps: the divergence-free solve whenever Chebyshev bounds are set, the
// constant-density solve only at tolerances tight enough to pay for them (ChebyshevBounds.AcceleratesDensitySolve).
bool Accelerated(uint solve)
{
    return _ChebyshevHigh > 0.0 && (solve != DENSITY_SOLVE || _AcceleratedDensitySolve != 0u);
}

// Tree sum of s_SolveErrors into s_SolveErrors[0]; every thread of the group must call it.
void SumGroupErrors(uint t)
{
    GroupMemoryBarrierWithGroupSync();
    for (uint stride = PARTICLE_THREADS / 2u; stride > 0u; stride >>= 1u)
    {
        if (t < stride)
            s_SolveErrors[t] += s_SolveErrors[t + stride];
        GroupMemoryBarrierWithGroupSync();
    }
}

// Sums the group's errors per phase into _SolverPartials[phase * groups + group], over the laned error pass's groups,
// for the fold's per-phase averages (FoldSolveErrors); every thread of the group must call it. Two barriers for up to
// PHASES_PER_FOLD phases: a thread sums one run of ERROR_RUN slots for one phase, then a thread a phase sums its runs.
// A tree per phase took nine barriers a phase, and barriers are what a CPU device pays for (NeighbourLanes.hlsl): on
// lavapipe with one worker (OilAndWater under DFSPH, `bench --solver dfsph`) DensitySolveError cost 1.22 times an
// ApplyStiffness with the trees, 1.12 with this fold and 1.11 with no fold at all.
void StoreGroupErrors(uint t, uint group, float error, uint phase)
{
    uint groups = LanedGroups(_ParticleCount);
    s_SolveErrors[t] = error;
    s_ErrorPhases[t] = phase;
    for (uint first = 0u; first < _PhaseCount; first += PHASES_PER_FOLD)
    {
        GroupMemoryBarrierWithGroupSync(); // the slots are written, and the last fold's run sums read
        uint k = first + t / ERROR_RUNS;
        uint start = (t % ERROR_RUNS) * ERROR_RUN;
        float sum = 0.0;
        if (k < _PhaseCount)
        {
            for (uint e = start; e < start + ERROR_RUN; e++)
                sum += s_ErrorPhases[e] == k ? s_SolveErrors[e] : 0.0;
        }
        s_RunSums[t] = sum;
        GroupMemoryBarrierWithGroupSync();
        if (t < PHASES_PER_FOLD && first + t < _PhaseCount)
        {
            float phaseSum = 0.0;
            for (uint r = 0u; r < ERROR_RUNS; r++)
                phaseSum += s_RunSums[t * ERROR_RUNS + r];
            _SolverPartials[(first + t) * groups + group] = phaseSum;
        }
    }
}

// Folds the error pass's group sums into each phase's average error. Once a solve has made two corrections and every
// phase's average is within the open solve's tolerance it is converged, and the indirect arguments become zero groups.
// Per phase, not over all particles: the tolerance is each liquid's, and a thin phase under a deep one, the most
// compressed, sat 63 % above it while the solve stopped on the average over all particles (PhaseToleranceTests).
// Every thread of one group calls it: the last group of BoundarySolveError to finish (LastGroupToFinish), which runs
// after the fluid's error pass, so the partials it reads were written by an earlier dispatch.
void FoldSolveErrors(uint t)
{
    uint solve = OpenSolve();
    uint slot = solve * 8u;
    if (_SolverState[slot + 1u] != 0u)
        return; // converged earlier (uniform over the group): the error pass did not run, its sums are stale
    uint groups = LanedGroups(_ParticleCount);
    float worst = 0.0;
    for (uint k = 0u; k < _PhaseCount; k++)
    {
        float sum = 0.0;
        for (uint g = t; g < groups; g += PARTICLE_THREADS)
            sum += _SolverPartials[k * groups + g];
        GroupMemoryBarrierWithGroupSync(); // s_SolveErrors[0] was read in the last phase's fold
        s_SolveErrors[t] = sum;
        SumGroupErrors(t);
        worst = max(worst, s_SolveErrors[0] * _Phases[k].inverseParticleCount);
    }
    if (t != 0u)
        return;
    uint corrections = _SolverState[slot];
    _SolverState[slot + 4u] = asuint(worst);
    float tolerance = solve == DENSITY_SOLVE ? _DensitySolveTolerance : _DivergenceSolveTolerance;
    if (corrections >= 2u && worst <= tolerance)
    {
        _SolverState[slot + 1u] = 1u;
        _SolverArguments[0] = 0u;
        _SolverArguments[3] = 0u;
        _SolverState[slot + 5u] = max(_SolverState[slot + 5u], corrections);
        return;
    }
    // The ApplyStiffness after this pass makes one more correction. In the last recorded round it is the solve's
    // last: the solve ends unconverged, and the host learns it through the motion read-back and records more rounds.
    _SolverState[slot] = corrections + 1u;
    _SolverState[slot + 2u] += 1u;
    if (Accelerated(solve))
        _SolverState[CHEBYSHEV_WORD] = asuint(ChebyshevWeights(asfloat(_SolverState[CHEBYSHEV_WORD]), _ChebyshevLow, _ChebyshevHigh).z);
    if (corrections + 1u >= (solve == DENSITY_SOLVE ? _DensitySolveRounds : _DivergenceSolveRounds))
    {
        _SolverState[slot + 5u] = max(_SolverState[slot + 5u], corrections + 1u);
        _SolverState[slot + 6u] += 1u;
        _SolverState[slot + 7u] += 1u; // its own count: the motion reduction resets word 6 for the budget, not at reports
    }
}

groupshared uint s_LastGroup;

// Whether this group is the last of the `groups` of its dispatch to get here, the one that may then fold what the
// dispatch's other groups have done with (every thread of the group calls it). The device barrier before the count
// releases each group's reads and writes, and the one after it has the last group acquire them, so the last group's
// writes to words the others read (the Chebyshev weight) come after every read. The last group sets the count back to
// zero for the next dispatch; it is alone by then. (A single-pass reduction's "last block": one dispatch fewer, and one
// barrier between dispatches fewer, every round.)
bool LastGroupToFinish(uint t, uint groups)
{
    DeviceMemoryBarrierWithGroupSync();
    if (t == 0u)
    {
        uint finished;
        InterlockedAdd(_SolverState[FOLD_COUNT_WORD], 1u, finished);
        s_LastGroup = finished + 1u == groups ? 1u : 0u;
        if (s_LastGroup != 0u)
            _SolverState[FOLD_COUNT_WORD] = 0u;
    }
    AllMemoryBarrierWithGroupSync(); // device memory, and the groupshared flag
    return s_LastGroup != 0u;
}

#endif
