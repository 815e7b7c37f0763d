#version 460
#extension GL_GOOGLE_include_directive : require
// How many of the faces asked for this frame the tracer takes, and its dispatch:
// every face never traced, at the full rays when the budget covers them all, else
// at the coarse; then, within what the budget has left, the faces partly traced.
// A frame that could not afford its new faces' full rays (an edit, a cold start)
// traces them alone: their first look is drawn at once, and the refining waits a
// frame instead of making that first frame as long as the whole budget.
#include "shared/face_trace.h"

layout(local_size_x = 1) in;
layout(push_constant) uniform Push { FaceTraceConstants c; };
layout(set = 0, binding = 0, std430) buffer Header { uint header[]; };

void main() {
    uint texels = c.texelsPerSide * c.texelsPerSide;
    uint capacity = header[GROTTO_FACE_CAPACITY];
    uint empty = min(header[GROTTO_FACE_QUEUE_EMPTY], capacity);
    uint partial = min(header[GROTTO_FACE_QUEUE_PARTIAL], capacity);
    uint full = texels * (c.rays + c.sunRays);
    // In 64 bits' worth of float: a budget of billions of rays must not wrap.
    bool emptyFull = float(empty) * float(full) <= float(c.budget);
    float left = emptyFull ? max(float(c.budget) - float(empty) * float(full), 0.0) : 0.0;
    uint taken = uint(min(float(partial), floor(left / float(full))));
    header[GROTTO_FACE_ASKED] = header[GROTTO_FACE_QUEUE_EMPTY] + header[GROTTO_FACE_QUEUE_PARTIAL] - header[GROTTO_FACE_BACKLOG_ADDED];
    header[GROTTO_FACE_TRACED_EMPTY] = empty;
    header[GROTTO_FACE_TRACED_PARTIAL] = taken;
    header[GROTTO_FACE_EMPTY_FULL] = emptyFull ? 1u : 0u;
    // The coarse faces an invocation each (face_cache_trace.comp), the rest one a texel.
    uint items = (emptyFull ? empty * texels : empty) + taken * texels;
    header[GROTTO_FACE_DISPATCH] = (items + GROTTO_FACE_TRACE_GROUP - 1u) / GROTTO_FACE_TRACE_GROUP;
    header[GROTTO_FACE_DISPATCH + 1u] = 1u;
    header[GROTTO_FACE_DISPATCH + 2u] = 1u;
}
