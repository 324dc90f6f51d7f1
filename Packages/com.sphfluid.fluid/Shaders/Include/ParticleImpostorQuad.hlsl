#ifndef SPHFLUID_PARTICLE_IMPOSTOR_QUAD_INCLUDED
#define SPHFLUID_PARTICLE_IMPOSTOR_QUAD_INCLUDED

// Camera-facing quad that carries one sphere impostor (vertex stage).
//
// D3D11 rasterises points at one pixel, so each particle becomes two triangles (6 vertices) expanded
// here from SV_VertexID, the particle being SV_InstanceID. The quad passes through the sphere centre c
// and faces the eye; it must cover the sphere's silhouette, not just a disc of radius R:
//   perspective:  the tangent cone from an eye at distance d meets the plane through c at
//                 half size  a = R d / sqrt(d^2 - R^2)            (similar triangles, d > R)
//   orthographic: a = R.
// An eye inside the sphere (d <= R) collapses the quad to a point: nothing is drawn for that particle.
// The fragment stage ray-casts the true sphere through each covered pixel (ParticleImpostorSphere.hlsl).
// After: Gumhold 2003, "Splatting illuminated ellipsoids with depth correction" (VMV); Sigg, Weyrich,
// Botsch & Gross 2006, "GPU-based ray-casting of quadratic surfaces" (SPBG) - bounding quads of quadrics.

// Corner of the quad for a vertex of the 6-vertex triangle list: corners 0 1 2 and 0 2 3 of
// (-1,-1) (1,-1) (1,1) (-1,1). Culling is off, so the winding does not matter.
float2 ImpostorQuadCorner(uint vertexId)
{
    uint v = vertexId % 6u;
    uint corner = v < 3u ? v : (v == 3u ? 0u : v - 2u);
    float x = (corner == 1u || corner == 2u) ? 1.0 : -1.0;
    float y = corner >= 2u ? 1.0 : -1.0;
    return float2(x, y);
}

// Half size of the quad (m) that covers the silhouette of a sphere of radius R seen from distance d.
float ImpostorHalfSize(float radius, float eyeDistance, float orthographic)
{
    if (orthographic > 0.5) return radius;
    float d2 = eyeDistance * eyeDistance;
    float r2 = radius * radius;
    // 1e-4 R^2 keeps the square root away from zero for an eye grazing the sphere.
    return d2 > r2 * 1.0001 ? radius * eyeDistance / sqrt(d2 - r2) : 0.0;
}

// World position of one quad corner. towardEye: unit vector from the centre to the eye (perspective)
// or minus the camera forward (orthographic); cameraUp/cameraRight: the camera's world axes, used to
// keep the quad upright and as the fallback when towardEye is parallel to cameraUp.
float3 ImpostorQuadVertex(float3 centre, float halfSize, float2 corner, float3 towardEye, float3 cameraUp, float3 cameraRight)
{
    float3 right = cross(cameraUp, towardEye);
    float rightLength = length(right);
    right = rightLength > 1e-5 ? right / rightLength : cameraRight;
    float3 up = cross(towardEye, right);
    return centre + (corner.x * right + corner.y * up) * halfSize;
}

#endif
