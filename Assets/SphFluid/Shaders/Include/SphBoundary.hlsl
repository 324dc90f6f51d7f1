#ifndef SPHFLUID_SPH_BOUNDARY_INCLUDED
#define SPHFLUID_SPH_BOUNDARY_INCLUDED

// Container and sphere-obstacle boundaries: a penalty force plus a final clamp.
// Container = box with centre c, rotation R, size S, moving with linear velocity V and angular
// velocity w (world). A particle's container-local position is q = R^T (x - c).
// Penalty (spring-damper, the dissertation's F = -k (r_p - r_b) plus damping; cf. Monaghan 1994's
// repulsive boundaries and Becker & Teschner 2007, sec. 5): on every axis where |q_a| > H_a,
// H = S/2 - s/2 (half a spacing off the wall, where a spawned lattice particle sits), with outward
// normal n and penetration d = |q_a| - H_a,
//   a += -kb d n - cb max(0, (v - v_wall) . n) n        (damping only while moving outward)
// kb [1/s^2], cb [1/s], v_wall(x) = V + w x (x - c): the walls push the fluid with their own velocity.
// Clamp (after every position update): q_a is put back into [-Hc_a, Hc_a] and the outward normal
// component of the velocity relative to the wall is removed, so no particle can ever leave, however
// stiff the flow or fast the container.
// DEVIATION from the team notes (which clamp at H itself): the clamp sits at Hc = S/2 - s/100, just
// inside the wall, not at H. Clamping at H would put every particle that enters the penalty zone back
// on its edge before the next force pass, so the penalty force would never act (only the hard clamp
// would, stacking a layer of particles exactly at H). With the clamp at the wall the spring-damper
// does the work and the clamp is the last-resort guarantee it is meant to be.
// Sphere obstacle (centre o, radius R, velocity u): the same with the penalty surface at R + s/2, the
// clamp surface at R + s/100 and the normal pointing out of the sphere.

float4x4 _WorldToContainer;        // q = mul(_WorldToContainer, float4(x, 1)).xyz = R^T (x - c)
float4x4 _ContainerToWorld;        // x = mul(_ContainerToWorld, float4(q, 1)).xyz = R q + c
float3 _ContainerCenter;           // c, m
float3 _ContainerHalfExtent;       // H = S/2 - s/2, m: where the penalty begins
float3 _ContainerClampExtent;      // Hc = S/2 - s/100, m: the clamp (no particle centre beyond)
float3 _ContainerVelocity;         // V, m/s
float3 _ContainerAngularVelocity;  // w, rad/s
float _BoundaryStiffness;          // kb, 1/s^2
float _BoundaryDamping;            // cb, 1/s
float _ParticleSpacing;            // s, m

struct SphereObstacle
{
    float3 center;   // o, m
    float radius;    // R, m
    float3 velocity; // u, m/s
    float padding;
};

StructuredBuffer<SphereObstacle> _Obstacles;
uint _ObstacleCount;

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

float3 ContainerPenaltyAcceleration(float3 x, float3 v)
{
    float3 q = ContainerLocal(x);
    float3 relative = ContainerDirectionToLocal(v - ContainerWallVelocity(x));
    float3 excess = abs(q) - _ContainerHalfExtent;
    float3 a = float3(0.0, 0.0, 0.0);
    [unroll]
    for (int axis = 0; axis < 3; axis++)
    {
        if (excess[axis] > 0.0)
        {
            float outward = q[axis] >= 0.0 ? 1.0 : -1.0;
            float approach = max(0.0, relative[axis] * outward);
            a[axis] = -outward * (_BoundaryStiffness * excess[axis] + _BoundaryDamping * approach);
        }
    }
    return ContainerDirectionToWorld(a);
}

// Puts x back inside the container and removes the outward wall-relative normal velocity.
void ContainerClamp(inout float3 x, inout float3 v)
{
    float3 q = ContainerLocal(x);
    float3 clamped = clamp(q, -_ContainerClampExtent, _ContainerClampExtent);
    if (all(clamped == q))
        return;
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
}

float3 ObstacleNormal(float3 d, float distance)
{
    return distance > 0.0 ? d / distance : float3(0.0, 1.0, 0.0);
}

float3 ObstaclePenaltyAcceleration(float3 x, float3 v)
{
    float3 a = float3(0.0, 0.0, 0.0);
    for (uint o = 0u; o < _ObstacleCount; o++)
    {
        SphereObstacle sphere = _Obstacles[o];
        float3 d = x - sphere.center;
        float distance = length(d);
        float surface = sphere.radius + 0.5 * _ParticleSpacing;
        if (distance < surface)
        {
            float3 n = ObstacleNormal(d, distance);
            float approach = max(0.0, -dot(v - sphere.velocity, n));
            a += n * (_BoundaryStiffness * (surface - distance) + _BoundaryDamping * approach);
        }
    }
    return a;
}

void ObstacleClamp(inout float3 x, inout float3 v)
{
    for (uint o = 0u; o < _ObstacleCount; o++)
    {
        SphereObstacle sphere = _Obstacles[o];
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
        }
    }
}

#endif
