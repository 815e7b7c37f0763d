#pragma once
// The world's solid voxels in GPU storage buffers for exact rays: a hash table of
// 64^3 tiles, a brick index per tile and a 512-bit mask per brick (the layout is
// in shaders/shared/trace.h). Built from the bricks the world already has and kept
// in step with its edits, in place: an edit stages only the masks, brick entries
// and hash entries it changed.
#include "engine/scene/staged_uploads.h"
#include "engine/vk/resources.h"
#include "voxel/world.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace grotto {

class GpuOccupancy {
public:
    GpuOccupancy(vk::Context& ctx, const voxel::World& world);
    ~GpuOccupancy();
    GpuOccupancy(const GpuOccupancy&) = delete;
    GpuOccupancy& operator=(const GpuOccupancy&) = delete;

    // Brings the bricks holding `changed` up to date with `world`. The writes go
    // through `uploads`, which the next frame records before any pass reads them.
    void update(const voxel::World& world, const voxel::IndexBox& changed, StagedUploads& uploads);

    const vk::Buffer& tiles() const { return tiles_; }
    const vk::Buffer& bricks() const { return bricks_; }
    const vk::Buffer& masks() const { return masks_; }
    uint32_t hashMask() const { return uint32_t(hash_.size() - 1); }
    const voxel::IndexBox& bounds() const { return bounds_; }  // of the solid voxels; empty when none

    size_t gpuBytes() const { return size_t(tiles_.size + bricks_.size + masks_.size); }
    size_t hostBytes() const;

private:
    struct KeyHash {
        size_t operator()(glm::ivec3 k) const { return size_t(k.x) * 73856093u ^ size_t(k.y) * 19349663u ^ size_t(k.z) * 83492791u; }
    };
    // The tile slot of `tile`, made (with its hash entry, setting hashChanged) when absent.
    uint32_t tileSlot(glm::ivec3 tile, bool& hashChanged);
    uint32_t brickSlot(glm::ivec3 brick) const;  // 0 when empty or its tile is absent
    void rebuildHash(size_t entries);

    vk::Context& ctx_;
    vk::Buffer tiles_, bricks_, masks_;
    std::vector<glm::ivec4> hash_;                          // the tiles buffer's host copy
    std::unordered_map<glm::ivec3, uint32_t, KeyHash> tileSlots_;
    std::vector<uint32_t> brickSlots_;                      // the bricks buffer's host copy
    uint32_t maskSlots_ = 1;                                // slots in use or free, slot 0 the empty brick
    std::vector<uint32_t> freeMasks_;
    voxel::IndexBox bounds_;
};

}  // namespace grotto
