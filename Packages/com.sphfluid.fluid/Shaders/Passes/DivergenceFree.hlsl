#ifndef SPHFLUID_PASSES_DIVERGENCE_FREE_INCLUDED
#define SPHFLUID_PASSES_DIVERGENCE_FREE_INCLUDED

// FluidSolver.compute's divergence-free SPH passes (DivergenceFreeSolver.hlsl): the factors, the two Jacobi solves
// with their stop decision kept on the GPU, the drift, and the per-particle divergence the diagnostics read.

// rest number density delta0 = rho0 / m of particle p's phase.
float RestNumberDensityOf(Particle p)
{
    PhaseProperties phase = _Phases[PHASE_OF(p)];
    return phase.restDensity / phase.particleMass;
}

// delta, rho and the factor alpha of the fluid particle of thread `thread`, from its neighbours, fluid and wall.
// Laned (NeighbourLanes.hlsl): every thread of the group calls it; true for the one thread that wrote.
bool StoreDensityFactor(uint thread, uint groupThread)
{
    uint i = min(LaneOwner(thread), _ParticleCount - 1u);
    uint lane = FirstCandidate(thread, _ParticleCount);
    Particle pi = _Particles[i];
    PhaseProperties phase = _Phases[PHASE_OF(pi)];
    int3 home = GridCoordOf(pi.position);
    NeighbourList list = ListOf(i);
    float numberDensity = 0.0;
    float3 gradientSum = float3(0.0, 0.0, 0.0);
    float squaredGradients = 0.0;
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 range = FluidNeighbours(list, home, row);
        for (uint k = range.x + lane; k < range.y; k += _NeighbourLanes)
        {
            uint j = Neighbour(list, k);
            Particle pj = _Particles[j];
            float3 rij = pi.position - pj.position;
            float r2 = dot(rij, rij);
            numberDensity += Kernel(r2);
            if (r2 >= _SmoothingRadius2 || j == i)
                continue;
            float3 gradient = PairGradient(rij, sqrt(r2), pi.id, pj.id);
            gradientSum += gradient;
            squaredGradients += dot(gradient, gradient) / _Phases[PHASE_OF(pj)].particleMass;
        }
        uint2 walls = WallNeighbours(list, home, row);
        for (uint kb = walls.x + lane; kb < walls.y; kb += _NeighbourLanes)
        {
            BoundaryParticle wall = _BoundaryParticles[Neighbour(list, kb)];
            float3 rib = pi.position - wall.position;
            float r2 = dot(rib, rib);
            float weight = WallWeight(wall, phase);
            numberDensity += weight * Kernel(r2);
            if (r2 >= _SmoothingRadius2)
                continue;
            gradientSum += weight * PairGradient(rib, sqrt(r2), 1u, 0u);
        }
    }
    float4 gradientsAndDensity = SumOverLanes(float4(gradientSum, numberDensity), groupThread);
    squaredGradients = SumOverLanes(float4(squaredGradients, 0.0, 0.0, 0.0), groupThread).x;
    if (lane != 0u)
        return false;
    gradientSum = gradientsAndDensity.xyz;
    numberDensity = gradientsAndDensity.w;
    _DivergenceFreeFactors[i] = DivergenceFreeFactor(gradientSum, squaredGradients, phase.particleMass);
    // The pressure term the last constant-density solve applied, for the readouts (WCSPH's layout).
    float q = _WarmStart[pi.id].x;
    _Densities[i] = float4(phase.particleMass * numberDensity, q * numberDensity * numberDensity, numberDensity, q);
    return true;
}

// After the drift and the sort: delta, rho, alpha, and the divergence solve's warm-start q. Laned.
[numthreads(PARTICLE_THREADS, 1, 1)]
void DensityFactor(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    if (!StoreDensityFactor(id.x, groupThread.x))
        return;
    uint i = LaneOwner(id.x);
    uint particleId = _Particles[i].id;
    _SolverStiffness[i] = DIVERGENCE_WARM_START * _WarmStart[particleId].y;
    _WarmStart[particleId] = float2(_WarmStart[particleId].x, 0.0); // ApplyStiffness counts the warm start as it applies it
}

// After the boundary moved (once per frame, before the first sub-step): the walls count at their new places in delta,
// rho and alpha, which the non-pressure forces and the constant-density solve read. The fluid has not moved, so the
// divergence solve's warm start stays where the last solve left it, for the next DensityFactor. Laned.
[numthreads(PARTICLE_THREADS, 1, 1)]
void WallMovedDensityFactor(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    StoreDensityFactor(id.x, groupThread.x);
}

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
    float warm = DENSITY_WARM_START * _WarmStart[p.id].x;
    _SolverStiffness[i] = warm;
    _WarmStart[p.id] = float2(0.0, _WarmStart[p.id].y); // ApplyStiffness counts the warm start as it applies it
}

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

[numthreads(1, 1, 1)]
void BeginDensitySolve(uint3 id : SV_DispatchThreadID)
{
    BeginSolve(DENSITY_SOLVE);
}

[numthreads(1, 1, 1)]
void BeginDivergenceSolve(uint3 id : SV_DispatchThreadID)
{
    BeginSolve(DIVERGENCE_SOLVE);
}

// Wall particle b as an unknown of the solves (DivergenceFreeSolver.hlsl, "Walls as unknowns"): delta_b, alpha_b, the rest
// number density of the fluid around it, and the divergence-free solve's warm start. Laned.
[numthreads(PARTICLE_THREADS, 1, 1)]
void BoundaryDensityFactor(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint b = min(LaneOwner(id.x), _BoundaryCount - 1u);
    uint lane = FirstCandidate(id.x, _BoundaryCount);
    float3 xb = _BoundaryParticles[b].position;
    int3 home = GridCoordOf(xb);
    NeighbourList list = ListOf(_ParticleCount + b);
    float fluidDensity = 0.0, squaredGradients = 0.0, restSum = 0.0, scaleSum = 0.0;
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 range = FluidNeighbours(list, home, row);
        for (uint k = range.x + lane; k < range.y; k += _NeighbourLanes)
        {
            Particle pf = _Particles[Neighbour(list, k)];
            float3 rfb = pf.position - xb;
            float r2 = dot(rfb, rfb);
            if (r2 >= _SmoothingRadius2)
                continue;
            float w = Kernel(r2);
            fluidDensity += w;
            restSum += w * RestNumberDensityOf(pf);
            scaleSum += w * _Phases[PHASE_OF(pf)].wallWeightScale;
            float3 gradient = PairGradient(rfb, sqrt(r2), 1u, 0u);
            squaredGradients += dot(gradient, gradient) / _Phases[PHASE_OF(pf)].particleMass;
        }
    }
    float4 sums = SumOverLanes(float4(fluidDensity, squaredGradients, restSum, scaleSum), groupThread.x);
    if (lane != 0u)
        return;
    fluidDensity = sums.x;
    squaredGradients = sums.y;
    restSum = sums.z;
    scaleSum = sums.w;
    float wallDensity = _WallNumberDensities[b];
    float rest = fluidDensity > 0.0 ? restSum / fluidDensity : 0.0;
    // The walls around b filled at the rest number density of the fluid that meets b (WallWeight, Shepard-weighted).
    float wallScale = fluidDensity > 0.0 ? scaleSum / fluidDensity : 1.0;
    uint boundaryId = _BoundarySortedSource[b];
    float2 warm = _BoundaryWarmStart[boundaryId];
    _BoundarySolve[b] = float4(fluidDensity + wallScale * wallDensity, WallFactor(fluidDensity, rest, squaredGradients),
        DIVERGENCE_WARM_START * warm.y, rest);
    _BoundaryWarmStart[boundaryId] = float2(warm.x, 0.0);
}

// Before a solve's first correction: the walls' warm start (the fluid's is set by PredictVelocity and DensityFactor).
[numthreads(PARTICLE_THREADS, 1, 1)]
void BoundaryBeginSolve(uint3 id : SV_DispatchThreadID)
{
    uint b = id.x;
    if (b >= _BoundaryCount || OpenSolve() != DENSITY_SOLVE)
        return;
    float4 solve = _BoundarySolve[b];
    uint boundaryId = _BoundarySortedSource[b];
    float2 warm = _BoundaryWarmStart[boundaryId];
    solve.z = DENSITY_WARM_START * warm.x;
    _BoundarySolve[b] = solve;
    _BoundaryWarmStart[boundaryId] = float2(0.0, warm.y);
}

// Whether `solve` takes accelerated steps: the divergence-free solve whenever Chebyshev bounds are set, the
// constant-density solve only at tolerances tight enough to pay for them (ChebyshevBounds.AcceleratesDensitySolve).
bool Accelerated(uint solve)
{
    return _ChebyshevHigh > 0.0 && (solve != DENSITY_SOLVE || _AcceleratedDensitySolve != 0u);
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
// it reads. Laned; a wall particle without a factor (no fluid) walks nothing and gets q_b = 0.
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
            weightedStiffness += w * (_WarmStart[pf.id].x + _SolverStiffness[f]);
            weights += w;
        }
    }
    float3 sums = SumOverLanes(float4(rate, weightedStiffness, weights, 0.0), groupThread.x).xyz;
    rate = sums.x;
    if (LaneOwner(id.x) >= _BoundaryCount || LaneOf(id.x) != 0u)
        return;
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
// for SolveFinal's per-phase averages; every thread of the group must call it. Two barriers for up to
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
        _SolverStiffness[i] = RoundStep(_SolverRelaxation * stiffness.x, AppliedStiffness(p.id, DENSITY_SOLVE), _SolverStiffness[i],
            _SolverRelaxation * SignedDensityStiffness(_Densities[i].z, rate, rest, factor, _TimeStep));
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
        _SolverStiffness[i] = RoundStep(_SolverRelaxation * stiffness.x, AppliedStiffness(p.id, DIVERGENCE_SOLVE), _SolverStiffness[i],
            _SolverRelaxation * SignedDivergenceStiffness(rate, factor, _TimeStep));
        error = stiffness.y;
    }
    StoreGroupErrors(threadId.x, groupId.x, error, phase);
}

// Folds the error pass's group sums into each phase's average error. Once a solve has made two corrections and every
// phase's average is within the open solve's tolerance it is converged, and the indirect arguments become zero groups.
// Per phase, not over all particles: the tolerance is each liquid's, and a thin phase under a deep one, the most
// compressed, sat 63 % above it while the solve stopped on the average over all particles (PhaseToleranceTests).
[numthreads(PARTICLE_THREADS, 1, 1)]
void SolveFinal(uint3 threadId : SV_GroupThreadID)
{
    uint t = threadId.x;
    uint solve = OpenSolve();
    uint slot = solve * 8u;
    if (_SolverState[slot + 1u] != 0u)
        return; // converged earlier: the error pass did not run, its sums are stale
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

// Laned (NeighbourLanes.hlsl).
[numthreads(PARTICLE_THREADS, 1, 1)]
void ApplyStiffness(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint i = min(LaneOwner(id.x), _ParticleCount - 1u);
    uint lane = FirstCandidate(id.x, _ParticleCount);
    Particle pi = _Particles[i];
    PhaseProperties phase = _Phases[PHASE_OF(pi)];
    float dtOverMass = _TimeStep / phase.particleMass;
    float qi = _SolverStiffness[i];
    int3 home = GridCoordOf(pi.position);
    NeighbourList list = ListOf(i);
    float3 dv = float3(0.0, 0.0, 0.0);
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 range = FluidNeighbours(list, home, row);
        for (uint k = range.x + lane; k < range.y; k += _NeighbourLanes)
        {
            uint j = Neighbour(list, k);
            Particle pj = _Particles[j];
            float3 rij = pi.position - pj.position;
            float r2 = dot(rij, rij);
            if (r2 >= _SmoothingRadius2 || j == i)
                continue;
            dv += StiffnessVelocityPair(qi, _SolverStiffness[j], PairGradient(rij, sqrt(r2), pi.id, pj.id), dtOverMass);
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

// DivergenceFreeSolver.hlsl's wall contact for particle i: under-dense at the sub-step's start, or bound to end its drift
// within DIVERGENCE_CONTACT_GAP spacings of a wall's face.
float3 ContactLimitedVelocity(uint i, Particle p)
{
    if (_Densities[i].z >= RestNumberDensityOf(p)
        && WallGap(DriftedPosition(p.position, p.velocity)) >= DIVERGENCE_CONTACT_GAP * _ParticleSpacing)
        return p.velocity;
    PhaseProperties phase = _Phases[PHASE_OF(p)];
    int3 home = GridCoordOf(p.position);
    NeighbourList list = ListOf(i);
    float3 wallGradients = float3(0.0, 0.0, 0.0);
    float wallRate = 0.0;
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 walls = WallNeighbours(list, home, row);
        for (uint kb = walls.x; kb < walls.y; kb++)
        {
            BoundaryParticle wall = _BoundaryParticles[Neighbour(list, kb)];
            float3 rib = p.position - wall.position;
            float r2 = dot(rib, rib);
            if (r2 >= _SmoothingRadius2)
                continue;
            float3 gradient = WallWeight(wall, phase) * PairGradient(rib, sqrt(r2), 1u, 0u);
            wallGradients += gradient;
            wallRate += dot(wall.velocity, gradient);
        }
    }
    return WallContactVelocity(p.velocity, wallGradients, wallRate);
}

[numthreads(PARTICLE_THREADS, 1, 1)]
void Drift(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _ParticleCount)
        return;
    Particle p = _Particles[i];
    p.velocity = ContactLimitedVelocity(i, p);
    p.position = DriftedPosition(p.position, p.velocity);
    LastResortClamp(p);
    _Particles[i] = p;
}

[numthreads(PARTICLE_THREADS, 1, 1)]
void DivergenceRate(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _ParticleCount)
        return;
    uint neighbours;
    _DivergenceRates[i] = abs(NumberDensityRate(i, 0u, 1u, neighbours)) / RestNumberDensityOf(_Particles[i]);
}

#endif
