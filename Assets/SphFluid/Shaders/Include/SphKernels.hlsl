#ifndef SPHFLUID_SPH_KERNELS_INCLUDED
#define SPHFLUID_SPH_KERNELS_INCLUDED

// SPH smoothing kernels of support radius h (Mueller, Charypar & Gross 2003, "Particle-based fluid
// simulation for interactive applications", SCA 2003, eqs. 20-22; Spiky after Desbrun & Gascuel 1996):
//   Spiky                 Ws(r)       = 15 / (pi h^6) (h - r)^3                  for r < h, else 0
//   Spiky gradient        gradW(r_ij) = -45 / (pi h^6) (h - r)^2 r_ij / r        (0 at r = 0)
//   Poly6                 W(r)        = 315 / (64 pi h^9) (h^2 - r^2)^3          (XSPH only)
//   viscosity Laplacian   lapW(r)     = 45 / (pi h^6) (h - r)
// DEVIATION from the team notes (which use Poly6 for the number density): the number density uses the
// Spiky kernel, the very kernel whose gradient the pressure force uses. With Poly6 density and Spiky
// gradient the pressure force is not the gradient of any potential energy (the SPH Lagrangian needs one
// kernel for both; Price 2012, "Smoothed particle hydrodynamics and magnetohydrodynamics", JCP 231,
// sec. 3), and measured on a 256-particle tank without XSPH the mismatch pumped energy in: the fluid
// "boiled" at ~2 m/s for as long as it ran. With one kernel the same tank comes to rest. Spiky's
// gradient does not vanish as r -> 0, so close particles still repel (Poly6's would let them clump).
// The coefficients are computed once in double precision on the CPU (FluidSimulation) and uploaded:
// h^9 underflows single precision's comfortable range for small h.

float _SmoothingRadius;               // h, m
float _SmoothingRadius2;              // h^2, m^2
float _SpikyCoefficient;              // 15 / (pi h^6)
float _Poly6Coefficient;              // 315 / (64 pi h^9)
float _SpikyGradientCoefficient;      // 45 / (pi h^6) (the sign is applied below)
float _ViscosityLaplacianCoefficient; // 45 / (pi h^6)

// The density kernel (number density delta_i = sum_j Ws(r_ij)).
float SpikyKernel(float r2)
{
    float d = max(_SmoothingRadius - sqrt(r2), 0.0);
    return _SpikyCoefficient * d * d * d;
}

float Poly6(float r2)
{
    float d = max(_SmoothingRadius2 - r2, 0.0);
    return _Poly6Coefficient * d * d * d;
}

// gradW with respect to x_i of the pair (i, j), rij = x_i - x_j, r = |rij| > 0, r < h.
float3 SpikyGradient(float3 rij, float r)
{
    float d = _SmoothingRadius - r;
    return (-_SpikyGradientCoefficient * d * d / r) * rij;
}

float ViscosityLaplacian(float r)
{
    return _ViscosityLaplacianCoefficient * (_SmoothingRadius - r);
}

#endif
