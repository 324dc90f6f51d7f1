#ifndef SPHFLUID_PASSES_DIVERGENCE_FREE_DRIFT_INCLUDED
#define SPHFLUID_PASSES_DIVERGENCE_FREE_DRIFT_INCLUDED

// The divergence-free sub-step's drift with its wall contact (DivergenceFreeSolver.hlsl), and the per-particle
// divergence the diagnostics read.

// Whether DivergenceFreeSolver.hlsl's wall contact acts on particle i: under-dense at the sub-step's start, or bound
// to end its drift within DIVERGENCE_CONTACT_GAP spacings of a wall's face.
bool InWallContact(uint i, Particle p)
{
    return _Densities[i].z < RestNumberDensityOf(p)
        || WallGap(DriftedPosition(p.position, p.velocity)) < DIVERGENCE_CONTACT_GAP * _ParticleSpacing;
}

// This lane's share of the wall contact's sums for particle i (WallContactVelocity): the walls' weighted kernel
// gradients (xyz) and the rate they approach at (w).
float4 WallContactSums(uint i, Particle p, uint lane)
{
    PhaseProperties phase = _Phases[PHASE_OF(p)];
    int3 home = GridCoordOf(p.position);
    NeighbourList list = ListOf(i);
    float3 wallGradients = float3(0.0, 0.0, 0.0);
    float wallRate = 0.0;
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 walls = WallNeighbours(list, home, row);
        for (uint kb = walls.x + lane; kb < walls.y; kb += _NeighbourLanes)
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
    return float4(wallGradients, wallRate);
}

// Laned (NeighbourLanes.hlsl) for the particles in wall contact, whose walk of their wall neighbours one thread made
// alone while the rest of a small scene's GPU stood idle; the others only pass the lanes' barriers.
[numthreads(PARTICLE_THREADS, 1, 1)]
void Drift(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint i = min(LaneOwner(id.x), _ParticleCount - 1u);
    uint lane = FirstCandidate(id.x, _ParticleCount);
    Particle p = _Particles[i];
    bool contact = InWallContact(i, p);
    float4 sums = float4(0.0, 0.0, 0.0, 0.0);
    if (contact) // not a ?: , which HLSL may evaluate on both sides
        sums = WallContactSums(i, p, lane);
    float4 walls = SumOverLanes(sums, groupThread.x);
    if (lane != 0u)
        return;
    if (contact)
        p.velocity = WallContactVelocity(p.velocity, walls.xyz, walls.w);
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
