// The face cache's three buffers at GROTTO_FACE_CACHE_BINDING and the two after
// it (engine/scene/face_cache_gpu.h binds them), read through
// shared/face_cache.h. The includer defines GROTTO_FACE_CACHE_BINDING and the
// functions faceCacheTable() and faceCacheK() before including this.
layout(set = 0, binding = GROTTO_FACE_CACHE_BINDING, std430) readonly buffer FaceBricks { uvec4 faceBricks[]; };
layout(set = 0, binding = GROTTO_FACE_CACHE_BINDING + 1, std430) readonly buffer FaceRecords { uint faceRecords[]; };
#ifdef GROTTO_FACE_CACHE_WRITE  // the face cache's tracer writes the texels
layout(set = 0, binding = GROTTO_FACE_CACHE_BINDING + 2, std430) buffer FaceTexels { uint faceTexels[]; };
#else
layout(set = 0, binding = GROTTO_FACE_CACHE_BINDING + 2, std430) readonly buffer FaceTexels { uint faceTexels[]; };
#endif

uvec4 faceCacheBrickEntry(uint slot) { return faceBricks[slot]; }
uint faceCacheRecordWord(uint word) { return faceRecords[word]; }
uint faceCacheTexelWord(uint word) { return faceTexels[word]; }
#include "shared/face_cache.h"
