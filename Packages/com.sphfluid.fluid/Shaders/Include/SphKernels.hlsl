#ifndef SPHFLUID_SPH_KERNELS_INCLUDED
#define SPHFLUID_SPH_KERNELS_INCLUDED

#include "FluidConstants.hlsl"

// ONE smoothing kernel for every sum of the solver: the cubic B-spline of Monaghan & Lattanzio 1985
// ("A refined particle method for astrophysical problems", A&A 149), in the support-radius form used by
// Ihmsen et al. 2014 ("SPH fluids in computer graphics", Eurographics STAR). With support H (= the
// grid cell size, _SmoothingRadius) and q = r / H:
//   W(q)     = sigma * { 6 (q^3 - q^2) + 1     0 <= q <= 1/2
//                      { 2 (1 - q)^3           1/2 < q <= 1
//                      { 0                     q > 1,                 sigma = 8 / (pi H^3)
//   gradW    = (sigma / H) w'(q) r_ij / r,  w'(q) = 6 (3 q^2 - 2 q) or -6 (1 - q)^2
// Density, the pressure gradient, viscosity, XSPH and the surface normals all use this one kernel, so
// the pressure force is the gradient of the SPH potential energy (Price 2012, "Smoothed particle
// hydrodynamics and magnetohydrodynamics", JCP 231, sec. 3) and the fluid can sit still.
// Why this kernel at H = 2 spacings by default: on the cubic spawn lattice it sums to the lattice
// number density to 1e-5 and reproduces a linear pressure field's gradient to 2 % (the Spiky kernel
// the solver used before recovered 77 %, so a tank at rest was 32 % too steep in pressure);
// SmoothingKernels.LatticeGradientReproduction (C#) prints the figure for any support.
// The coefficients are computed once in double precision on the CPU (FluidSimulation) and uploaded.

// Reads _SmoothingRadius, _SmoothingRadius2, _KernelCoefficient and _GradientCoefficient (FluidConstants.hlsl).

float KernelShape(float q)
{
    float t = 1.0 - q;
    float inner = 6.0 * (q * q * q - q * q) + 1.0;
    float outer = 2.0 * t * t * t;
    return q <= 0.5 ? inner : (q < 1.0 ? outer : 0.0);
}

float KernelShapeDerivative(float q)
{
    float t = 1.0 - q;
    float inner = 6.0 * (3.0 * q * q - 2.0 * q);
    float outer = -6.0 * t * t;
    return q <= 0.5 ? inner : (q < 1.0 ? outer : 0.0);
}

// W(r) from r^2.
float Kernel(float r2)
{
    return _KernelCoefficient * KernelShape(sqrt(r2) / _SmoothingRadius);
}

// gradW with respect to x_i of the pair (i, j): rij = x_i - x_j, r = |rij| > 0.
float3 KernelGradient(float3 rij, float r)
{
    return (_GradientCoefficient * KernelShapeDerivative(r / _SmoothingRadius) / r) * rij;
}

#endif
