#version 460
#extension GL_GOOGLE_include_directive : require
// The shadow edge pass's indirect dispatch: a group per 64 pixels listed.
#include "shared/face_trace.h"

layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) buffer Edges { uint edgeHeader[GROTTO_EDGE_HEADER_WORDS]; };

void main() {
    uint n = min(edgeHeader[GROTTO_EDGE_COUNT], edgeHeader[GROTTO_EDGE_CAPACITY]);
    edgeHeader[GROTTO_EDGE_DISPATCH] = (n + 63u) / 64u;
    edgeHeader[GROTTO_EDGE_DISPATCH + 1u] = 1u;
    edgeHeader[GROTTO_EDGE_DISPATCH + 2u] = 1u;
}
