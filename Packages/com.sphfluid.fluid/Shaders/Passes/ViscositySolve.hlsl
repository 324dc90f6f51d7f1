#ifndef SPHFLUID_PASSES_VISCOSITY_SOLVE_INCLUDED
#define SPHFLUID_PASSES_VISCOSITY_SOLVE_INCLUDED

// FluidSolver.compute's implicit viscosity solve (SphViscositySolve.hlsl), between DFSPH's constant-density solve and its
// drift, or after each of WCSPH's half kicks: for each stage the host records ViscosityStage, which sets the stage's
// target, and its rounds of ViscosityStep > ViscosityApply on the particles' velocities. PredictVelocity (DFSPH) or
// HalfKick and FullStep (WCSPH) keep each particle's v_n in _ViscosityStart.

// What lane `lane` of particle i's neighbourhood adds to the viscous force at the present velocities (xyz) and to the
// couplings' sum (w), fluid and walls, as ForceSumsOf sums them.
float4 ViscousSumsOf(uint i, uint lane)
{
    Particle pi = _Particles[i];
    PhaseProperties phaseI = _Phases[PHASE_OF(pi)];
    float4 di = _Densities[i];
    float3 force = float3(0.0, 0.0, 0.0);
    float couplings = 0.0;
    int3 home = GridCoordOf(pi.position);
    NeighbourList list = ListOf(i);
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
            float c = ViscosityCoupling(PairViscosity(phaseI.viscosity, PHASE_OF(pj)), rij, r2, PairGradient(rij, sqrt(r2), pi.id, pj.id), 1.0 / (di.z * _Densities[j].z));
            force += c * (pj.velocity - pi.velocity);
            couplings += c;
        }
        uint2 walls = WallNeighbours(list, home, row);
        for (uint kb = walls.x + lane; kb < walls.y; kb += _NeighbourLanes)
        {
            BoundaryParticle wall = _BoundaryParticles[Neighbour(list, kb)];
            float3 rib = pi.position - wall.position;
            float r2 = dot(rib, rib);
            if (r2 >= _SmoothingRadius2)
                continue;
            float c = ViscosityCoupling(_WallFriction * phaseI.viscosity, rib, r2, PairGradient(rib, sqrt(r2), 1u, 0u),
                WallWeight(wall, phaseI) / (di.z * di.z));
            force += c * (wall.velocity - pi.velocity);
            couplings += c;
        }
    }
    return float4(force, couplings);
}

// One round's step d_k = beta_k d_{k-1} + gamma_k z_k into _ViscositySteps (laned, as NonPressureForces). The
// velocities stay as they are until ViscosityApply, since the neighbours' sums read them.
[numthreads(PARTICLE_THREADS, 1, 1)]
void ViscosityStep(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint i = min(LaneOwner(id.x), _ParticleCount - 1u);
    uint lane = FirstCandidate(id.x, _ParticleCount);
    float4 sums = SumOverLanes(ViscousSumsOf(i, lane), groupThread.x);
    if (lane != 0u)
        return;
    Particle pi = _Particles[i];
    float previousRho = asfloat(_SolverState[VISCOSITY_WORD]);
    float3 jacobi = ViscousJacobiStep(_ViscosityTargets[i].xyz, pi.velocity, sums.xyz, sums.w, _Phases[PHASE_OF(pi)].particleMass);
    float3 weights = ChebyshevWeights(previousRho, _ViscositySolveLow, _ViscositySolveHigh);
    _ViscositySteps[i] = float4(weights.x * _ViscositySteps[i].xyz + weights.y * jacobi, 0.0);
}

// x += d_k; the round's rho for the next round's weights (no thread of this pass reads it).
[numthreads(PARTICLE_THREADS, 1, 1)]
void ViscosityApply(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i == 0u)
        _SolverState[VISCOSITY_WORD] = asuint(ChebyshevWeights(asfloat(_SolverState[VISCOSITY_WORD]), _ViscositySolveLow, _ViscositySolveHigh).z);
    if (i >= _ParticleCount)
        return;
    Particle p = _Particles[i];
    p.velocity += _ViscositySteps[i].xyz;
    _Particles[i] = p;
}

// A stage's start: its target (FirstStageTarget from v_n and v*, the velocities the constant-density solve left; then
// SecondStageTarget from stage one's target and solution) into _ViscosityTargets and, as its first iterate, into the
// velocities; _ViscosityStart.w counts the stages opened. The Chebyshev rounds start again.
[numthreads(PARTICLE_THREADS, 1, 1)]
void ViscosityStage(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i == 0u)
        _SolverState[VISCOSITY_WORD] = 0u; // no rho before the stage's first round
    if (i >= _ParticleCount)
        return;
    Particle p = _Particles[i];
    float4 start = _ViscosityStart[i];
    float3 target;
    if (start.w == 0.0)
    {
        target = FirstStageTarget(start.xyz, p.velocity);
        _ViscosityStart[i] = float4(start.xyz, 1.0);
    }
    else
    {
        target = SecondStageTarget(start.xyz, _ViscosityTargets[i].xyz, p.velocity);
    }
    _ViscosityTargets[i] = float4(target, 0.0);
    p.velocity = target;
    _Particles[i] = p;
}

#endif
