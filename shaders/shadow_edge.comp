#version 460
#extension GL_GOOGLE_include_directive : require
// Exact sun rays where a shadow edge crosses the face cache's texels: the
// composite lists every pixel whose texels disagree on a point sun (some lit,
// some not), with the sun visibility it lit the pixel with and the sun's light
// there at full visibility; here each listed pixel traces its one ray toward the
// sun from its exact surface point and its colour takes the difference. So a
// hard shadow's edge is as sharp as the voxels make it, at the cost of a ray for
// the few pixels on an edge only.
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

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= min(edgeHeader[GROTTO_EDGE_COUNT], edgeHeader[GROTTO_EDGE_CAPACITY])) return;
    uvec4 e = edges[2u * i];
    ivec2 q = ivec2(e.x & 0xFFFFu, e.x >> 16u);
    uint face = surfaceFace(texelFetch(surfaceTex, q, 0).r);
    VoxelRayStart start = traceStart(traceViewPosition(q, texelFetch(depthBuffer, q, 0).r), face, faceAxisNormal(face));
    float lit = traceWorldHit(start, trace.sunDirection.xyz, kVoxelRayNever, false).t >= 0.0 ? 0.0 : 1.0;
    vec3 light = uintBitsToFloat(edges[2u * i + 1u].xyz);
    vec4 c = imageLoad(colorImage, q);
    imageStore(colorImage, q, vec4(c.rgb + (lit - uintBitsToFloat(e.y)) * light, c.a));
}
