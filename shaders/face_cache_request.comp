#version 460
#extension GL_GOOGLE_include_directive : require
// The faces in view whose texels have not converged, listed for the face cache's
// tracer (shared/face_trace.h): every full-res pixel on a world surface asks for
// the face its point lies on (face_cache_requests.glsl), before the frame's
// trace, so a face new to the view is traced in the frame it appears.
#include "shared/face_trace.h"
#include "shared/frame.h"
#include "shared/objects.h"
#include "shared/quad.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = 0, std140) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1) uniform sampler2D depthBuffer;
layout(set = 0, binding = 2) uniform usampler2D surfaceTex;
uint faceCacheTable() { return frame.faceCache.x; }
uint faceCacheK() { return frame.faceCache.y; }
#define GROTTO_FACE_CACHE_BINDING 3
#include "face_cache.glsl"
#define GROTTO_FACE_REQUEST_BINDING 6
#include "face_cache_requests.glsl"
#include "face_cache_surface.glsl"

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(q), frame.size))) return;
    uint surface = texelFetch(surfaceTex, q, 0).r;
    if (surface == 0u || surfaceObject(surface) != 0u) return;
    // The face the pixel's point lies on; the composite asks for the neighbours'
    // texels it reads across the face's edges, for the next frame.
    uint dir = surfaceFace(surface);
    vec3 p = cachedPointAt(q, dir);
    uint axis = faceAxis(dir);
    ivec3 cell = ivec3(floor(p)) + frame.cameraCell.xyz;
    cell[axis] = int(round(p[axis])) + frame.cameraCell[axis] - (facePositive(dir) ? 1 : 0);
    int face = faceCacheFace(cell, dir);
    if (face >= 0) requestFace(face, cell, dir);
}
