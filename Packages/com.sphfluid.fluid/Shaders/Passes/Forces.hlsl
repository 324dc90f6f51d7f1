#ifndef SPHFLUID_PASSES_FORCES_INCLUDED
#define SPHFLUID_PASSES_FORCES_INCLUDED

// FluidSolver.compute's force passes: colour-field normals (SphSurfaceTension.hlsl), the strain-rate viscosity's
// rotations (SphVelocityGradient.hlsl) and every force on a fluid particle from its fluid and wall neighbours
// (SphPressureForce.hlsl, SphViscosity.hlsl, SphXsph.hlsl, SphBoundary.hlsl's wall contact); NonPressureForces is the
// same sum without pressure, for the divergence-free solver.

// Laned (NeighbourLanes.hlsl).
[numthreads(PARTICLE_THREADS, 1, 1)]
void Normals(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint i = min(LaneOwner(id.x), _ParticleCount - 1u);
    uint lane = FirstCandidate(id.x, _ParticleCount);
    Particle pi = _Particles[i];
    uint phaseI = PHASE_OF(pi);
    int3 home = GridCoordOf(pi.position);
    NeighbourList list = ListOf(i);
    float3 normal = float3(0.0, 0.0, 0.0);
    for (uint row = 0u; row < NeighbourRows(list); row++)
    {
        uint2 range = FluidNeighbours(list, home, row);
        for (uint k = range.x + lane; k < range.y; k += _NeighbourLanes)
        {
            uint j = Neighbour(list, k);
            Particle pj = _Particles[j];
            float3 rij = pi.position - pj.position;
            float r2 = dot(rij, rij);
            if (r2 >= _SmoothingRadius2 || r2 <= 0.0 || PHASE_OF(pj) != phaseI)
                continue;
            normal += KernelGradient(rij, sqrt(r2)) / _Densities[j].z;
        }
    }
    normal = SumOverLanes(float4(normal, 0.0), groupThread.x).xyz;
    if (lane != 0u)
        return;
    _Normals[i] = float4(_SmoothingRadius * normal, 0.0);
}

// The velocity gradient's sums over the lanes of this thread's particle (NeighbourLanes.hlsl), as five float4s; every
// thread of the group must call it.
VelocityGradientSums SumVelocityGradientOverLanes(VelocityGradientSums sums, uint groupThread)
{
    float4 a = SumOverLanes(float4(sums.vx, sums.vy.x), groupThread);
    float4 b = SumOverLanes(float4(sums.vy.yz, sums.vz.xy), groupThread);
    float4 c = SumOverLanes(float4(sums.vz.z, sums.mx), groupThread);
    float4 d = SumOverLanes(float4(sums.my, sums.mz.x), groupThread);
    float4 e = SumOverLanes(float4(sums.mz.yz, 0.0, 0.0), groupThread);
    VelocityGradientSums total;
    total.vx = a.xyz;
    total.vy = float3(a.w, b.xy);
    total.vz = float3(b.zw, c.x);
    total.mx = c.yzw;
    total.my = d.xyz;
    total.mz = float3(d.w, e.xy);
    return total;
}

// Omega_i = curl v / 2 for the strain rate's viscous stress (SphViscosity.hlsl), from the velocity gradient corrected for
// the particle distribution (SphVelocityGradient.hlsl). Walls with friction count, at their own velocity: beside a wall
// that turns with the fluid the pair term then leaves the common rotation alone; free-slip walls count for nothing.
// Laned (NeighbourLanes.hlsl).
[numthreads(PARTICLE_THREADS, 1, 1)]
void Rotations(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    uint i = min(LaneOwner(id.x), _ParticleCount - 1u);
    uint lane = FirstCandidate(id.x, _ParticleCount);
    Particle pi = _Particles[i];
    PhaseProperties phaseI = _Phases[PHASE_OF(pi)];
    float4 di = _Densities[i];
    int3 home = GridCoordOf(pi.position);
    NeighbourList list = ListOf(i);
    VelocityGradientSums sums = NoVelocityGradientSums();
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
            float3 gradient = PairGradient(rij, sqrt(r2), pi.id, pj.id) / _Densities[j].z;
            sums = AddVelocityGradientPair(sums, pj.velocity - pi.velocity, rij, gradient);
        }
        uint2 walls = WallNeighbours(list, home, row);
        for (uint kb = walls.x + lane; kb < walls.y; kb += _NeighbourLanes)
        {
            BoundaryParticle wall = _BoundaryParticles[Neighbour(list, kb)];
            float3 rib = pi.position - wall.position;
            float r2 = dot(rib, rib);
            if (r2 >= _SmoothingRadius2)
                continue;
            float3 gradient = PairGradient(rib, sqrt(r2), 1u, 0u) * (_WallFriction * WallWeight(wall, phaseI) / di.z);
            sums = AddVelocityGradientPair(sums, wall.velocity - pi.velocity, rib, gradient);
        }
    }
    sums = SumVelocityGradientOverLanes(sums, groupThread.x);
    if (lane != 0u)
        return;
    _Rotations[i] = float4(RotationOf(sums), 0.0);
}

// Omega_ij, the mean rotation of the pair i, j for the strain rate's viscous stress; zero for Morris's.
float3 PairRotation(float3 rotationI, uint j)
{
    return _StrainRateViscosity != 0u ? 0.5 * (rotationI + _Rotations[j].xyz) : float3(0.0, 0.0, 0.0);
}

// mu_ij of a fluid pair whose first particle has viscosity muI (SphViscosity.hlsl's mixing rule); with one phase
// every pair has the phase's own.
float PairViscosity(float muI, uint phaseIndexJ)
{
#if MULTIPHASE
    return MixedViscosity(muI, _Phases[phaseIndexJ].viscosity);
#else
    return muI;
#endif
}

// What lane `lane` of particle i's neighbourhood (every _NeighbourLanes-th neighbour, NeighbourLanes.hlsl) adds to
// the sums AccelerationOf turns into its acceleration.
struct ForceSums
{
    float3 force;
    float3 xsph;
    float3 wallGradients;
    float wallRate;
    float wallNumberDensity;
};

ForceSums ForceSumsOf(uint i, bool withPressure, uint lane)
{
    Particle pi = _Particles[i];
    uint phaseIndexI = PHASE_OF(pi);
    PhaseProperties phaseI = _Phases[phaseIndexI];
    float4 di = _Densities[i];
#if SURFACE_TENSION
    float3 normalI = _Normals[i].xyz;
#endif
    // The viscosity may be the implicit solve's instead (ViscositySolve.hlsl); the strain rate's rotation term then stays
    // here, at the rotations of the sub-step's start.
    bool explicitViscosity = !ViscosityIsImplicit();
    bool strainRate = _StrainRateViscosity != 0u;
    float3 rotationI = strainRate ? _Rotations[i].xyz : float3(0.0, 0.0, 0.0);
    float3 force = float3(0.0, 0.0, 0.0);
    float3 xsph = float3(0.0, 0.0, 0.0);
    float3 wallGradients = float3(0.0, 0.0, 0.0);
    float wallRate = 0.0;
    float wallNumberDensity = 0.0;
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
            float r = sqrt(r2);
            float4 dj = _Densities[j];
            uint phaseIndexJ = PHASE_OF(pj);
            float muIJ = PairViscosity(phaseI.viscosity, phaseIndexJ);
            float3 gradient = PairGradient(rij, r, pi.id, pj.id);
            if (withPressure)
                force += PressureForcePair(di.w, dj.w, gradient);
            if (explicitViscosity)
                force += ViscosityForcePair(muIJ, pi.velocity, pj.velocity, rij, r2, gradient, 1.0 / (di.z * dj.z), PairRotation(rotationI, j));
            else if (strainRate)
                force += ViscosityRotationForcePair(muIJ, rij, r2, gradient, 1.0 / (di.z * dj.z), PairRotation(rotationI, j));
            if (withPressure)
                force += ArtificialViscosityForcePair(pi.velocity, pj.velocity, rij, r2, gradient, 0.5 * (di.x + dj.x), 1.0 / (di.z * dj.z));
#if SURFACE_TENSION
            if (phaseIndexJ == phaseIndexI && phaseI.surfaceTension > 0.0)
                force += SurfaceTensionForcePair(phaseI.surfaceTension, normalI, _Normals[j].xyz,
                    phaseI.particleMass / phaseI.restDensity, dj.z, gradient);
#endif
#if XSPH
            xsph += XsphPair(pi.velocity, pj.velocity, r2, di.z, dj.z);
#endif
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
            float r = sqrt(r2);
            float3 gradient = PairGradient(rib, r, 1u, 0u);
            float weight = WallWeight(wall, phaseI);
            if (withPressure)
                force += BoundaryPressureForcePair(di.y, _BoundaryPressures[b], di.z, weight, gradient);
            if (explicitViscosity)
                force += ViscosityForcePair(_WallFriction * phaseI.viscosity, pi.velocity, wall.velocity, rib, r2, gradient,
                    weight / (di.z * di.z), rotationI);
            else if (strainRate)
                force += ViscosityRotationForcePair(_WallFriction * phaseI.viscosity, rib, r2, gradient, weight / (di.z * di.z), rotationI);
            if (withPressure)
            {
                force += ArtificialViscosityForcePair(pi.velocity, wall.velocity, rib, r2, gradient, di.x, weight / (di.z * di.z));
                float3 intoWall = float3(0.0, 0.0, 0.0);
                if (UnderDense(di.x, phaseI.restDensity))
                    intoWall = IntoWallVelocity(pi.velocity - wall.velocity, WallNormal(wall, _BoundaryRest[_BoundarySortedSource[b]].position));
                force += WallArtificialViscosityForcePair(intoWall, rib, r2, gradient, di.x, weight / (di.z * di.z));
            }
            wallGradients += weight * gradient;
            wallNumberDensity += weight * Kernel(r2);
            wallRate += weight * dot(wall.velocity, gradient);
        }
    }
    ForceSums sums;
    sums.force = force;
    sums.xsph = xsph;
    sums.wallGradients = wallGradients;
    sums.wallRate = wallRate;
    sums.wallNumberDensity = wallNumberDensity;
    return sums;
}

// Every force on the particle of thread `thread` (laned: every thread of the group calls this, for SumOverLanes);
// withPressure false (DFSPH) leaves out the pressure and the artificial viscosities, whose scale is the Tait fluid's
// speed of sound: the solves keep the density instead.
void AccelerationOf(uint thread, uint groupThread, bool withPressure)
{
    uint i = min(LaneOwner(thread), _ParticleCount - 1u);
    uint lane = FirstCandidate(thread, _ParticleCount);
    ForceSums sums = ForceSumsOf(i, withPressure, lane);
    float4 forceAndRate = SumOverLanes(float4(sums.force, sums.wallRate), groupThread);
    float4 xsphAndWallDensity = SumOverLanes(float4(sums.xsph, sums.wallNumberDensity), groupThread);
    float3 wallGradients = SumOverLanes(float4(sums.wallGradients, 0.0), groupThread).xyz;
    if (lane != 0u)
        return;
    float3 force = forceAndRate.xyz;
    float wallRate = forceAndRate.w;
    float3 xsph = xsphAndWallDensity.xyz;
    float wallNumberDensity = xsphAndWallDensity.w;
    Particle pi = _Particles[i];
    PhaseProperties phaseI = _Phases[PHASE_OF(pi)];
    float4 di = _Densities[i];
    float3 a = force / phaseI.particleMass + _Gravity;
    float3 correction = float3(0.0, 0.0, 0.0);
#if XSPH
    correction = _XsphEpsilon * xsph;
#endif
    // SphBoundary.hlsl's wall contact, on the velocity the particle drifts with next (DFSPH applies it in its drift
    // instead: Drift, InWallContact).
    if (withPressure && (_WallContactAtAnyDensity != 0u || di.x < phaseI.restDensity) && wallNumberDensity > _WallContactNumberDensity * phaseI.wallWeightScale)
    {
        float3 predicted = pi.velocity + a * _TimeStep + correction;
        correction += WallContactVelocity(predicted, wallGradients, wallRate) - predicted;
    }
    _Accelerations[i] = float4(a, 0.0);
    _VelocityCorrections[i] = float4(correction, 0.0);
}

// Laned (NeighbourLanes.hlsl), as NonPressureForces.
[numthreads(PARTICLE_THREADS, 1, 1)]
void Forces(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    AccelerationOf(id.x, groupThread.x, true);
}

[numthreads(PARTICLE_THREADS, 1, 1)]
void NonPressureForces(uint3 id : SV_DispatchThreadID, uint3 groupThread : SV_GroupThreadID)
{
    AccelerationOf(id.x, groupThread.x, false);
}

#endif
