#version 460
#extension GL_GOOGLE_include_directive : require
// How many of the faces asked for this frame the tracer takes, and its dispatch:
// every face never traced, at the full rays when the budget covers them all, else
// at the coarse; then, within what the budget has left, the faces partly traced.
#include "shared/face_trace.h"

layout(local_size_x = 1) in;
layout(push_constant) uniform Push { FaceTraceConstants c; };
layout(set = 0, binding = 0, std430) buffer Header { uint header[]; };

void main() {
    uint texels = c.texelsPerSide * c.texelsPerSide;
    uint capacity = header[GROTTO_FACE_CAPACITY];
    uint empty = min(header[GROTTO_FACE_QUEUE_EMPTY], capacity);
    uint partial = min(header[GROTTO_FACE_QUEUE_PARTIAL], capacity);
    uint full = texels * (c.rays + c.sunRays), coarse = texels * (c.coarseRays + c.coarseSunRays);
    // In 64 bits' worth of float: a budget of billions of rays must not wrap.
    bool emptyFull = float(empty) * float(full) <= float(c.budget);
    float left = max(float(c.budget) - float(empty) * float(emptyFull ? full : coarse), 0.0);
    uint taken = uint(min(float(partial), floor(left / float(full))));
    header[GROTTO_FACE_ASKED] = header[GROTTO_FACE_QUEUE_EMPTY] + header[GROTTO_FACE_QUEUE_PARTIAL];
    header[GROTTO_FACE_TRACED_EMPTY] = empty;
    header[GROTTO_FACE_TRACED_PARTIAL] = taken;
    header[GROTTO_FACE_EMPTY_FULL] = emptyFull ? 1u : 0u;
    header[GROTTO_FACE_DISPATCH] = ((empty + taken) * texels + GROTTO_FACE_TRACE_GROUP - 1u) / GROTTO_FACE_TRACE_GROUP;
    header[GROTTO_FACE_DISPATCH + 1u] = 1u;
    header[GROTTO_FACE_DISPATCH + 2u] = 1u;
}
