// GpuScene's face atlas (face_atlas.h): its layout over the scene's chunks, and
// the records and cells a fill writes.
#include "engine/scene/face_atlas.h"
#include "engine/scene/scene.h"

#include <tbb/parallel_for.h>

#include <cstring>

namespace grotto {

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
    vk::destroy(ctx, atlasCells_);
    atlasCurrent_ = false;
    // An atlas one storage buffer cannot hold is not made: the chain reads the cache
    // (lavapipe's limit is 128 MiB).
    const uint64_t limit = ctx.properties.limits.maxStorageBufferRange;
    if (atlasLayout_->capacity() * sizeof(glm::uvec2) > limit || slots.capacity() * sizeof(glm::uvec2) > limit) return;
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
    atlasCells_ = vk::uploadBuffer(ctx, std::max<uint64_t>(atlasLayout_->capacity(), 2) * sizeof(glm::uvec2), usage, [&](void* data) {
        glm::uvec2* cells = static_cast<glm::uvec2*>(data);
        std::memset(data, 0, std::max<uint64_t>(atlasLayout_->capacity(), 2) * sizeof(glm::uvec2));
        tbb::parallel_for(size_t(0), chunks.size(), [&](size_t i) {
            const GpuChunk& c = chunks[i];
            const FaceAtlasLayout::Chunk* placed = atlasLayout_->find(c.index);
            for (size_t q = 0; placed && q < c.atlasBoxes.size(); ++q) {
                const AtlasBox box = unpackAtlasBox(c.atlasBoxes[q]);
                fillAtlasRegion(arrays, c.index, box, {cells + placed->regions[q], size_t(atlasRegionCells(box, k))});
            }
        });
    });
    atlasCurrent_ = true;
}

}  // namespace grotto
