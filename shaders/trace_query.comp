#version 460
#extension GL_GOOGLE_include_directive : require
// For tests: the exact traversal the shadow pass runs (trace.glsl's traceHit) for a
// list of rays given by their starts, so they can compare it ray by ray with the
// CPU's World::raycast. A ray with a face axis (voxel.w >= 0) starts as a ray from
// a face point does (voxelRayOpenStart); one with voxel.w = -2 asks instead how far
// it runs through solid voxels (voxelRayExit, VBAO's voxels thickness), into t.

layout(local_size_x = 64) in;
layout(push_constant) uniform Query { uint count; } query;
struct QueryRay {
    ivec4 voxel;     // xyz: the start voxel; w: the face's axis, or -1
    vec4 fraction;   // xyz: the start within it; w: the ray's length (voxels)
    vec4 direction;  // xyz: unit
};
layout(set = 0, binding = 0, std430) readonly buffer Rays { QueryRay rays[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Hits { vec4 hits[]; };  // voxel xyz and face, then t
#define GROTTO_TRACE_BINDING 2
#include "trace.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= query.count) return;
    QueryRay r = rays[i];
    VoxelRayStart s;
    s.voxel = r.voxel.xyz;
    s.fraction = r.fraction.xyz;
    if (r.voxel.w == -2) {
        hits[2u * i] = vec4(0.0);
        hits[2u * i + 1u] = vec4(voxelRayExit(s, r.direction.xyz, r.fraction.w), 0.0, 0.0, 0.0);
        return;
    }
    if (r.voxel.w >= 0) s = voxelRayOpenStart(s, r.voxel.w);
    VoxelRayHit h = traceHit(s, r.direction.xyz, r.fraction.w, false);
    hits[2u * i] = vec4(vec3(h.voxel), float(h.face));
    hits[2u * i + 1u] = vec4(h.t, 0.0, 0.0, 0.0);
}
