#ifndef SPHFLUID_PASSES_INTEGRATION_INCLUDED
#define SPHFLUID_PASSES_INTEGRATION_INCLUDED

// FluidSolver.compute's Velocity-Verlet halves and the clamp behind the walls (SphIntegration.hlsl, SphBoundary.hlsl):
//   HalfStep  v += a dt/2, x += v dt; FullStep  v += a dt/2 + dv; both end with the last-resort clamp.
// A plan whose sub-steps may pass the explicit viscous limit (SphViscositySolve.hlsl) splits HalfStep into HalfKick and
// HalfDrift, so that the implicit viscosity solve can take each half kick before the particles drift with it; HalfKick
// and, while the viscosity is implicit, FullStep keep the velocity before their kick in _ViscosityStart.

// The clamp behind the boundary particles: counts every particle it catches.
void LastResortClamp(inout Particle p)
{
    bool caught = false;
#if OBSTACLES
    caught = ObstacleClamp(p.position, p.velocity);
#endif
    caught = ContainerClamp(p.position, p.velocity) || caught;
    if (caught)
        InterlockedAdd(_ClampHits[0], 1u);
}

[numthreads(PARTICLE_THREADS, 1, 1)]
void HalfStep(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _ParticleCount)
        return;
    Particle p = _Particles[i];
    KickDrift(p.position, p.velocity, _Accelerations[i].xyz);
    LastResortClamp(p);
    _Particles[i] = p;
}

[numthreads(PARTICLE_THREADS, 1, 1)]
void HalfKick(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _ParticleCount)
        return;
    Particle p = _Particles[i];
    _ViscosityStart[i] = float4(p.velocity, 0.0);
    p.velocity = HalfKickedVelocity(p.velocity, _Accelerations[i].xyz);
    _Particles[i] = p;
}

[numthreads(PARTICLE_THREADS, 1, 1)]
void HalfDrift(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _ParticleCount)
        return;
    Particle p = _Particles[i];
    p.position = DriftedPosition(p.position, p.velocity);
    LastResortClamp(p);
    _Particles[i] = p;
}

[numthreads(PARTICLE_THREADS, 1, 1)]
void FullStep(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _ParticleCount)
        return;
    Particle p = _Particles[i];
    if (ViscosityIsImplicit())
        _ViscosityStart[i] = float4(p.velocity, 0.0);
    p.velocity = FullStepVelocity(p.velocity, _Accelerations[i].xyz, _VelocityCorrections[i].xyz);
    LastResortClamp(p);
    _Particles[i] = p;
}

#endif
