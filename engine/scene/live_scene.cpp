#include "engine/scene/live_scene.h"

#include "engine/frame/render_memory.h"
#include "engine/scene/scene_memory.h"
#include "voxel/mesh_footprint.h"

namespace grotto {

LiveScene::LiveScene(vk::Context& ctx, voxel::World world, const SceneFrames& frames)
    : world_(std::move(world)), mesh_(world_, {.coarseLevels = voxel::kMaxCoarseLevels}) {
    const uint64_t meshBytes = voxel::measureMesh(mesh_).liveBytes;
    // Uploaded from the mesh's own chunks, lent, not copied: the mesh is most of the peak.
    gpu_ = mesh_.lend([&](std::span<const voxel::MeshChunkQuads> chunks) {
        memoryEstimate_ = requireSceneFits(world_, meshBytes, chunks, frames, cpuDevice(ctx));
        return uploadScene(ctx, chunks, world_);
    });
}

voxel::EditResult LiveScene::apply(const voxel::Edit& edit) {
    const voxel::EditResult result = world_.apply(edit);
    changed(result);
    return result;
}

voxel::EditResult LiveScene::undo() {
    const voxel::EditResult result = world_.undo();
    changed(result);
    return result;
}

const voxel::BrickTable& LiveScene::bricks() {
    if (!bricks_) bricks_.emplace(world_);
    return *bricks_;
}

void LiveScene::loadFaceCache(const std::filesystem::path& bake, double radius) {
    faceCache_.emplace(LiveFaceCache::load(*gpu_, bricks(), world_, radius, bake));  // the old one kept if it throws
}

void LiveScene::bakeFaceCache(const voxel::FaceBakeSettings& settings) {
    faceCache_.emplace(LiveFaceCache::bake(*gpu_, bricks(), world_, settings));
}

void LiveScene::progressiveFaceCache(const voxel::FaceBakeSettings& settings) {
    faceCache_.emplace(LiveFaceCache::progressive(*gpu_, bricks(), world_, settings));
}

void LiveScene::changed(const voxel::EditResult& result) {
    if (result.voxels.empty()) return;
    std::vector<voxel::MeshChunkQuads> replaced;
    std::vector<glm::ivec3> removed;
    for (const glm::ivec3& origin : mesh_.update(world_, result.voxels)) {
        if (const voxel::MeshChunkQuads* chunk = mesh_.find(origin)) replaced.push_back(*chunk);
        else removed.push_back(origin);
    }
    gpu_->updateChunks(replaced, removed);
    gpu_->updateOccupancy(world_, result.voxels);
    if (bricks_) bricks_->update(world_, result.voxels);
    if (faceCache_) faceCache_->edited(bricks(), world_, result.voxels);
}

}  // namespace grotto
