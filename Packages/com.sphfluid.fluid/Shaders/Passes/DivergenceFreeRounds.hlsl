#ifndef SPHFLUID_PASSES_DIVERGENCE_FREE_ROUNDS_INCLUDED
#define SPHFLUID_PASSES_DIVERGENCE_FREE_ROUNDS_INCLUDED

// One round of a divergence-free solve (DivergenceFreeSolver.hlsl): the velocity prediction that warm-starts the
// constant-density solve, each particle's (fluid and wall) step from its predicted compression or compression rate,
// and the correction that applies them.

[numthreads(PARTICLE_THREADS, 1, 1)]
void PredictVelocity(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _ParticleCount)
        return;
    Particle p = _Particles[i];
    if (ViscosityIsImplicit())
        _ViscosityStart[i] = float4(p.velocity, 0.0); // v_n, and no stage opened yet (ViscosityStage)
    p.velocity = PredictedVelocity(p.velocity, _Accelerations[i].xyz, _VelocityCorrections[i].xyz);
    _Particles[i] = p;
    _SolverParticles[i] = float4(p.position, DENSITY_WARM_START * _WarmStart[p.id].x);
    _WarmStart[p.id] = float2(0.0, _WarmStart[p.id].y); // ApplyStiffness counts the warm start as it applies it
}

// The walls' warm start of the constant-density solve, before its first correction (the fluid's is set by
// PredictVelocity; the divergence-free solve's, fluid and walls, by DensityFactor and BoundaryDensityFactor).
void BeginWallDensitySolve(uint b)
{
    float4 solve = _BoundarySolve[b];
    uint boundaryId = _BoundarySortedSource[b];
    float2 warm = _BoundaryWarmStart[boundaryId];
    solve.z = DENSITY_WARM_START * warm.x;
    _BoundarySolve[b] = solve;
    _BoundaryWarmStart[boundaryId] = float2(0.0, warm.y);
}

// Opens the constant-density solve, one thread a wall particle: the first thread the solve's state (BeginSolve),
// every thread its wall particle's warm start. One dispatch, not two: the state and the walls touch no common word.
[numthreads(PARTICLE_THREADS, 1, 1)]
void BeginDensitySolve(uint3 id : SV_DispatchThreadID)
{
    if (id.x == 0u)
        BeginSolve(DENSITY_SOLVE);
    if (id.x < _BoundaryCount)
        BeginWallDensitySolve(id.x);
}

// The q a fluid particle has applied so far in the open solve, warm start included; read only by the accelerated solve
// (the Jacobi solve's error pass need not load it).
float AppliedStiffness(uint particleId, uint solve)
{
    if (!Accelerated(solve))
        return 0.0;
    float2 summed = _WarmStart[particleId];
    return solve == DENSITY_SOLVE ? summed.x : summed.y;
}

// The q a particle applies in this round of the open solve: the Jacobi solve's compression-only step, or, where that
// solve is accelerated, the projected Chebyshev step (DivergenceFreeSolver.hlsl) from the q it applied so far in this
// solve, its last step and the signed Jacobi step.
float RoundStep(float compressionStep, float applied, float previousStep, float signedStep)
{
    if (!Accelerated(OpenSolve()))
        return compressionStep;
    float3 weights = ChebyshevWeights(asfloat(_SolverState[CHEBYSHEV_WORD]), _ChebyshevLow, _ChebyshevHigh);
    return ProjectedChebyshevStep(applied, previousStep, signedStep, weights);
}

// One Jacobi step of a wall particle: q_b from its predicted compression (density solve) or its compression rate
// (divergence solve), D delta_b / Dt = sum_f (v_f - v_b) . gradW_fb; in the density solve raised to the fluid's q around
// it (WallStepAtLeast: the q each fluid neighbour has applied in this solve with this round's step, Shepard-weighted).
// The q_b the last correction applied is summed into the warm start first. Runs after the fluid's error pass, whose steps
// it reads. Laned; a wall particle without a factor (no fluid) walks nothing and gets q_b = 0. Its last group to finish
// then folds the round's errors and decides whether the solve goes on (FoldSolveErrors): the fold needs the fluid's
// error pass done and comes before the correction, as this pass does, so the round takes three dispatches, not four.
// The pass always has a group to fold in: every container has at least one layer of wall particles (BoundarySampling).
[numthreads(PARTICLE_THREADS, 1, 1)]
void BoundarySolveError(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint b = min(LaneOwner(id.x), _BoundaryCount - 1u);
    float4 solve = _BoundarySolve[b];
    bool pushes = solve.y > 0.0;
    uint lane = FirstCandidate(id.x, pushes ? _BoundaryCount : 0u);
    BoundaryParticle wall = _BoundaryParticles[b];
    int3 home = GridCoordOf(wall.position);
    NeighbourList list = ListOf(_ParticleCount + b);
    uint open = OpenSolve();
    float rate = 0.0, weightedStiffness = 0.0, weights = 0.0;
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 range = FluidNeighbours(list, home, row);
        for (uint k = range.x + lane; k < range.y; k += _NeighbourLanes)
        {
            uint f = Neighbour(list, k);
            Particle pf = _Particles[f];
            float3 rfb = pf.position - wall.position;
            float r2 = dot(rfb, rfb);
            if (r2 >= _SmoothingRadius2)
                continue;
            rate += ContinuityPair(pf.velocity, wall.velocity, PairGradient(rfb, sqrt(r2), 1u, 0u));
            if (open != DENSITY_SOLVE)
                continue;
            float w = Kernel(r2);
            weightedStiffness += w * (_WarmStart[pf.id].x + _SolverParticles[f].w);
            weights += w;
        }
    }
    float3 sums = SumOverLanes(float4(rate, weightedStiffness, weights, 0.0), groupThread.x).xyz;
    rate = sums.x;
    if (LaneOwner(id.x) < _BoundaryCount && LaneOf(id.x) == 0u)
    {
        uint boundaryId = _BoundarySortedSource[b];
        float2 summed = _BoundaryWarmStart[boundaryId] + (open == DENSITY_SOLVE ? float2(solve.z, 0.0) : float2(0.0, solve.z));
        _BoundaryWarmStart[boundaryId] = summed;
        float2 stiffness = open == DENSITY_SOLVE
            ? DensityStiffness(solve.x, rate, solve.w, solve.y, _TimeStep)
            : DivergenceStiffness(rate, solve.w, solve.y, _TimeStep);
        float signedStiffness = open == DENSITY_SOLVE
            ? SignedDensityStiffness(solve.x, rate, solve.w, solve.y, _TimeStep)
            : SignedDivergenceStiffness(rate, solve.y, _TimeStep);
        float wallRelaxation = CHEBYSHEV_WALL_SHARE * _SolverRelaxation;
        float applied = open == DENSITY_SOLVE ? summed.x : summed.y;
        float step = RoundStep(WALL_RELAXATION * stiffness.x, applied, solve.z, wallRelaxation * signedStiffness);
        if (open == DENSITY_SOLVE)
            step = WallStepAtLeast(step, applied, sums.z > 0.0 ? sums.y / sums.z : 0.0);
        solve.z = pushes ? step : 0.0;
        _BoundarySolve[b] = solve;
    }
    if (LastGroupToFinish(groupThread.x, LanedGroups(_BoundaryCount)))
        FoldSolveErrors(groupThread.x);
}

// D delta_i / Dt and the neighbours that gave it, for the fluid particle of thread `thread`, summed over its lanes
// (every thread of the group calls it); the lane that writes gets `writes`.
float2 LanedNumberDensityRate(uint thread, uint groupThread, out bool writes)
{
    uint i = min(LaneOwner(thread), _ParticleCount - 1u);
    uint lane = FirstCandidate(thread, _ParticleCount);
    uint neighbours;
    float rate = NumberDensityRate(i, lane, _NeighbourLanes, neighbours);
    writes = lane == 0u;
    return SumOverLanes(float4(rate, (float)neighbours, 0.0, 0.0), groupThread).xy;
}

// Laned, as the correction (ApplyStiffness); only the lane that writes adds its particle's error to the group's.
[numthreads(PARTICLE_THREADS, 1, 1)]
void DensitySolveError(uint3 id : SV_DispatchThreadID, uint3 groupId : SV_GroupID, uint3 threadId : SV_GroupThreadID)
{
    bool writes;
    float rate = LanedNumberDensityRate(id.x, threadId.x, writes).x;
    float error = 0.0;
    uint phase = 0u;
    if (writes)
    {
        uint i = LaneOwner(id.x);
        Particle p = _Particles[i];
        phase = PHASE_OF(p);
        float rest = RestNumberDensityOf(p);
        float factor = _DivergenceFreeFactors[i];
        float2 stiffness = DensityStiffness(_Densities[i].z, rate, rest, factor, _TimeStep);
        _SolverParticles[i] = float4(p.position, RoundStep(_SolverRelaxation * stiffness.x, AppliedStiffness(p.id, DENSITY_SOLVE),
            _SolverParticles[i].w, _SolverRelaxation * SignedDensityStiffness(_Densities[i].z, rate, rest, factor, _TimeStep)));
        error = stiffness.y;
    }
    StoreGroupErrors(threadId.x, groupId.x, error, phase);
}

[numthreads(PARTICLE_THREADS, 1, 1)]
void DivergenceSolveError(uint3 id : SV_DispatchThreadID, uint3 groupId : SV_GroupID, uint3 threadId : SV_GroupThreadID)
{
    bool writes;
    float2 rateAndNeighbours = LanedNumberDensityRate(id.x, threadId.x, writes);
    float error = 0.0;
    uint phase = 0u;
    if (writes)
    {
        uint i = LaneOwner(id.x);
        float rate = rateAndNeighbours.y >= (float)DIVERGENCE_MIN_NEIGHBOURS ? rateAndNeighbours.x : 0.0;
        Particle p = _Particles[i];
        phase = PHASE_OF(p);
        float factor = _DivergenceFreeFactors[i];
        float2 stiffness = DivergenceStiffness(rate, RestNumberDensityOf(p), factor, _TimeStep);
        _SolverParticles[i] = float4(p.position, RoundStep(_SolverRelaxation * stiffness.x, AppliedStiffness(p.id, DIVERGENCE_SOLVE),
            _SolverParticles[i].w, _SolverRelaxation * SignedDivergenceStiffness(rate, factor, _TimeStep)));
        error = stiffness.y;
    }
    StoreGroupErrors(threadId.x, groupId.x, error, phase);
}

// Laned (NeighbourLanes.hlsl). A fluid neighbour is one 16-byte read of _SolverParticles (its position and q, which the
// passes that set q write together), not its 32-byte Particle, whose velocity the correction does not need, and q's
// word beside it: this pass is the largest share of a DFSPH sub-step (40 % at 1M particles on the H200), and its reads
// of the neighbours are most of its memory traffic. The results are the same to the bit.
[numthreads(PARTICLE_THREADS, 1, 1)]
void ApplyStiffness(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint i = min(LaneOwner(id.x), _ParticleCount - 1u);
    uint lane = FirstCandidate(id.x, _ParticleCount);
    Particle pi = _Particles[i];
    PhaseProperties phase = _Phases[PHASE_OF(pi)];
    float dtOverMass = _TimeStep / phase.particleMass;
    float qi = _SolverParticles[i].w;
    int3 home = GridCoordOf(pi.position);
    NeighbourList list = ListOf(i);
    float3 dv = float3(0.0, 0.0, 0.0);
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 range = FluidNeighbours(list, home, row);
        for (uint k = range.x + lane; k < range.y; k += _NeighbourLanes)
        {
            uint j = Neighbour(list, k);
            float4 sj = _SolverParticles[j];
            float3 rij = pi.position - sj.xyz;
            float r2 = dot(rij, rij);
            if (r2 >= _SmoothingRadius2 || j == i)
                continue;
            uint idJ = 0u; // PairGradient reads the ids of coincident particles only
            if (r2 == 0.0)
                idJ = _Particles[j].id;
            dv += StiffnessVelocityPair(qi, sj.w, PairGradient(rij, sqrt(r2), pi.id, idJ), dtOverMass);
        }
        uint2 walls = WallNeighbours(list, home, row);
        for (uint kb = walls.x + lane; kb < walls.y; kb += _NeighbourLanes)
        {
            uint b = Neighbour(list, kb);
            BoundaryParticle wall = _BoundaryParticles[b];
            float3 rib = pi.position - wall.position;
            float r2 = dot(rib, rib);
            if (r2 >= _SmoothingRadius2)
                continue;
            dv += StiffnessVelocityWall(qi, _BoundarySolve[b].z, WallWeight(wall, phase), PairGradient(rib, sqrt(r2), 1u, 0u), dtOverMass);
        }
    }
    dv = SumOverLanes(float4(dv, 0.0), groupThread.x).xyz;
    if (lane != 0u)
        return;
    _Particles[i].velocity = pi.velocity + dv;
    // Only q that was applied becomes the next sub-step's warm start: the error pass of the round that converged
    // computes a q that no ApplyStiffness uses, and counting it would push the next sub-step with a pressure the
    // fluid never felt.
    _WarmStart[pi.id] += OpenSolve() == DENSITY_SOLVE ? float2(qi, 0.0) : float2(0.0, qi);
}

#endif
