#ifndef SPHFLUID_SPH_INTEGRATION_INCLUDED
#define SPHFLUID_SPH_INTEGRATION_INCLUDED

#include "FluidConstants.hlsl"

// Velocity Verlet (kick-drift-kick; Verlet 1967, Swope et al. 1982), split around the force pass:
//   half step:  v_{n+1/2} = v_n + a_n dt/2 ;  x_{n+1} = x_n + v_{n+1/2} dt     (then clamp)
//   forces:     a_{n+1} = a(x_{n+1}, v_{n+1/2})                                (after the re-sort)
//   full step:  v_{n+1} = v_{n+1/2} + a_{n+1} dt/2 + dv ;  v *= max(0, 1 - damping dt)   (then clamp)
// where dv, computed by the force pass, is XSPH's correction plus the wall contact (SphBoundary.hlsl).
// Second order and time-reversible for position-only forces; the velocity-dependent terms
// (viscosity, XSPH, the wall contact) use the half-step velocity. Before the first step the forces are
// computed once so that a_0 is valid.
// Reads _TimeStep and _VelocityDamping (FluidConstants.hlsl).

float3 HalfKickedVelocity(float3 v, float3 a)
{
    return v + a * (0.5 * _TimeStep);
}

void KickDrift(inout float3 x, inout float3 v, float3 a)
{
    v = HalfKickedVelocity(v, a);
    x += v * _TimeStep;
}

float3 FullStepVelocity(float3 v, float3 a, float3 correction)
{
    v += a * (0.5 * _TimeStep) + correction;
    return v * max(0.0, 1.0 - _VelocityDamping * _TimeStep);
}

// Divergence-free SPH integrates with symplectic Euler (Bender & Koschier 2017, Algorithm 1): the non-pressure
// accelerations give v* = v + a dt (+ dv_xsph, then damping), the constant-density solve corrects v*, and the
// particles drift with it: x += v* dt.
float3 PredictedVelocity(float3 v, float3 a, float3 correction)
{
    v += a * _TimeStep + correction;
    return v * max(0.0, 1.0 - _VelocityDamping * _TimeStep);
}

float3 DriftedPosition(float3 x, float3 v)
{
    return x + v * _TimeStep;
}

#endif
