#version 460
#extension GL_GOOGLE_include_directive : require
// Chunks drawn through a whole transform: objects, and, where objects move, the
// world's chunks too (so every pixel gets its motion). Voxel coordinates go to clip
// space this frame and the frame before through matrices built in double on the
// CPU, camera-relative. The draw's instance index is the object's (0 = the world).
// Built a second time with GROTTO_STILL (gbuffer_still.vert) for objects that do
// not move: no motion, so no clip positions for the fragment shader.
#include "shared/objects.h"
#include "shared/quad.h"

layout(push_constant) uniform Push { ObjectPush chunk; };

layout(location = 0) in uint inVertex;
layout(location = 0) flat out uint outSurface;
#ifndef GROTTO_STILL
layout(location = 1) out vec4 outClip;
layout(location = 2) out vec4 outPreviousClip;
#endif

void main() {
    vec4 p = vec4(vertexCoord(inVertex, 0u), vertexCoord(inVertex, 1u), vertexCoord(inVertex, 2u), 1.0);
    gl_Position = chunk.clip * p;
#ifndef GROTTO_STILL
    outClip = gl_Position;
    outPreviousClip = chunk.previousClip * p;
#endif
    outSurface = surfaceWithObject(packSurface(vertexFace(inVertex), vertexMaterial(inVertex)), uint(gl_InstanceIndex));
}
