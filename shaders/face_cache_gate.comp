#version 460
#extension GL_GOOGLE_include_directive : require
// The request pass's dispatch: over the whole frame while any face has not
// converged, none once all have (a bake loaded, nothing edited since). And the
// backlog's (shared/face_trace.h): after a frame that found nothing in view to
// trace, and whose composite asked for nothing, its next window of faces, as
// many as its share of the budget traces at the full rays.
#include "shared/face_trace.h"

layout(local_size_x = 1) in;
layout(push_constant) uniform Push { FaceTraceConstants c; };
layout(set = 0, binding = 0, std430) buffer Header { uint header[]; };

void main() {
    bool any = header[GROTTO_FACE_UNCONVERGED] > 0u;
    header[GROTTO_FACE_REQUEST_DISPATCH] = any ? (c.width + 15u) / 16u : 0u;
    header[GROTTO_FACE_REQUEST_DISPATCH + 1u] = (c.height + 15u) / 16u;
    header[GROTTO_FACE_REQUEST_DISPATCH + 2u] = 1u;

    uint backlog = header[GROTTO_FACE_BACKLOG];
    bool idle = header[GROTTO_FACE_FRAMES] > 0u &&
                header[GROTTO_FACE_ASKED] + header[GROTTO_FACE_QUEUE_EMPTY] + header[GROTTO_FACE_QUEUE_PARTIAL] == 0u;
    uint perFace = c.texelsPerSide * c.texelsPerSide * (c.rays + c.sunRays);
    uint share = c.budget / GROTTO_FACE_BACKLOG_SHARE;
    uint window = any && idle && backlog > 0u ? min(min(share / max(perFace, 1u), header[GROTTO_FACE_CAPACITY]), backlog) : 0u;
    uint start = header[GROTTO_FACE_BACKLOG_NEXT];
    header[GROTTO_FACE_BACKLOG_START] = start;
    header[GROTTO_FACE_BACKLOG_TAKEN] = window;
    header[GROTTO_FACE_BACKLOG_NEXT] = backlog > 0u ? (start + window) % backlog : 0u;
    header[GROTTO_FACE_BACKLOG_ADDED] = 0u;
    header[GROTTO_FACE_BACKLOG_DISPATCH] = (window + 63u) / 64u;
    header[GROTTO_FACE_BACKLOG_DISPATCH + 1u] = 1u;
    header[GROTTO_FACE_BACKLOG_DISPATCH + 2u] = 1u;
    header[GROTTO_FACE_FRAMES] = min(header[GROTTO_FACE_FRAMES] + 1u, 2u);
}
