#ifndef SPHFLUID_PARTICLE_IMPOSTOR_SPHERE_INCLUDED
#define SPHFLUID_PARTICLE_IMPOSTOR_SPHERE_INCLUDED

// Ray-cast sphere impostor (fragment stage): the exact sphere behind each pixel of the quad.
//
// Ray x(t) = p + t D through the quad point p (on the plane through the centre c, so |p - c| is small
// and the quadratic keeps its precision far from the camera), unit direction D:
//   |p + t D - c|^2 = R^2  ->  t^2 + 2 b t + k = 0,  b = (p - c).D,  k = |p - c|^2 - R^2
//   discriminant  q = b^2 - k ;  q < 0: the ray misses (the pixel is outside the disc: discard)
//   front hit t0 = -b - sqrt(q), back hit t1 = -b + sqrt(q)
//   normal n = (x(t0) - c) / R,  thickness (chord through the liquid) L = t1 - t0 = 2 sqrt(q).
// The depth written is that of x(t0), so impostors intersect each other and the scene as spheres.
// After: Gumhold 2003, "Splatting illuminated ellipsoids with depth correction" (VMV); Sigg et al. 2006,
// "GPU-based ray-casting of quadratic surfaces" (SPBG); van der Laan, Green & Sainz 2009, "Screen space
// fluid rendering with curvature flow" (I3D) for the thickness used by the absorption.

struct ImpostorHit
{
    float3 position;  // front surface point, world, m
    float3 normal;    // unit outward normal, world
    float thickness;  // chord length through the sphere along the ray, m
    float covered;    // 1 when the ray meets the sphere, 0 when the pixel must be discarded
};

ImpostorHit ImpostorIntersect(float3 rayPoint, float3 rayDirection, float3 centre, float radius)
{
    float3 offset = rayPoint - centre;
    float b = dot(offset, rayDirection);
    float k = dot(offset, offset) - radius * radius;
    float q = b * b - k;
    float root = sqrt(max(q, 0.0));

    ImpostorHit hit;
    hit.position = rayPoint + rayDirection * (-b - root);
    hit.normal = (hit.position - centre) / max(radius, 1e-7);
    hit.thickness = 2.0 * root;
    hit.covered = q >= 0.0 ? 1.0 : 0.0;
    return hit;
}

// Depth-buffer value of a clip-space position. Clip z/w is the stored depth where clip space has
// z in [0, w] (D3D, Vulkan, Metal; reversed-Z there keeps this form with 1 at the near plane); OpenGL
// clip space has z in [-w, w] (near clip value -1) and stores 0.5 z/w + 0.5. Saturate keeps a hit in
// front of the near plane (eye grazing a particle) on the near plane instead of outside the range.
float ImpostorDeviceDepth(float4 positionCS, float nearClipValue)
{
    float ndcZ = positionCS.z / positionCS.w;
    return saturate(nearClipValue < 0.0 ? ndcZ * 0.5 + 0.5 : ndcZ);
}

#endif
