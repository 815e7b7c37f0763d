#version 460
#extension GL_GOOGLE_include_directive : require
// For tests: the face cache read (shared/face_cache.h's faceCacheAt) at a list of
// points, so it can be compared point by point with the CPU's FaceCacheLookup.

layout(local_size_x = 64) in;
layout(push_constant) uniform Query { uint count, table, k; } query;
struct CacheQuery {
    vec4 point;    // xyz: voxel index units relative to `origin`
    ivec4 origin;  // xyz: whole voxels taken out of the point; w: the face's direction
};
layout(set = 0, binding = 0, std430) readonly buffer Queries { CacheQuery queries[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Results { vec4 results[]; };  // AO, sun, horizon, zenith; then found

uint faceCacheTable() { return query.table; }
uint faceCacheK() { return query.k; }
#define GROTTO_FACE_CACHE_BINDING 2
#include "face_cache.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= query.count) return;
    CacheQuery q = queries[i];
    bool found;
    results[2u * i] = faceCacheAt(q.point.xyz, q.origin.xyz, uint(q.origin.w), found);
    results[2u * i + 1u] = vec4(found ? 1.0 : 0.0);
}
