#pragma once
// The face cache of a live world (--ao cache): every exposed face's texels on the
// host, laid out and uploaded into the scene's GpuScene::faceCache, from a bake
// loaded from disk or made here on every core.
#include "engine/scene/scene.h"
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/face_cache_edit.h"
#include "voxel/face_cache_file.h"

#include <filesystem>
#include <span>
#include <vector>

namespace grotto {

class LiveFaceCache {
public:
    // `texels`: k x k for each of `faces` (exposedFaces of the world, in order),
    // traced with `settings`. Uploads them into `scene`.
    LiveFaceCache(GpuScene& scene, std::vector<voxel::ExposedFace> faces, std::vector<voxel::FaceTexel> texels,
                  const voxel::FaceBakeSettings& settings);

    // A bake of the world (`grotto bake`) with AO radius `radius` (world units);
    // throws grotto::Error (input) naming the file and the first field that is not
    // this world's or these settings' (voxel::requireMatchingBake).
    static LiveFaceCache load(GpuScene& scene, const voxel::BrickTable& table, const voxel::World& world,
                              double radius, const std::filesystem::path& bake);
    // Baked here on every core, as `grotto bake` with `settings` would.
    static LiveFaceCache bake(GpuScene& scene, const voxel::BrickTable& table, const voxel::World& world,
                              const voxel::FaceBakeSettings& settings);

    // After an edit of `changed` (the world and table already edited): the faces
    // listed again, the texels the edit reaches traced again, the rest carried
    // over (voxel::updateAfterEdit), and the GPU copy replaced.
    void edited(const voxel::BrickTable& table, const voxel::World& world, const IndexBox& changed);

    const voxel::FaceBakeSettings& settings() const { return settings_; }
    std::span<const voxel::ExposedFace> faces() const { return faces_; }
    std::span<const voxel::FaceTexel> texels() const { return texels_; }

private:
    void upload();  // replaces the scene's GPU copy

    GpuScene& scene_;
    std::vector<voxel::ExposedFace> faces_;
    std::vector<voxel::FaceTexel> texels_;
    voxel::FaceBakeSettings settings_;
};

// The settings a bake of `world` with AO radius `radius` (world units) and k
// texels a side traces with: `grotto bake`'s defaults otherwise, the world's sun.
voxel::FaceBakeSettings worldBakeSettings(const voxel::World& world, double radius,
                                          uint32_t texelsPerSide = voxel::kDefaultBakeTexels);

}  // namespace grotto
