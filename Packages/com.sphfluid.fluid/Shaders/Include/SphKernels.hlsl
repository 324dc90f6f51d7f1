#ifndef SPHFLUID_SPH_KERNELS_INCLUDED
#define SPHFLUID_SPH_KERNELS_INCLUDED

#include "FluidConstants.hlsl"

// ONE smoothing kernel family for every sum of the solver, chosen per scene (_SmoothingKernel,
// FluidSettings.SmoothingKernel), in the support-radius form of Ihmsen et al. 2014 ("SPH fluids in computer
// graphics", Eurographics STAR). With support H (= the grid cell size, _SmoothingRadius) and q = r / H,
// W(r) = sigma w(q) and gradW = (sigma / H) w'(q) r_ij / r, w = 0 for q >= 1:
//   0: cubic B-spline (Monaghan & Lattanzio 1985, "A refined particle method for astrophysical problems", A&A 149)
//        w(q) = 6 (q^3 - q^2) + 1  (q <= 1/2),  2 (1 - q)^3  (1/2 < q < 1),          sigma = 8 / (pi H^3)
//   1: Wendland C2 (Wendland 1995, "Piecewise polynomial, positive definite and compactly supported radial
//      functions of minimal degree", Adv. Comput. Math. 4)
//        w(q) = (1 - q)^4 (1 + 4 q),  w'(q) = -20 q (1 - q)^3,                        sigma = 21 / (2 pi H^3)
// Density, the pressure gradient, viscosity, XSPH and the surface normals all use the one kernel, so the pressure
// force is the gradient of the SPH potential energy (Price 2012, "Smoothed particle hydrodynamics and
// magnetohydrodynamics", JCP 231, sec. 3) and the fluid can sit still.
// Why the cubic spline at H = 2 spacings by default: on the cubic spawn lattice it sums to the lattice number
// density to 1e-5 and reproduces a linear pressure field's gradient to 2 % at the lowest cost (the Spiky kernel the
// solver used before recovered 77 %, so a tank at rest was 32 % too steep in pressure). Above 2.25 spacings its
// particles pair up (Dehnen & Aly 2012, "Improving convergence in SPH simulations without pairing instability",
// MNRAS 425) and the walls stop holding them: in a resting tank the last-resort clamp caught 208 particles at 2.5
// spacings and 23 515 at 3 (FluidSettings.MaxCubicSplineSupportRatio). Wendland C2 has no
// pairing instability and is the kernel for 3 and 4 spacings. SmoothingKernels.LatticeGradientReproduction (C#)
// prints the gradient figure for either kernel at any support; the branch below is uniform across a dispatch.
// The coefficients are computed once in double precision on the CPU (FluidSimulation) and uploaded.

// Reads _SmoothingKernel, _SmoothingRadius, _SmoothingRadius2, _KernelCoefficient and _GradientCoefficient
// (FluidConstants.hlsl).

float KernelShape(float q)
{
    float t = max(1.0 - q, 0.0);
    if (_SmoothingKernel == 1u)
        return t * t * t * t * (1.0 + 4.0 * q);
    float inner = 6.0 * (q * q * q - q * q) + 1.0;
    float outer = 2.0 * t * t * t;
    return q <= 0.5 ? inner : outer;
}

float KernelShapeDerivative(float q)
{
    float t = max(1.0 - q, 0.0);
    if (_SmoothingKernel == 1u)
        return -20.0 * q * t * t * t;
    float inner = 6.0 * (3.0 * q * q - 2.0 * q);
    float outer = -6.0 * t * t;
    return q <= 0.5 ? inner : outer;
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
