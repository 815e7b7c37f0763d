#pragma once
// A live world and its GPU copy kept in step: an edit changes the world's grid,
// re-meshes only the chunks it touched and stages only their quads, which the
// renderer copies into the existing buffers at the start of its next frame. The
// brick table the reference traces is updated the same way, once it exists.
#include "engine/scene/live_face_cache.h"
#include "engine/scene/scene.h"
#include "engine/scene/scene_memory.h"
#include "voxel/brick_table.h"
#include "voxel/live_mesh.h"
#include "voxel/world.h"

#include <filesystem>
#include <memory>
#include <optional>

namespace grotto {

class LiveScene {
public:
    // `frames`: the renderer and first frame that will draw it, for a .vox world's
    // memory estimate, checked against its budget before the scene is uploaded
    // (scene_memory.h).
    LiveScene(vk::Context& ctx, voxel::World world, const SceneFrames& frames = {});

    // Throws grotto::Error (input) for an edit the world refuses; nothing changes then.
    voxel::EditResult apply(const voxel::Edit& edit);
    voxel::EditResult undo();

    const voxel::World& world() const { return world_; }
    const voxel::LiveMesh& mesh() const { return mesh_; }
    // A .vox world's estimated peak memory with the renderer (scene_memory.h); else 0.
    uint64_t memoryEstimate() const { return memoryEstimate_; }
    GpuScene& gpu() { return *gpu_; }
    // Built on first use (the reference needs it; rendering does not), then kept up to date.
    const voxel::BrickTable& bricks();

    // --ao cache's light on the faces (live_face_cache.h), kept in step with
    // edits: a bake of this world with AO radius `radius` (world units), refused
    // with grotto::Error (input) when it is not one, or a bake made here.
    void loadFaceCache(const std::filesystem::path& bake, double radius);
    void bakeFaceCache(const voxel::FaceBakeSettings& settings);
    // Nothing traced yet: the renderer's tracer converges the faces in view.
    void progressiveFaceCache(const voxel::FaceBakeSettings& settings);
    // The cache's full light baked on its own thread, once it has finished
    // (LiveFaceCache::takeBakedLight): between frames. True when it was taken.
    bool takeBakedLight() { return faceCache_ && faceCache_->takeBakedLight(bricks(), world_); }
    // The face atlas filled again as the GPU's tracer catches up after an edit (LiveFaceCache::catchUpAtlas).
    bool catchUpFaceAtlas() { return faceCache_ && faceCache_->catchUpAtlas(); }
    const LiveFaceCache* faceCache() const { return faceCache_ ? &*faceCache_ : nullptr; }
    LiveFaceCache* faceCache() { return faceCache_ ? &*faceCache_ : nullptr; }

private:
    void changed(const voxel::EditResult& result);

    voxel::World world_;
    voxel::LiveMesh mesh_;
    std::unique_ptr<GpuScene> gpu_;
    uint64_t memoryEstimate_ = 0;
    std::optional<voxel::BrickTable> bricks_;
    std::optional<LiveFaceCache> faceCache_;
};

}  // namespace grotto
