// Asking the face cache's tracer for a face (shared/face_trace.h): the includer
// defines GROTTO_FACE_REQUEST_BINDING, where the levels, request bits, queue and
// header buffers sit, one after another (GpuFaceCache::withRequestBindings).
#define GROTTO_FACE_LEVELS_BINDING GROTTO_FACE_REQUEST_BINDING
#include "face_cache_levels.glsl"
layout(set = 0, binding = GROTTO_FACE_REQUEST_BINDING + 1, std430) buffer FaceRequested { uint faceRequested[]; };
layout(set = 0, binding = GROTTO_FACE_REQUEST_BINDING + 2, std430) writeonly buffer FaceQueue { uvec4 faceQueue[]; };
layout(set = 0, binding = GROTTO_FACE_REQUEST_BINDING + 3, std430) buffer FaceHeader { uint faceHeader[]; };

// Lists face `face` (of `cell`, looking `dir`) unless it has converged or is
// listed already: once each, level 0 in the first list, levels 1 and 2 in the
// second. True where this call listed it.
bool requestFace(int face, ivec3 cell, uint dir) {
    uint f = uint(face);
    uint level = faceLevel(face);
    if (level == GROTTO_FACE_LEVEL_CONVERGED) return false;
    uint bit = 1u << (f & 31u);
    if ((faceRequested[f >> 5u] & bit) != 0u || (atomicOr(faceRequested[f >> 5u], bit) & bit) != 0u) return false;
    uint list = level == 0u ? GROTTO_FACE_QUEUE_EMPTY : GROTTO_FACE_QUEUE_PARTIAL;
    uint capacity = faceHeader[GROTTO_FACE_CAPACITY];
    uint slot = atomicAdd(faceHeader[list], 1u);
    if (slot < capacity) faceQueue[list * capacity + slot] = uvec4(uvec3(cell), dir | (f << 3u));
    return true;
}
