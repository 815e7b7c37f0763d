#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/quad.h"

layout(location = 0) flat in uint inFace;
layout(location = 1) flat in vec3 inAlbedo;
layout(location = 0) out vec4 outNormal;
layout(location = 1) out vec4 outAlbedo;

void main() {
    vec3 n = vec3(0.0);
    n[faceAxis(inFace)] = facePositive(inFace) ? 1.0 : -1.0;
    outNormal = vec4(n, 0.0);
    outAlbedo = vec4(inAlbedo, 1.0);
}
