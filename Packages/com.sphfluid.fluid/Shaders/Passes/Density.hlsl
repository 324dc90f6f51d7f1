#ifndef SPHFLUID_PASSES_DENSITY_INCLUDED
#define SPHFLUID_PASSES_DENSITY_INCLUDED

// FluidSolver.compute's density passes (SphDensityPressure.hlsl, SphDensityDiffusion.hlsl, SphBoundary.hlsl): WCSPH's
// summed or carried (delta-SPH) number density with its Tait pressure, and the walls' pressure from the fluid around
// them. NumberDensityRate, the continuity equation's D delta / Dt, is shared with the divergence-free solver.

// Laned (NeighbourLanes.hlsl): dispatched over _ParticleCount * _NeighbourLanes threads.
[numthreads(PARTICLE_THREADS, 1, 1)]
void DensityPressure(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint i = min(LaneOwner(id.x), _ParticleCount - 1u);
    uint lane = FirstCandidate(id.x, _ParticleCount);
    float3 xi = _Particles[i].position;
    PhaseProperties phase = _Phases[PHASE_OF(_Particles[i])];
    int3 home = GridCoordOf(xi);
    NeighbourList list = ListOf(i);
    float numberDensity = 0.0;
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 range = FluidNeighbours(list, home, row);
        for (uint k = range.x + lane; k < range.y; k += _NeighbourLanes)
        {
            float3 rij = xi - _Particles[Neighbour(list, k)].position;
            numberDensity += Kernel(dot(rij, rij));
        }
        uint2 walls = WallNeighbours(list, home, row);
        for (uint kb = walls.x + lane; kb < walls.y; kb += _NeighbourLanes)
        {
            BoundaryParticle wall = _BoundaryParticles[Neighbour(list, kb)];
            float3 rib = xi - wall.position;
            numberDensity += WallWeight(wall, phase) * Kernel(dot(rib, rib));
        }
    }
    numberDensity = SumOverLanes(float4(numberDensity, 0.0, 0.0, 0.0), groupThread.x).x;
    if (lane == 0u)
        _Densities[i] = DensityRecord(numberDensity, phase.particleMass, phase.restDensity);
}

// D delta_i / Dt from the current velocities of the fluid and the walls: the continuity equation of
// SphDensityDiffusion.hlsl, read by DFSPH's solves, delta-SPH's ContinuityDensity and the diagnostics. Lane `lane` of
// `lanes` sums every lanes-th neighbour (NeighbourLanes.hlsl); an unlaned caller passes 0 and 1.
float NumberDensityRate(uint i, uint lane, uint lanes, out uint neighbours)
{
    Particle pi = _Particles[i];
    PhaseProperties phase = _Phases[PHASE_OF(pi)];
    int3 home = GridCoordOf(pi.position);
    NeighbourList list = ListOf(i);
    float rate = 0.0;
    neighbours = 0u;
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 range = FluidNeighbours(list, home, row);
        for (uint k = range.x + lane; k < range.y; k += lanes)
        {
            uint j = Neighbour(list, k);
            Particle pj = _Particles[j];
            float3 rij = pi.position - pj.position;
            float r2 = dot(rij, rij);
            if (r2 >= _SmoothingRadius2 || j == i)
                continue;
            rate += ContinuityPair(pi.velocity, pj.velocity, PairGradient(rij, sqrt(r2), pi.id, pj.id));
            neighbours++;
        }
        uint2 walls = WallNeighbours(list, home, row);
        for (uint kb = walls.x + lane; kb < walls.y; kb += lanes)
        {
            BoundaryParticle wall = _BoundaryParticles[Neighbour(list, kb)];
            float3 rib = pi.position - wall.position;
            float r2 = dot(rib, rib);
            if (r2 >= _SmoothingRadius2)
                continue;
            rate += WallWeight(wall, phase) * ContinuityPair(pi.velocity, wall.velocity, PairGradient(rib, sqrt(r2), 1u, 0u));
            neighbours++;
        }
    }
    return rate;
}

// delta-SPH, before the drift (SphDensityDiffusion.hlsl): the continuity sum at x^n with the half-step velocities
// v + a dt / 2 that HalfStep is about to give (the sorted order and accelerations are the last force pass's), and the
// diffusion from every neighbour's delta^n. Where the viscosity is implicit the pass runs after HalfKick and the
// solve instead, on the half-step velocities the drift will take: ahead of the solve, the continuity saw the
// undamped kick, and the two halves of its trapezoidal rule integrated two different velocity fields.
// Laned (NeighbourLanes.hlsl).
[numthreads(PARTICLE_THREADS, 1, 1)]
void DensityRate(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint i = min(LaneOwner(id.x), _ParticleCount - 1u);
    uint lane = FirstCandidate(id.x, _ParticleCount);
    Particle pi = _Particles[i];
    float halfKick = ViscosityIsImplicit() ? 0.0 : 0.5 * _TimeStep;
    float3 vi = pi.velocity + halfKick * _Accelerations[i].xyz;
    PhaseProperties phaseI = _Phases[PHASE_OF(pi)];
    float deltaI = _NumberDensities[pi.id];
    int3 home = GridCoordOf(pi.position);
    NeighbourList list = ListOf(i);
    float continuity = 0.0;
    float diffusion = 0.0;
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
            float3 gradient = PairGradient(rij, sqrt(r2), pi.id, pj.id);
            continuity += ContinuityPair(vi, pj.velocity + halfKick * _Accelerations[j].xyz, gradient);
#if MULTIPHASE
            PhaseProperties phaseJ = _Phases[PHASE_OF(pj)];
            float restNumberDensityIJ = 0.5 * (phaseI.restDensity / phaseI.particleMass + phaseJ.restDensity / phaseJ.particleMass);
            float restDensityIJ = 0.5 * (phaseI.restDensity + phaseJ.restDensity);
#else
            float restNumberDensityIJ = phaseI.restDensity / phaseI.particleMass;
            float restDensityIJ = phaseI.restDensity;
#endif
            diffusion += DensityDiffusionPair(deltaI, _NumberDensities[pj.id],
                HydrostaticNumberDensityDifference(restNumberDensityIJ, restDensityIJ, _Gravity, rij), rij, r2, gradient);
        }
        uint2 walls = WallNeighbours(list, home, row);
        for (uint kb = walls.x + lane; kb < walls.y; kb += _NeighbourLanes)
        {
            BoundaryParticle wall = _BoundaryParticles[Neighbour(list, kb)];
            float3 rib = pi.position - wall.position;
            float r2 = dot(rib, rib);
            if (r2 >= _SmoothingRadius2)
                continue;
            continuity += WallWeight(wall, phaseI) * ContinuityPair(vi, wall.velocity, PairGradient(rib, sqrt(r2), 1u, 0u));
        }
    }
    float2 sums = SumOverLanes(float4(continuity, diffusion, 0.0, 0.0), groupThread.x).xy;
    continuity = sums.x;
    diffusion = sums.y;
    if (lane == 0u)
    {
        _DensityRates[i] = float2(continuity, _DensityDiffusion * diffusion);
        _NumberDensitiesHalf[pi.id] = HalfStepNumberDensity(deltaI, continuity, diffusion, _TimeStep);
    }
}

// delta-SPH, after the drift and the re-sort: the second half of the continuity sum, then rho and the Tait pressure.
// Laned (NeighbourLanes.hlsl).
[numthreads(PARTICLE_THREADS, 1, 1)]
void ContinuityDensity(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint i = min(LaneOwner(id.x), _ParticleCount - 1u);
    uint lane = FirstCandidate(id.x, _ParticleCount);
    Particle pi = _Particles[i];
    uint neighbours;
    float continuity = NumberDensityRate(i, lane, _NeighbourLanes, neighbours);
    continuity = SumOverLanes(float4(continuity, 0.0, 0.0, 0.0), groupThread.x).x;
    if (lane != 0u)
        return;
    float numberDensity = _NumberDensitiesHalf[pi.id] + 0.5 * _TimeStep * continuity;
    _NumberDensities[pi.id] = numberDensity;
    PhaseProperties phase = _Phases[PHASE_OF(pi)];
    _Densities[i] = DensityRecord(numberDensity, phase.particleMass, phase.restDensity);
}

// Laned (NeighbourLanes.hlsl): dispatched over _BoundaryCount * _NeighbourLanes threads.
[numthreads(PARTICLE_THREADS, 1, 1)]
void WallPressure(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint b = min(LaneOwner(id.x), _BoundaryCount - 1u);
    uint lane = FirstCandidate(id.x, _BoundaryCount);
    float3 xb = _BoundaryParticles[b].position;
    int3 home = GridCoordOf(xb);
    NeighbourList list = ListOf(_ParticleCount + b); // a wall's list holds its fluid neighbours only
    float2 sums = float2(0.0, 0.0);
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 range = FluidNeighbours(list, home, row);
        for (uint k = range.x + lane; k < range.y; k += _NeighbourLanes)
        {
            uint f = Neighbour(list, k);
            float3 fluidToWall = xb - _Particles[f].position;
            float r2 = dot(fluidToWall, fluidToWall);
            if (r2 >= _SmoothingRadius2)
                continue;
            float4 df = _Densities[f];
            sums += WallPressureTerm(df.y, df.x, _Gravity, fluidToWall, Kernel(r2));
        }
    }
    sums = SumOverLanes(float4(sums, 0.0, 0.0), groupThread.x).xy;
    if (lane == 0u)
        _BoundaryPressures[b] = WallPressureOf(sums);
}

#endif
