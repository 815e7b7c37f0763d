#pragma once
// A flat lookup from brick coordinates (voxel index >> 3) to 512-bit occupancy
// masks, for traversals that test millions of voxels: one table read per brick
// entered and one bit test per voxel, instead of a tree walk per voxel.
#include "voxel/world.h"

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace grotto::voxel {

// The first solid voxel a ray enters.
struct BrickHit {
    double t = 0.0;        // along the ray, in voxels (the ray's direction is unit length)
    glm::ivec3 voxel{0};
    int face = 0;          // entered through: 0..5 = +X -X +Y -Y +Z -Z (World::raycast's order)
};

class BrickTable {
public:
    explicit BrickTable(const World& world);

    // Brings the bricks holding `changed` up to date with the world, in place
    // (a brick that turns empty or a new one outside the table's range included),
    // so the table equals a fresh BrickTable(world).
    void update(const World& world, const IndexBox& changed);

    // 0 for an empty (or absent) brick, else an index for mask().
    uint32_t find(glm::ivec3 brick) const {
        const glm::ivec3 r = brick - lo_;
        if (r.x < 0 || r.y < 0 || r.z < 0 || r.x >= dims_.x || r.y >= dims_.y || r.z >= dims_.z) return 0;
        if (!dense_.empty()) return dense_[denseIndex(r)];
        const auto it = sparse_.find(r);
        return it == sparse_.end() ? 0 : it->second;
    }
    // Bit for voxel v of brick `index` (v's low three bits pick the voxel).
    bool solid(uint32_t index, glm::ivec3 v) const {
        return (masks_[size_t(index) * 8 + (v.x & 7)] >> (((v.y & 7) << 3) | (v.z & 7))) & 1u;
    }
    // Does the ray from p (voxel index units, relative to voxel corner 0,0,0) along
    // the unit direction d enter a solid voxel at t <= tMax? The start cell counts
    // as open: it is the empty cell in front of a visible face, and at concave
    // edges rounding may put p a hair inside the neighbouring voxel.
    bool hitWithin(glm::dvec3 p, glm::dvec3 d, double tMax) const;
    // The same walk, telling where: the first solid voxel entered at t <= tMax.
    std::optional<BrickHit> firstHit(glm::dvec3 p, glm::dvec3 d, double tMax) const;
    // Beyond which t (plus a margin) the ray from p along d is past the table's
    // brick range for good; -1 when it never enters it.
    double leaveRange(glm::dvec3 p, glm::dvec3 d) const;

    bool dense() const { return !dense_.empty(); }

private:
    template <bool kRecord>
    bool walk(glm::dvec3 p, glm::dvec3 d, double tMax, BrickHit* hit) const;
    // Re-lays the index over the brick range [lo, lo + dims), keeping every mask.
    void reshape(glm::ivec3 lo, glm::ivec3 dims);
    void setIndex(glm::ivec3 brick, uint32_t index);
    uint32_t newSlot();

    size_t denseIndex(glm::ivec3 r) const {
        return (size_t(r.x) * size_t(dims_.y) + size_t(r.y)) * size_t(dims_.z) + size_t(r.z);
    }

    glm::ivec3 lo_{0}, dims_{0};          // brick coordinate range
    std::vector<uint32_t> dense_;         // over the whole range, when it is small enough
    // Otherwise the non-empty bricks only, keyed by their coordinates relative to lo_
    // (a product of the extents could overflow 64 bits for a far-flung sparse world).
    struct KeyHash {
        size_t operator()(glm::ivec3 r) const {
            return size_t(uint32_t(r.x)) * 0x9E3779B97F4A7C15ull ^ size_t(uint32_t(r.y)) * 0xC2B2AE3D27D4EB4Full ^
                   size_t(uint32_t(r.z)) * 0x165667B19E3779F9ull;
        }
    };
    std::unordered_map<glm::ivec3, uint32_t, KeyHash> sparse_;
    std::vector<uint64_t> masks_;         // 8 words per brick; brick 0 is all empty
    std::vector<uint32_t> freeSlots_;     // mask slots of bricks that an update emptied
};

}  // namespace grotto::voxel
