#ifndef SPHFLUID_SPH_BOUNDARY_INCLUDED
#define SPHFLUID_SPH_BOUNDARY_INCLUDED

#include "FluidConstants.hlsl"

#include "SphKernels.hlsl"
#include "BoundaryParticle.hlsl"
#include "Phase.hlsl"

// Walls and obstacles made of particles. The container's walls and every sphere obstacle are sampled
// with boundary particles (BoundarySampling.cs): a shell of ceil(H / s) layers on the fluid's lattice, so
// a fluid particle next to a wall finds the neighbourhood it would have inside the fluid. They take part
// in density and pressure (Akinci, Ihmsen, Akinci, Solenthaler & Teschner 2012, "Versatile rigid-fluid
// coupling for incompressible SPH", SIGGRAPH 2012: a boundary particle b adds its volume to the fluid's
// density sum and receives a pressure force), with each particle's volume V_b carried as the weight
// omega_b = V_b / s^3, the lattice cells it stands for (1 for a shell on the fluid's lattice):
//   delta_i += sum_b omega_ib W(r_ib)
//   F_i^p   += -sum_b omega_ib (p_i + p_b) / delta_i^2 gradW(r_ib)
// where omega_ib = omega_b (delta0_i / delta0) fills the wall particle's volume at fluid particle i's own rest number
// density delta0_i = rho0_i / m_i, as Akinci et al. weigh it with rho0_i V_b (WallWeight). delta0_i equals the
// lattice's delta0 only when a phase's particles stand for exactly s^3: a box whose height is not a whole number of
// spacings spawns a stretched lattice (OilAndWater: 13 rows in 0.2 m, 0.01538 m apart) and its derived mass sets
// delta0_i 2.5 % lower, and a phase of explicit mass sets its own. Weighed at the lattice's delta0, a wall beside
// such a fluid reads 2.5 % times its share of the neighbourhood too dense, so both solvers saw the fluid at rest beside
// a wall as compressed, and DFSPH's wall particles, whose own wall sum then exceeded the rest density of the fluid around them, asked for a
// density no motion of the fluid could give, summed their q without bound and lifted the whole fluid: a DFSPH tank
// spawned 2.5 % stretched rose at 1.02 m/s after its first frame, 0.033 m/s weighed here (StretchedLatticeTankTests).
// The boundary particle's pressure p_b is the fluid's around it, extrapolated hydrostatically as in
// Adami, Hu & Adams 2012 ("A generalized wall boundary condition for smoothed particle hydrodynamics",
// JCP 231, eq. 27), one pass over the boundary particles per sub-step (WallPressure):
//   p_b = max(0, sum_f (p_f + rho_f (g - a_b) . (x_b - x_f)) W(r_bf) / sum_f W(r_bf))
// (a_b, the wall's acceleration, is left out: walls move smoothly at frame rate). Without the
// hydrostatic term the bottom layer carries the column only by compressing more than the fluid above it,
// and with the fluid's own pressure mirrored instead (p_b = p_i, one pair at a time) the wall force is not
// the same for every fluid neighbour of a wall particle: measured, that pumped energy into a tank at rest
// through its corners.
// Friction: the viscous term of SphViscosity.hlsl against the wall's velocity, times _WallFriction
// (0 = free slip, 1 = no slip).
// Contact damping: summation density gives an under-dense particle (a free surface, a splash) no pressure, so
// nothing above stops it from drifting into a wall and the clamp caught it (18 times in a quarter turn of a
// half-full container). Besides the fluid's own artificial viscosity, Monaghan's artificial viscosity
// (SphViscosity.hlsl) is applied against each boundary particle a second time with the velocity's component
// into the wall only, alpha_w = 0.5, and only for under-dense particles (UnderDense): it brakes their motion
// into the wall, where the wall pressure cannot, and leaves sliding along it and the bulk alone. (A 25 times stronger isotropic alpha also stopped the clamp hits, but slowed a
// dam-break front 6-7 % below Martin & Moyce's measurement; braking the bulk too slowed oil rising through
// water in a narrow tank by half.)
// Wall contact: the damping only brakes, so a particle below its rest density (no pressure of its own to meet the
// wall's) that the bulk keeps pushing still reached the clamp: 27 times in 3 s of the OilAndWater scene, along the
// front and back walls of its thin container. Once such a particle is closer to the walls than a particle at rest
// beside a flat wall (its walls' number density sum_b omega_ib W_ib exceeds that lattice value,
// _WallContactNumberDensity: SmoothingKernels.FlatWallNumberDensity, times the phase's WallWeightScale), it may come no closer: the wall part of its
// continuity equation,
//   sum_b omega_ib (v_i - v_b) . gradW_ib = v_i . G_w - sum_b omega_ib v_b . gradW_ib,   G_w = sum_b omega_ib gradW_ib,
// is kept from turning positive by removing exactly the velocity along G_w that would (WallContactVelocity: an
// inelastic contact; sliding along the wall and motion away from it are left alone). It acts on the velocity the
// particle drifts with next (v_{n+1/2} + a dt + dv_xsph) through the full step's velocity correction, so it is not
// an acceleration and does not shorten the step. DFSPH's solves have no such damping and apply the same contact to
// every particle below rest density, and to any within a quarter spacing of a wall's face, in the drift after the
// constant-density solve (DivergenceFreeSolver.hlsl).
// Measured (`Headless/simulate.sh <scene> --seconds N`): clamp hits 27 -> 0 in OilAndWater (3 s), 35 -> 10 in
// SphereWake (4 s, the rest are compressed fluid driven into the corners of the back wall at a third of the speed
// of sound), 2 -> 0 in RotatingContainer (3 s). Applied to every particle below rest density instead, it stilled
// splashes as well but doubled the last-second speed of a small tank at rest (SolverDynamicsTests.TankAtRest_Settles:
// 51 mm/s against 23): contact chatter of the free surface along the side walls. With delta-SPH
// (_WallContactAtAnyDensity = 1) the density gate does not hold: a particle carries its density, and one at the free
// surface keeps one near or just above rest, so it passed the gate while the small near-surface wall pressure could not
// stop it: oil and water in the RestingTank configuration had 21 clamp hits in 3.6 s, all of them surface oil at 901 to
// 903 kg/m^3 in the corners. There the contact acts by distance alone, which took them to 0 and left the resting tank at
// rest. The distance is read off the walls' number density, which in an edge or a corner exceeds a flat wall's rest
// value anywhere; gated by the distance to the faces instead (WallGap under half a spacing), OilAndWater's floor layer
// held 0.6 % oil at 6 s against 0.9 %, layering index 0.962 against 0.963: a particle or two, which does not pay for
// measuring every WCSPH figure again (Headless/tools/experiment.sh --baseline wcsph-contact-by-distance).
// A clamp (after every position update) remains as the last resort: a particle centre beyond the wall
// (or inside a sphere) is put back on it and loses its outward velocity. Every catch is counted in
// _ClampHits[0], which the diagnostics report; it stays at zero in normal runs.
// Container = box with centre c, rotation R, size S, linear velocity V and angular velocity w (world).
// A particle's container-local position is q = R^T (x - c).

// The container's transforms, extents and motion, the spacing, the wall friction and the obstacle count are in
// FluidConstants.hlsl.

struct Obstacle
{
    float3 center;   // o, m
    float radius;    // R, m
    float3 velocity; // u, m/s
    float padding;
};

StructuredBuffer<Obstacle> _Obstacles; // the first _ObstacleCount are live

float3 ContainerLocal(float3 x)
{
    return mul(_WorldToContainer, float4(x, 1.0)).xyz;
}

float3 ContainerDirectionToWorld(float3 local)
{
    return mul((float3x3)_ContainerToWorld, local);
}

float3 ContainerDirectionToLocal(float3 world)
{
    return mul((float3x3)_WorldToContainer, world);
}

float3 ContainerWallVelocity(float3 x)
{
    return _ContainerVelocity + cross(_ContainerAngularVelocity, x - _ContainerCenter);
}

// A rest-frame boundary particle placed in the world with its owner's current pose and velocity.
BoundaryParticle PlaceBoundaryParticle(BoundaryParticle rest)
{
    BoundaryParticle placed = rest;
    if (rest.owner == BOUNDARY_OWNER_CONTAINER)
    {
        placed.position = mul(_ContainerToWorld, float4(rest.position, 1.0)).xyz;
        placed.velocity = ContainerWallVelocity(placed.position);
    }
    else
    {
        Obstacle sphere = _Obstacles[min(rest.owner, max(_ObstacleCount, 1u) - 1u)];
        placed.position = sphere.center + rest.position;
        placed.velocity = sphere.velocity;
    }
    return placed;
}

// The wall's outward normal at a placed boundary particle (from the fluid into the wall): the faces it lies
// beyond for the container (edges and corners get the diagonal), towards the centre for a sphere. q is the
// particle's place in its owner's frame, its rest position: the same point as ContainerLocal(wall.position)
// without the round trip through the world. (Mesa 22.3's lavapipe, which CI runs, also rebuilt the whole Forces
// kernel at every dispatch while it read _WorldToContainer here, and kept every copy: Headless/SphFluid.Vulkan/README.md.)
float3 WallNormal(BoundaryParticle wall, float3 q)
{
    if (wall.owner == BOUNDARY_OWNER_CONTAINER)
    {
        float3 beyond = max(abs(q) - _ContainerHalfSize, 0.0) * sign(q);
        float length2 = dot(beyond, beyond);
        return length2 > 0.0 ? ContainerDirectionToWorld(beyond * rsqrt(length2)) : float3(0.0, 0.0, 0.0);
    }
    float3 inward = _Obstacles[min(wall.owner, max(_ObstacleCount, 1u) - 1u)].center - wall.position;
    float length2 = dot(inward, inward);
    return length2 > 0.0 ? inward * rsqrt(length2) : float3(0.0, 0.0, 0.0);
}

// Whether wall particle `other` counts in wall particle `wall`'s wall sum (DFSPH's wall constraint, Passes/Walls.hlsl):
// the container's lattice does, except inside `wall`'s own sphere, whose solid counts at rest from the sampling
// (BoundarySampling.OwnNumberDensities). Spheres' shells do not: weighed up for the fluid outside them
// (BoundarySampling.ConvexWeightFactor), they over-count their solid at any other wall particle, whose constraint then asks
// for a density no motion of the fluid can give: with every other wall summed, the pool of SunkSphereTests (a sphere sunk
// a third of its radius into the floor) gained 8.8 J and reached 15.6 m/s with 23 clamp hits in its first second. A wall
// particle beside a sphere reads less solid than there is, which lets the fluid no closer: the fluid's own constraint
// counts every wall.
bool CountsInWallSum(BoundaryParticle wall, BoundaryParticle other)
{
    if (other.owner != BOUNDARY_OWNER_CONTAINER)
        return false;
    if (wall.owner == BOUNDARY_OWNER_CONTAINER)
        return true;
    Obstacle sphere = _Obstacles[min(wall.owner, max(_ObstacleCount, 1u) - 1u)];
    float3 d = other.position - sphere.center;
    return dot(d, d) >= sphere.radius * sphere.radius;
}

// A particle the summation density sees clearly short of neighbours (a free surface, a splash): more than 3 %
// below its rest density, where the equation of state gives it no pressure to meet the wall's with.
bool UnderDense(float density, float restDensity)
{
    return density < 0.97 * restDensity;
}

// The part of a fluid particle's velocity relative to the wall that points into it (0 when moving away).
float3 IntoWallVelocity(float3 relativeVelocity, float3 normal)
{
    return max(dot(relativeVelocity, normal), 0.0) * normal;
}

// The velocity of a particle below rest density after its wall contact: the part along G_w (wallGradientSum) that
// compresses its wall side, v . G_w - sum_b omega_ib v_b . gradW_ib (wallVelocityRate: the walls' own motion), removed.
float3 WallContactVelocity(float3 velocity, float3 wallGradientSum, float wallVelocityRate)
{
    float rate = dot(velocity, wallGradientSum) - wallVelocityRate;
    float g2 = dot(wallGradientSum, wallGradientSum);
    return rate > 0.0 && g2 > 1e-20 ? velocity - (rate / g2) * wallGradientSum : velocity;
}

// One fluid neighbour's share of a wall particle's pressure: (p_f + rho_f g . (x_b - x_f)) W, and W.
float2 WallPressureTerm(float pressureF, float densityF, float3 gravity, float3 fluidToWall, float weight)
{
    return float2((pressureF + densityF * dot(gravity, fluidToWall)) * weight, weight);
}

float WallPressureOf(float2 sums)
{
    return sums.y > 0.0 ? max(0.0, sums.x / sums.y) : 0.0;
}

// omega_ib: wall particle b's volume at the rest number density of fluid particle i's phase (above).
float WallWeight(BoundaryParticle wall, PhaseProperties phase)
{
    return wall.weight * phase.wallWeightScale;
}

// Pressure force on fluid particle i from boundary particle b (divide by m_i).
float3 BoundaryPressureForcePair(float pressureI, float boundaryPressure, float numberDensityI, float weight, float3 gradient)
{
    return -(weight * (pressureI + boundaryPressure) / (numberDensityI * numberDensityI)) * gradient;
}

// How far x lies inside the walls: its distance to the nearest of the container's faces and, with obstacles, of the
// spheres' surfaces (m; negative beyond one).
float WallGap(float3 x)
{
    float3 faces = _ContainerHalfSize - abs(ContainerLocal(x));
    float gap = min(faces.x, min(faces.y, faces.z));
#if OBSTACLES
    for (uint o = 0u; o < _ObstacleCount; o++)
        gap = min(gap, length(x - _Obstacles[o].center) - _Obstacles[o].radius);
#endif
    return gap;
}

// Puts x back inside the container and removes the outward wall-relative normal velocity; true if it did.
bool ContainerClamp(inout float3 x, inout float3 v)
{
    float3 q = ContainerLocal(x);
    float3 clamped = clamp(q, -_ContainerClampExtent, _ContainerClampExtent);
    if (all(clamped == q))
        return false;
    float3 xClamped = mul(_ContainerToWorld, float4(clamped, 1.0)).xyz;
    float3 wall = ContainerWallVelocity(xClamped);
    float3 relative = ContainerDirectionToLocal(v - wall);
    [unroll]
    for (int axis = 0; axis < 3; axis++)
    {
        if (clamped[axis] != q[axis])
        {
            float outward = q[axis] > 0.0 ? 1.0 : -1.0;
            if (relative[axis] * outward > 0.0)
                relative[axis] = 0.0;
        }
    }
    x = xClamped;
    v = wall + ContainerDirectionToWorld(relative);
    return true;
}

float3 ObstacleNormal(float3 d, float distance)
{
    return distance > 0.0 ? d / distance : float3(0.0, 1.0, 0.0);
}

// Puts x back outside every sphere and removes the inward sphere-relative normal velocity; true if it did.
bool ObstacleClamp(inout float3 x, inout float3 v)
{
    bool caught = false;
    for (uint o = 0u; o < _ObstacleCount; o++)
    {
        Obstacle sphere = _Obstacles[o];
        float3 d = x - sphere.center;
        float distance = length(d);
        float surface = sphere.radius + 0.01 * _ParticleSpacing;
        if (distance < surface)
        {
            float3 n = ObstacleNormal(d, distance);
            x = sphere.center + n * surface;
            float inward = dot(v - sphere.velocity, n);
            if (inward < 0.0)
                v -= inward * n;
            caught = true;
        }
    }
    return caught;
}

#endif
