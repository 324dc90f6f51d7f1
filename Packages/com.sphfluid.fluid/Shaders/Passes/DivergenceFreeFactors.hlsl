#ifndef SPHFLUID_PASSES_DIVERGENCE_FREE_FACTORS_INCLUDED
#define SPHFLUID_PASSES_DIVERGENCE_FREE_FACTORS_INCLUDED

// FluidSolver.compute's divergence-free SPH factors (DivergenceFreeSolver.hlsl): each fluid particle's number density,
// density and factor alpha after the sort, and each wall particle's as an unknown of the solves.

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
    Particle p = _Particles[i];
    uint particleId = p.id;
    _SolverParticles[i] = float4(p.position, DIVERGENCE_WARM_START * _WarmStart[particleId].y);
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

#endif
