#version 460
#extension GL_GOOGLE_include_directive : require
// Sun shadows at full resolution: one exact ray per pixel from its surface point
// toward the sun through the world's voxels (trace.glsl), until it leaves the
// world's bounds. Writes 1 where the sun reaches the point, 0 where a voxel blocks
// it or the face turns away from the sun; 1 for the sky.
#include "shared/objects.h"
#include "shared/quad.h"
#include "shared/trace.h"

layout(local_size_x = GROTTO_TRACE_GROUP, local_size_y = GROTTO_TRACE_GROUP) in;
layout(set = 0, binding = 0) uniform sampler2D depthBuffer;   // full-res D32, reverse-Z
layout(set = 0, binding = 1) uniform usampler2D surfaceTex;   // full-res surface ids
layout(set = 0, binding = 2, std140) uniform Objects { ObjectUniforms objects; };  // object faces' normals
layout(set = 0, binding = 3, r32f) uniform writeonly image2D shadowOut;
#define GROTTO_TRACE_BINDING 4
#include "trace.glsl"

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(shadowOut);
    if (any(greaterThanEqual(q, size))) return;
    uint surface = texelFetch(surfaceTex, q, 0).r;
    if (surface == 0u) {
        imageStore(shadowOut, q, vec4(1.0));
        return;
    }
    vec3 sun = trace.sunDirection.xyz;
    vec3 normal = objects.worldNormals[surfaceKey(surface) - 1u].xyz;
    bool world = surfaceObject(surface) == 0u;
    if (world) {  // an axis: exact
        uint face = surfaceFace(surface);
        normal = vec3(0.0);
        normal[faceAxis(face)] = facePositive(face) ? 1.0 : -1.0;
    }
    if (dot(normal, sun) <= 0.0) {
        imageStore(shadowOut, q, vec4(0.0));
        return;
    }
    float z = trace.depthAB.y / (texelFetch(depthBuffer, q, 0).r + trace.depthAB.x);
    vec2 m = (vec2(q) + 0.5) * trace.ndcToViewMul_Add.xy + trace.ndcToViewMul_Add.zw;
    TraceStart start = traceStart(vec3(m * z, -z), world ? surfaceFace(surface) : 6u, normal);
    float reach = traceBoundsExit(start, sun);
    float lit = reach > 0.0 && traceRay(start, sun, reach) >= 0.0 ? 0.0 : 1.0;
    imageStore(shadowOut, q, vec4(lit));
}
