#version 460
#extension GL_GOOGLE_include_directive : require
// The faces in view whose texels have not converged, listed for the face cache's
// tracer (shared/face_trace.h): every full-res pixel on a world surface asks for
// the face its point lies on, once each per frame, level 0 in the first list and
// levels 1 and 2 in the second.
#include "shared/face_trace.h"
#include "shared/frame.h"
#include "shared/objects.h"
#include "shared/quad.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(push_constant) uniform Push { FaceTraceConstants c; };
layout(set = 0, binding = 0, std140) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1) uniform sampler2D depthBuffer;
layout(set = 0, binding = 2) uniform usampler2D surfaceTex;
layout(set = 0, binding = 3, std430) readonly buffer Levels { uint levels[]; };
layout(set = 0, binding = 4, std430) buffer Requested { uint requested[]; };  // a bit per face, cleared each frame
layout(set = 0, binding = 5, std430) writeonly buffer Queue { uvec4 queue[]; };
layout(set = 0, binding = 6, std430) buffer Header { uint header[]; };
uint faceCacheHashMask() { return frame.faceCache.x; }
uint faceCacheK() { return frame.faceCache.y; }
#define GROTTO_FACE_CACHE_BINDING 7
#include "face_cache.glsl"
#include "face_cache_surface.glsl"

void request(int face, ivec3 cell, uint dir) {
    uint f = uint(face);
    uint level = (levels[f >> 4u] >> ((f & 15u) * 2u)) & 3u;
    if (level == GROTTO_FACE_LEVEL_CONVERGED) return;
    uint bit = 1u << (f & 31u);
    if ((requested[f >> 5u] & bit) != 0u || (atomicOr(requested[f >> 5u], bit) & bit) != 0u) return;
    uint list = level == 0u ? GROTTO_FACE_QUEUE_EMPTY : GROTTO_FACE_QUEUE_PARTIAL;
    uint slot = atomicAdd(header[list], 1u);
    if (slot < c.capacity) queue[list * c.capacity + slot] = uvec4(uvec3(cell), dir | (f << 3u));
}

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(q), frame.size))) return;
    uint surface = texelFetch(surfaceTex, q, 0).r;
    if (surface == 0u || surfaceObject(surface) != 0u) return;
    // The face the pixel's point lies on: the texels of its neighbours across an
    // edge that it reads too are in view beside it, and asked for there.
    uint dir = surfaceFace(surface);
    vec3 p = cachedPointAt(q, dir);
    uint axis = faceAxis(dir);
    ivec3 cell = ivec3(floor(p)) + frame.cameraCell.xyz;
    cell[axis] = int(round(p[axis])) + frame.cameraCell[axis] - (facePositive(dir) ? 1 : 0);
    int face = faceCacheFace(cell, dir);
    if (face >= 0) request(face, cell, dir);
}
