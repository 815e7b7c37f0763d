#version 460
#extension GL_GOOGLE_include_directive : require
// A game's normals image: the world-space normal of the face each pixel sees, from
// the G-buffer's surface id; an object's face from the frame's normal table (its
// faces turned by its pose). w: 1 on a surface, 0 on the sky (normal 0).
#include "shared/objects.h"
#include "shared/quad.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = 0) uniform usampler2D surfaceTex;
layout(set = 0, binding = 1, std140) uniform Objects { ObjectUniforms objects; };
layout(set = 0, binding = 2, rgba16f) uniform writeonly image2D normalsImage;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(normalsImage)))) return;
    uint surface = texelFetch(surfaceTex, p, 0).r;
    vec4 n = vec4(0.0);
    if (surface != 0u) {
        uint face = surfaceFace(surface);
        n = vec4(0.0, 0.0, 0.0, 1.0);
        n[faceAxis(face)] = facePositive(face) ? 1.0 : -1.0;
        if (surfaceObject(surface) != 0u) n.xyz = objects.worldNormals[surfaceKey(surface) - 1u].xyz;
    }
    imageStore(normalsImage, p, n);
}
