#version 460
#extension GL_GOOGLE_include_directive : require
// The request pass's dispatch: over the whole frame while any face has not
// converged, none once all have (a bake loaded, nothing edited since).
#include "shared/face_trace.h"

layout(local_size_x = 1) in;
layout(push_constant) uniform Push { FaceTraceConstants c; };
layout(set = 0, binding = 0, std430) buffer Header { uint header[]; };

void main() {
    bool any = header[GROTTO_FACE_UNCONVERGED] > 0u;
    header[GROTTO_FACE_REQUEST_DISPATCH] = any ? (c.width + 15u) / 16u : 0u;
    header[GROTTO_FACE_REQUEST_DISPATCH + 1u] = (c.height + 15u) / 16u;
    header[GROTTO_FACE_REQUEST_DISPATCH + 2u] = 1u;
}
