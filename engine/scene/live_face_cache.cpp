#include "engine/scene/live_face_cache.h"

#include "voxel/face_cache_layout.h"

#include <algorithm>

namespace grotto {

voxel::FaceBakeSettings worldBakeSettings(const voxel::World& world, double radius, uint32_t texelsPerSide) {
    const voxel::Lighting& light = world.desc().lighting;
    return {.radius = radius, .texelsPerSide = texelsPerSide, .sunDirection = glm::dvec3(light.sunDirection),
            .sunAngleDegrees = double(light.sunAngle)};
}

LiveFaceCache::LiveFaceCache(GpuScene& scene, std::vector<voxel::ExposedFace> faces,
                             std::vector<voxel::FaceTexel> texels, const voxel::FaceBakeSettings& settings)
    : scene_(scene), faces_(std::move(faces)), texels_(std::move(texels)), settings_(settings) {
    upload();
}

LiveFaceCache LiveFaceCache::load(GpuScene& scene, const voxel::BrickTable& table, const voxel::World& world,
                                  double radius, const std::filesystem::path& bake) {
    voxel::FaceCacheFile file = voxel::loadFaceCache(bake);
    std::vector<voxel::ExposedFace> faces = voxel::exposedFaces(table, world);
    voxel::requireMatchingBake(file, voxel::faceCacheKey(world, radius, file.key.texelsPerSide), faces.size(), bake);
    voxel::FaceBakeSettings settings = worldBakeSettings(world, radius, file.key.texelsPerSide);
    // Faces baked after an edit get as many rays as the bake gave its texels.
    uint32_t rays = 0, sunRays = 0;
    for (const voxel::FaceTexel& t : file.texels) rays = std::max(rays, t.samples), sunRays = std::max(sunRays, t.sunSamples);
    if (rays) settings.rays = rays;
    if (sunRays) settings.sunRays = sunRays;
    return LiveFaceCache(scene, std::move(faces), std::move(file.texels), settings);
}

LiveFaceCache LiveFaceCache::bake(GpuScene& scene, const voxel::BrickTable& table, const voxel::World& world,
                                  const voxel::FaceBakeSettings& settings) {
    std::vector<voxel::ExposedFace> faces = voxel::exposedFaces(table, world);
    std::vector<voxel::FaceTexel> texels(faces.size() * settings.texelsPerSide * settings.texelsPerSide);
    voxel::bakeFaces(table, world, faces, settings, texels);
    return LiveFaceCache(scene, std::move(faces), std::move(texels), settings);
}

void LiveFaceCache::edited(const voxel::BrickTable& table, const voxel::World& world, const IndexBox& changed) {
    voxel::updateAfterEdit(table, world, changed, settings_, faces_, texels_);
    upload();
}

void LiveFaceCache::upload() {
    const voxel::FaceCacheArrays arrays = voxel::layFaceCache(faces_, texels_, settings_.texelsPerSide);
    auto gpu = std::make_unique<GpuFaceCache>(
        scene_.ctx, arrays,
        GpuFaceCache::Sun{glm::vec3(settings_.sunDirection), float(settings_.sunAngleDegrees)});
    vkDeviceWaitIdle(scene_.ctx.device);  // no frame in flight may still read the old copy
    scene_.faceCache = std::move(gpu);
}

}  // namespace grotto
