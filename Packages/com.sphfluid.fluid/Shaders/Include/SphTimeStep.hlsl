#ifndef SPHFLUID_SPH_TIME_STEP_INCLUDED
#define SPHFLUID_SPH_TIME_STEP_INCLUDED

// Inputs of the adaptive time step (TimeStepController, C#):
//   dt = min(cfl h / (c + vmax), 0.25 sqrt(h / amax), dt_viscous, MaxTimeStep)
// (CFL condition: Courant, Friedrichs & Lewy 1928, in the SPH form of Monaghan 1992; force condition:
// Monaghan 1992 / Becker & Teschner 2007, sec. 4.2; dt_viscous from the viscous force's stiffest wave on the
// particle lattice, ViscousStepLimit, C#). The GPU finds
// vmax = max |v_i| and amax = max |a_i| with a two-level max-reduction (group partials, then one
// group over the partials) and the host reads them back asynchronously.
// Non-finite values are reduced as 0 here (they would poison max()); the diagnostics count them.

#define REDUCTION_THREADS 256u

float FiniteOrZero(float value)
{
    // Exponent bits all set = Inf or NaN; checked on the bits because fast-math may fold isnan away.
    return (asuint(value) & 0x7F800000u) == 0x7F800000u ? 0.0 : value;
}

bool IsFinite3(float3 v)
{
    uint3 bits = asuint(v) & 0x7F800000u;
    return all(bits != uint3(0x7F800000u, 0x7F800000u, 0x7F800000u));
}

#endif
