#ifndef SPHFLUID_PASSES_DIVERGENCE_FREE_DRIFT_INCLUDED
#define SPHFLUID_PASSES_DIVERGENCE_FREE_DRIFT_INCLUDED

// The divergence-free sub-step's drift with its wall contact (DivergenceFreeSolver.hlsl), and the per-particle
// divergence the diagnostics read.

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
