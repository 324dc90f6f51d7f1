#ifndef SPHFLUID_PASSES_INTEGRATION_INCLUDED
#define SPHFLUID_PASSES_INTEGRATION_INCLUDED

// FluidSolver.compute's Velocity-Verlet halves and the clamp behind the walls (SphIntegration.hlsl, SphBoundary.hlsl):
//   HalfStep  v += a dt/2, x += v dt; FullStep  v += a dt/2 + dv; both end with the last-resort clamp.

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
void FullStep(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _ParticleCount)
        return;
    Particle p = _Particles[i];
    p.velocity = FullStepVelocity(p.velocity, _Accelerations[i].xyz, _VelocityCorrections[i].xyz);
    LastResortClamp(p);
    _Particles[i] = p;
}

#endif
