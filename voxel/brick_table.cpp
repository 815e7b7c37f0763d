#include "voxel/brick_table.h"

namespace grotto::voxel {

namespace {
// Above this many bricks in the bounding range the table is a hash map: a sparse
// world spread over a huge box would otherwise cost 4 bytes per empty brick.
constexpr size_t kDenseLimit = size_t(1) << 25;
}  // namespace

BrickTable::BrickTable(const World& world) {
    masks_.assign(8, 0);
    const IndexBox box = world.bounds();
    if (box.empty()) return;
    lo_ = box.min >> 3;  // arithmetic shift: floor division for negative indices too
    dims_ = (box.max >> 3) - lo_ + 1;
    const size_t range = size_t(dims_.x) * size_t(dims_.y) * size_t(dims_.z);
    if (range <= kDenseLimit) dense_.assign(range, 0);
    for (const Brick& b : world.bricks()) {
        bool any = false;
        for (uint64_t w : b.occupancy) any = any || w != 0;
        if (!any) continue;
        const glm::ivec3 r = (b.origin >> 3) - lo_;
        const size_t key = (size_t(r.x) * size_t(dims_.y) + size_t(r.y)) * size_t(dims_.z) + size_t(r.z);
        const uint32_t index = uint32_t(masks_.size() / 8);
        masks_.insert(masks_.end(), b.occupancy, b.occupancy + 8);
        if (dense()) dense_[key] = index;
        else sparse_[key] = index;
    }
}

}  // namespace grotto::voxel
