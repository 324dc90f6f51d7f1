#ifndef SPHFLUID_SPH_VELOCITY_GRADIENT_INCLUDED
#define SPHFLUID_SPH_VELOCITY_GRADIENT_INCLUDED

// A particle's velocity gradient corrected for the distribution of its neighbours, and the local rigid rotation
// Omega = curl v / 2 taken from it, which the strain-rate viscosity (SphViscosity.hlsl) leaves out of each pair.
// Bonet & Lok 1999, "Variational and momentum preservation aspects of Smooth Particle Hydrodynamic formulations":
//   grad v_i = [sum_j V_j (v_j - v_i) (x) gradW_ij] [sum_j V_j (x_j - x_i) (x) gradW_ij]^-1,
// exact for a linear velocity field wherever the moment matrix (the second factor) is invertible, so a rigid rotation
// gives its own Omega at a free surface and beside a wall as in the bulk. Without the correction the first sum alone
// under-reads Omega wherever the support is cut, and the viscosity would brake the rotation there.

// The two sums, row by row: v* = sum_j V_j (v_j - v_i)_* gradW_ij and m* = sum_j V_j (x_j - x_i)_* gradW_ij, * = x, y, z.
// Kept as vectors set to zero field by field, not float3x3 sums started from (float3x3)0: summed into matrices, the kernel
// compiled through glslang read on lavapipe the uncorrected sum for every particle in one keyword variant, and a wrong
// rotation in another, with results that came and went with edits that changed no arithmetic, while the same sums in C#
// (ReferenceSph) were exact.
struct VelocityGradientSums
{
    float3 vx, vy, vz;
    float3 mx, my, mz;
};

VelocityGradientSums NoVelocityGradientSums()
{
    VelocityGradientSums sums;
    sums.vx = float3(0.0, 0.0, 0.0);
    sums.vy = float3(0.0, 0.0, 0.0);
    sums.vz = float3(0.0, 0.0, 0.0);
    sums.mx = float3(0.0, 0.0, 0.0);
    sums.my = float3(0.0, 0.0, 0.0);
    sums.mz = float3(0.0, 0.0, 0.0);
    return sums;
}

// Neighbour j's terms: dv = v_j - v_i, rij = x_i - x_j, and weightedGradient = V_j gradW_ij.
VelocityGradientSums AddVelocityGradientPair(VelocityGradientSums sums, float3 dv, float3 rij, float3 weightedGradient)
{
    sums.vx += dv.x * weightedGradient;
    sums.vy += dv.y * weightedGradient;
    sums.vz += dv.z * weightedGradient;
    sums.mx -= rij.x * weightedGradient;
    sums.my -= rij.y * weightedGradient;
    sums.mz -= rij.z * weightedGradient;
    return sums;
}

// Omega = curl v / 2 from the sums. For v = A x the velocity sum is A times the moment matrix M (rows m*), so
// A = V M^-1, whose columns are (my x mz, mz x mx, mx x my) / det M and whose entry A_ab is row a of V dotted with column b.
// M is the identity in a full support; where the support is nearly empty (a lone particle, a thin sheet) it is close to
// singular, and the uncorrected sum is taken instead.
float3 RotationOf(VelocityGradientSums sums)
{
    float3 px = cross(sums.my, sums.mz), py = cross(sums.mz, sums.mx), pz = cross(sums.mx, sums.my);
    float det = dot(sums.mx, px);
    if (!(det > 0.05))
    {
        px = float3(1.0, 0.0, 0.0);
        py = float3(0.0, 1.0, 0.0);
        pz = float3(0.0, 0.0, 1.0);
        det = 1.0;
    }
    return (0.5 / det) * float3(dot(sums.vz, py) - dot(sums.vy, pz), dot(sums.vx, pz) - dot(sums.vz, px), dot(sums.vy, px) - dot(sums.vx, py));
}

#endif
