#include "engine/scene/occupancy.h"

#include "shaders/shared/trace.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <map>

namespace grotto {
namespace {

constexpr uint32_t kBricksPerTile = 512, kMaskWords = 16;
constexpr VkDeviceSize kTileBytes = kBricksPerTile * sizeof(uint32_t), kMaskBytes = kMaskWords * sizeof(uint32_t);
constexpr VkBufferUsageFlags kOccupancyBufferUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

// Room for a quarter more than `used`, so edits that add bricks grow a buffer rarely.
VkDeviceSize withRoom(size_t used, VkDeviceSize unit) { return VkDeviceSize(used + used / 4 + 1) * unit; }

uint32_t brickEntry(glm::ivec3 brick) { return gpu::occupancyBrickEntry(brick.x, brick.y, brick.z); }

void appendMask(std::vector<uint32_t>& words, const voxel::Brick& b) {
    // Little-endian: uint64 word x splits into uint32 words 2x (y < 4) and 2x + 1.
    const size_t at = words.size();
    words.resize(at + kMaskWords);
    std::memcpy(words.data() + at, b.occupancy, kMaskBytes);
}

}  // namespace

GpuOccupancy::GpuOccupancy(vk::Context& ctx, const voxel::World& world) : ctx_(ctx) {
    bounds_ = world.bounds();
    std::vector<uint32_t> masks(kMaskWords, 0u);  // slot 0: the empty brick
    bool grew = false;
    for (const voxel::Brick& b : world.bricks()) {
        const uint32_t tile = tileSlot(b.origin >> GROTTO_TILE_SHIFT, grew);
        brickSlots_[size_t(tile) * kBricksPerTile + brickEntry(b.origin >> 3)] = maskSlots_++;
        appendMask(masks, b);
    }
    rebuildHash(tileSlots_.size());
    // Device-local, with room to grow; the spare room is zero (empty bricks, absent tiles).
    std::vector<uint32_t> bricks(brickSlots_);
    bricks.resize(withRoom(std::max<size_t>(tileSlots_.size(), 1), kTileBytes) / sizeof(uint32_t), 0u);
    masks.resize(withRoom(maskSlots_, kMaskBytes) / sizeof(uint32_t), 0u);
    try {
        tiles_ = vk::uploadBuffer(ctx, hash_.data(), hash_.size() * sizeof(glm::ivec4), kOccupancyBufferUsage);
        bricks_ = vk::uploadBuffer(ctx, bricks.data(), bricks.size() * sizeof(uint32_t), kOccupancyBufferUsage);
        masks_ = vk::uploadBuffer(ctx, masks.data(), masks.size() * sizeof(uint32_t), kOccupancyBufferUsage);
    } catch (...) {
        vk::destroy(ctx, tiles_);
        vk::destroy(ctx, bricks_);
        throw;
    }
}

GpuOccupancy::~GpuOccupancy() {
    vk::destroy(ctx_, tiles_);
    vk::destroy(ctx_, bricks_);
    vk::destroy(ctx_, masks_);
}

size_t GpuOccupancy::hostBytes() const {
    return hash_.size() * sizeof(glm::ivec4) + brickSlots_.size() * sizeof(uint32_t) +
           tileSlots_.size() * (sizeof(glm::ivec3) + sizeof(uint32_t) + 2 * sizeof(void*)) +
           freeMasks_.size() * sizeof(uint32_t);
}

uint32_t GpuOccupancy::tileSlot(glm::ivec3 tile, bool& hashChanged) {
    const auto [it, added] = tileSlots_.try_emplace(tile, uint32_t(tileSlots_.size()));
    if (!added) return it->second;
    hashChanged = true;
    brickSlots_.resize(brickSlots_.size() + kBricksPerTile, 0u);
    // Load factor at most a half keeps probe runs short; the table is rebuilt when it would pass that.
    if (!hash_.empty()) {
        if (2 * tileSlots_.size() > hash_.size()) {
            rebuildHash(tileSlots_.size());
        } else {
            const uint32_t mask = hashMask();
            uint32_t i = gpu::occupancyHash(tile.x, tile.y, tile.z) & mask;
            while (hash_[i].w != 0) i = (i + 1) & mask;
            hash_[i] = glm::ivec4(tile, int(it->second + 1));
        }
    }
    return it->second;
}

void GpuOccupancy::rebuildHash(size_t entries) {
    hash_.assign(std::max<size_t>(std::bit_ceil(2 * entries), 16), glm::ivec4(0));
    const uint32_t mask = hashMask();
    for (const auto& [tile, slot] : tileSlots_) {
        uint32_t i = gpu::occupancyHash(tile.x, tile.y, tile.z) & mask;
        while (hash_[i].w != 0) i = (i + 1) & mask;
        hash_[i] = glm::ivec4(tile, int(slot + 1));
    }
}

uint32_t GpuOccupancy::brickSlot(glm::ivec3 brick) const {
    const auto it = tileSlots_.find(brick >> (GROTTO_TILE_SHIFT - 3));
    return it == tileSlots_.end() ? 0 : brickSlots_[size_t(it->second) * kBricksPerTile + brickEntry(brick)];
}

void GpuOccupancy::update(const voxel::World& world, const voxel::IndexBox& changed, StagedUploads& uploads) {
    if (changed.empty()) return;
    bounds_ = world.bounds();
    // The final brick entry of every brick the box touches, each written once.
    std::map<size_t, uint32_t> entries;  // index into the bricks buffer -> mask slot
    const glm::ivec3 lo = changed.min >> 3, hi = changed.max >> 3;
    for (const auto& [tile, slot] : tileSlots_) {
        const glm::ivec3 tLo = glm::max(lo, tile << 3), tHi = glm::min(hi, (tile << 3) + 7);
        for (int x = tLo.x; x <= tHi.x; ++x)
            for (int y = tLo.y; y <= tHi.y; ++y)
                for (int z = tLo.z; z <= tHi.z; ++z) {
                    const size_t at = size_t(slot) * kBricksPerTile + brickEntry({x, y, z});
                    if (brickSlots_[at] == 0) continue;
                    freeMasks_.push_back(brickSlots_[at]);
                    brickSlots_[at] = 0;
                    entries[at] = 0;
                }
    }
    bool hashChanged = false;
    std::vector<std::pair<uint32_t, const voxel::Brick*>> maskWrites;
    const std::vector<voxel::Brick> bricks = world.bricks(changed);
    for (const voxel::Brick& b : bricks) {
        const uint32_t tile = tileSlot(b.origin >> GROTTO_TILE_SHIFT, hashChanged);
        uint32_t mask = maskSlots_;
        if (!freeMasks_.empty()) mask = freeMasks_.back(), freeMasks_.pop_back();
        else ++maskSlots_;
        const size_t at = size_t(tile) * kBricksPerTile + brickEntry(b.origin >> 3);
        brickSlots_[at] = mask;
        entries[at] = mask;
        maskWrites.push_back({mask, &b});
    }
    // Grow what no longer fits, keeping what the GPU holds. The new room reads zero
    // (StagedUploads clears it): a new tile's brick slots are written only where
    // its bricks are, so its other slots rely on that.
    if (VkDeviceSize(brickSlots_.size()) * sizeof(uint32_t) > bricks_.size)
        uploads.reallocate(bricks_, withRoom(tileSlots_.size(), kTileBytes), kOccupancyBufferUsage, true);
    if (VkDeviceSize(maskSlots_) * kMaskBytes > masks_.size)
        uploads.reallocate(masks_, withRoom(maskSlots_, kMaskBytes), kOccupancyBufferUsage, true);
    if (hashChanged) {  // new tiles: the table is small, so it is rewritten whole
        if (VkDeviceSize(hash_.size() * sizeof(glm::ivec4)) > tiles_.size)
            uploads.reallocate(tiles_, hash_.size() * sizeof(glm::ivec4), kOccupancyBufferUsage, false);
        uploads.discard(tiles_, 0, tiles_.size);
        uploads.write(tiles_, 0, hash_.data(), hash_.size() * sizeof(glm::ivec4));
    }
    for (const auto& [at, mask] : entries) {
        uploads.discard(bricks_, at * sizeof(uint32_t), sizeof(uint32_t));
        uploads.write(bricks_, at * sizeof(uint32_t), &brickSlots_[at], sizeof(uint32_t));
    }
    for (const auto& [mask, brick] : maskWrites) {
        uploads.discard(masks_, mask * kMaskBytes, kMaskBytes);
        uploads.write(masks_, mask * kMaskBytes, brick->occupancy, kMaskBytes);
    }
}

}  // namespace grotto
