#pragma once
// The GPU's read of the face cache (shaders/shared/face_cache.h) compiled as C++
// over laid-out arrays: the one twin the atlas's fill and the tests read through,
// so the host finds exactly what a shader finds. A FaceCacheTwin on the stack
// points this thread's reads at its arrays while it lives.
#include "voxel/face_cache_layout.h"

namespace grotto::gpu {
inline thread_local const voxel::FaceCacheArrays* faceCacheTwin = nullptr;
inline glm::uvec4 faceCacheBrickEntry(uint32_t slot) { return faceCacheTwin->bricks[slot]; }
inline uint32_t faceCacheRecordWord(uint32_t word) { return faceCacheTwin->records[word]; }
inline uint32_t faceCacheTexelWord(uint32_t word) { return faceCacheTwin->texels[word]; }
inline uint32_t faceCacheTable() { return faceCacheTwin->table; }
inline uint32_t faceCacheK() { return faceCacheTwin->texelsPerSide; }
}  // namespace grotto::gpu
#include "shaders/shared/face_cache.h"

namespace grotto::voxel {

class FaceCacheTwin {
public:
    explicit FaceCacheTwin(const FaceCacheArrays& arrays) : previous_(gpu::faceCacheTwin) { gpu::faceCacheTwin = &arrays; }
    ~FaceCacheTwin() { gpu::faceCacheTwin = previous_; }
    FaceCacheTwin(const FaceCacheTwin&) = delete;
    FaceCacheTwin& operator=(const FaceCacheTwin&) = delete;

private:
    const FaceCacheArrays* previous_;
};

}  // namespace grotto::voxel
