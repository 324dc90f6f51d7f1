#ifndef SPHFLUID_SPH_KERNELS_INCLUDED
#define SPHFLUID_SPH_KERNELS_INCLUDED

// SPH smoothing kernels of support radius h (Mueller, Charypar & Gross 2003, "Particle-based fluid
// simulation for interactive applications", SCA 2003, eqs. 20-22):
//   Poly6                 W(r)        = 315 / (64 pi h^9) (h^2 - r^2)^3          for r < h, else 0
//   Spiky gradient        gradW(r_ij) = -45 / (pi h^6) (h - r)^2 r_ij / r        (0 at r = 0)
//   viscosity Laplacian   lapW(r)     = 45 / (pi h^6) (h - r)
// Poly6 for density (smooth, its value needs no r), Spiky for pressure (its gradient does not vanish
// as r -> 0, so close particles still repel), the viscosity kernel's Laplacian is positive everywhere.
// The coefficients are computed once in double precision on the CPU (FluidSimulation) and uploaded:
// h^9 underflows single precision's comfortable range for small h.

float _SmoothingRadius;               // h, m
float _SmoothingRadius2;              // h^2, m^2
float _Poly6Coefficient;              // 315 / (64 pi h^9)
float _SpikyGradientCoefficient;      // 45 / (pi h^6) (the sign is applied below)
float _ViscosityLaplacianCoefficient; // 45 / (pi h^6)

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
