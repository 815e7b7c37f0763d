#version 460
#extension GL_GOOGLE_include_directive : require
// The backlog's window this frame (face_cache_gate.comp set it): each face in it
// not converged nor asked for already is listed for the tracer, in view or not,
// and counted apart from those asked in view.
#include "shared/face_trace.h"

layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) readonly buffer Backlog { uvec4 backlog[]; };
#define GROTTO_FACE_REQUEST_BINDING 1
#include "face_cache_requests.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= faceHeader[GROTTO_FACE_BACKLOG_TAKEN]) return;
    uvec4 e = backlog[(faceHeader[GROTTO_FACE_BACKLOG_START] + i) % faceHeader[GROTTO_FACE_BACKLOG]];
    if (requestFace(int(e.w >> 3u), ivec3(e.xyz), e.w & 7u)) atomicAdd(faceHeader[GROTTO_FACE_BACKLOG_ADDED], 1u);
}
