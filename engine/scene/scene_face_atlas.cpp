#include "engine/scene/scene.h"

#include "engine/scene/face_atlas.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>

namespace grotto {

// The face atlas (face_atlas.h): its layout over the chunks, its records and cells.
void GpuScene::layFaceAtlas(uint32_t texelsPerSide) {
    if (atlasLayout_ && atlasLayout_->texelsPerSide() == texelsPerSide) return;
    atlasCurrent_ = false;
    atlasLayout_ = std::make_unique<FaceAtlasLayout>(texelsPerSide);
    for (const GpuChunk& c : chunks) atlasLayout_->place(c.index, c.atlasBoxes);
}

void GpuScene::fillFaceAtlas(const voxel::FaceCacheArrays& arrays) {
    layFaceAtlas(arrays.texelsPerSide);
    const uint32_t k = arrays.texelsPerSide;
    constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    vk::destroy(ctx, atlasRecords_);
    atlasCurrent_ = false;
    // An atlas one storage buffer cannot hold is not made: the chain reads the cache
    // (lavapipe's limit is 128 MiB).
    const uint64_t limit = ctx.properties.limits.maxStorageBufferRange;
    if (atlasLayout_->capacity() * sizeof(glm::uvec2) > limit || slots.capacity() * sizeof(glm::uvec2) > limit) {
        vk::destroy(ctx, atlasCells_);
        return;
    }
    // Quads of coarser levels, and spare room, keep record (0, 0): no region.
    atlasRecords_ = vk::uploadBuffer(ctx, std::max<uint64_t>(slots.capacity(), 1) * sizeof(glm::uvec2), usage, [&](void* data) {
        glm::uvec2* records = static_cast<glm::uvec2*>(data);
        std::memset(data, 0, std::max<uint64_t>(slots.capacity(), 1) * sizeof(glm::uvec2));
        for (const GpuChunk& c : chunks) {
            const FaceAtlasLayout::Chunk* placed = atlasLayout_->find(c.index);
            for (size_t q = 0; placed && q < c.atlasRectOf.size(); ++q) {
                const uint32_t r = c.atlasRectOf[q];
                records[c.slotFirst + q] = atlasRecord(c.index, unpackAtlasBox(c.atlasBoxes[r]), placed->regions[r], k);
            }
        }
    });
    // Every region's cells; the rest of the range is never read (no record points there).
    auto fillRegions = [&](glm::uvec2* cells) {
        tbb::parallel_for(size_t(0), chunks.size(), [&](size_t i) {
            const GpuChunk& c = chunks[i];
            const FaceAtlasLayout::Chunk* placed = atlasLayout_->find(c.index);
            for (size_t q = 0; placed && q < c.atlasBoxes.size(); ++q) {
                const AtlasBox box = unpackAtlasBox(c.atlasBoxes[q]);
                fillAtlasRegion(arrays, c.index, box, {cells + placed->regions[q], size_t(atlasRegionCells(box, k))});
            }
        });
    };
    const VkDeviceSize cellBytes = std::max<uint64_t>(atlasLayout_->capacity(), 2) * sizeof(glm::uvec2);
    // A CPU device reads host memory: the cells are written where the frames read
    // them, and kept from fill to fill while the range's size holds. Staged, and a
    // new buffer each fill, the caves' 73 MB took 0.45 s a fill against 0.05 s for
    // their regions alone: fresh pages twice, a clear and a copy.
    if (ctx.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
        if (atlasCells_.size != cellBytes) {
            vk::destroy(ctx, atlasCells_);
            atlasCells_ = vk::createBuffer(ctx, cellBytes, usage, true);
        }
        fillRegions(static_cast<glm::uvec2*>(atlasCells_.mapped()));
    } else {
        vk::destroy(ctx, atlasCells_);
        atlasCells_ = vk::uploadBuffer(ctx, cellBytes, usage, [&](void* data) {
            std::memset(data, 0, cellBytes);
            fillRegions(static_cast<glm::uvec2*>(data));
        });
    }
    atlasCurrent_ = true;
}

}  // namespace grotto
