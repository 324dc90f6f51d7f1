#ifndef SPHFLUID_PASSES_SHIFTING_INCLUDED
#define SPHFLUID_PASSES_SHIFTING_INCLUDED

// FluidSolver.compute's particle shifting (ParticleShifting.hlsl): ParticleShift computes each particle's shift,
// ApplyShift moves it, so every particle reads its neighbours' unshifted places.

// Laned (NeighbourLanes.hlsl).
[numthreads(PARTICLE_THREADS, 1, 1)]
void ParticleShift(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint i = min(LaneOwner(id.x), _ParticleCount - 1u);
    uint lane = FirstCandidate(id.x, _ParticleCount);
    Particle pi = _Particles[i];
    uint phaseI = PHASE_OF(pi);
    float volumeI = 1.0 / _Densities[i].z;
    PhaseProperties phase = _Phases[phaseI];
    int3 home = GridCoordOf(pi.position);
    NeighbourList list = ListOf(i);
    float4 concentration = float4(0.0, 0.0, 0.0, 0.0);
    float3 otherPhases = float3(0.0, 0.0, 0.0);
    float divergence = 0.0;
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 range = FluidNeighbours(list, home, row);
        for (uint k = range.x + lane; k < range.y; k += _NeighbourLanes)
        {
            uint j = Neighbour(list, k);
            Particle pj = _Particles[j];
            float3 rij = pi.position - pj.position;
            float r2 = dot(rij, rij);
            if (r2 >= _SmoothingRadius2)
                continue;
            float3 gradient = j == i ? float3(0.0, 0.0, 0.0) : PairGradient(rij, sqrt(r2), pi.id, pj.id);
            float volumeJ = 1.0 / _Densities[j].z;
            float4 pair = ConcentrationPair(volumeJ, Kernel(r2), gradient);
            concentration += pair;
            divergence += PositionDivergencePair(volumeJ, rij, gradient);
            if (PHASE_OF(pj) != phaseI)
                otherPhases += pair.xyz;
        }
        uint2 walls = WallNeighbours(list, home, row);
        for (uint kb = walls.x + lane; kb < walls.y; kb += _NeighbourLanes)
        {
            BoundaryParticle wall = _BoundaryParticles[Neighbour(list, kb)];
            float3 rib = pi.position - wall.position;
            float r2 = dot(rib, rib);
            if (r2 >= _SmoothingRadius2)
                continue;
            float3 gradient = PairGradient(rib, sqrt(r2), 1u, 0u);
            float wallVolume = WallWeight(wall, phase) * volumeI;
            concentration += ConcentrationPair(wallVolume, Kernel(r2), gradient);
            divergence += PositionDivergencePair(wallVolume, rib, gradient);
        }
    }
    concentration = SumOverLanes(concentration, groupThread.x);
    float4 others = SumOverLanes(float4(otherPhases, divergence), groupThread.x);
    otherPhases = others.xyz;
    divergence = others.w;
    if (lane != 0u)
        return;
    _Shifts[i] = float4(ShiftOf(concentration, otherPhases, divergence, length(pi.velocity), _TimeStep, _ParticleSpacing), 0.0);
}

[numthreads(PARTICLE_THREADS, 1, 1)]
void ApplyShift(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _ParticleCount)
        return;
    Particle p = _Particles[i];
    p.position += _Shifts[i].xyz;
    LastResortClamp(p);
    _Particles[i] = p;
}

#endif
