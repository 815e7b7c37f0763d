#version 460
#extension GL_GOOGLE_include_directive : require
// Exact sun rays where a shadow edge crosses the face cache's texels: the
// composite lists every pixel whose texels an edge crosses (a point sun: not all
// lit nor all shadowed, since a texel's rays start all over its square; a disc:
// disagreeing by over a quarter, a penumbra narrower than the texels are apart), with the sun visibility it lit the pixel with and the sun's light
// there at full visibility. Here each listed pixel traces from its exact surface
// point, one ray toward a point sun or 16 over the disc, and its colour takes the
// difference. So a shadow's edge is as sharp as the voxels and the sun make it,
// at the cost of rays for the few pixels on an edge only.
#include "shared/face_trace.h"
#include "shared/objects.h"
#include "shared/quad.h"

layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform sampler2D depthBuffer;  // full-res D32, reverse-Z
layout(set = 0, binding = 1) uniform usampler2D surfaceTex;
layout(set = 0, binding = 2, rgba32f) uniform image2D colorImage;
layout(set = 0, binding = 3, std430) readonly buffer Edges {
    uint edgeHeader[GROTTO_EDGE_HEADER_WORDS];
    uvec4 edges[];  // two per pixel: (x | y << 16, visibility used), (light at full visibility)
};
#define GROTTO_TRACE_BINDING 4
#include "trace.glsl"
#include "texel_rays.glsl"

// The rays over a sun's disc, as the face cache's texels take them.
const uint kDiscRays = 16u;

// The part of the sun's disc seen from `start` on face `face`: the same 16
// directions for every point of a voxel face (its R2 sequence shifted by a hash
// of the face), so a still surface's value stays from frame to frame. Most listed
// pixels lie beside a penumbra, not in it: when the first 4 rays, spread over the
// disc, all agree, the other 12 are not traced.
float discVisibility(VoxelRayStart start, uint face) {
    vec3 sun = trace.sunDirection.xyz, n = faceAxisNormal(face), s1, s2;
    texelTangents(sun, s1, s2);
    uvec2 h = texelSeed(start.voxel, face, 0u, 0u);
    vec2 shift = vec2(unitInterval(h), unitInterval(splitmix64(h)));
    uint open = 0u;
    for (uint r = 0u; r < kDiscRays; ++r) {
        vec3 cone = coneDirection(r2(r, shift), trace.sunCosRadius);
        vec3 d = s1 * cone.x + s2 * cone.y + sun * cone.z;
        if (dot(d, n) > 0.0 && traceWorldHit(start, d, kVoxelRayNever, false).t < 0.0) ++open;
        if (r == 3u && (open == 0u || open == 4u)) return float(open) / 4.0;
    }
    return float(open) / float(kDiscRays);
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= min(edgeHeader[GROTTO_EDGE_COUNT], edgeHeader[GROTTO_EDGE_CAPACITY])) return;
    uvec4 e = edges[2u * i];
    ivec2 q = ivec2(e.x & 0xFFFFu, e.x >> 16u);
    uint face = surfaceFace(texelFetch(surfaceTex, q, 0).r);
    VoxelRayStart start = traceStart(traceViewPosition(q, texelFetch(depthBuffer, q, 0).r), face, faceAxisNormal(face));
    float lit = trace.sunCosRadius < 1.0 ? discVisibility(start, face)
                                         : traceWorldHit(start, trace.sunDirection.xyz, kVoxelRayNever, false).t >= 0.0 ? 0.0 : 1.0;
    vec3 light = uintBitsToFloat(edges[2u * i + 1u].xyz);
    vec4 c = imageLoad(colorImage, q);
    imageStore(colorImage, q, vec4(c.rgb + (lit - uintBitsToFloat(e.y)) * light, c.a));
}
