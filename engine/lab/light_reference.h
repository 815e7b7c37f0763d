#pragma once
// The path-traced light of one view (docs/reference.md, "Full light"): the
// G-buffer's surface points of the exact voxels, each traced by
// voxel::pathTrace with the world's lighting, through the on-disk cache.
// `grotto reference --light full` writes it to an EXR; compare and the tests
// measure the frame's light against it.
#include "engine/camera.h"
#include "engine/vk/context.h"
#include "voxel/path_trace.h"
#include "voxel/world.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace grotto {

struct LightReference {
    // Per pixel, row 0 on top: scene-linear radiance and its standard error, per
    // channel. A sky pixel holds the sky's radiance along its centre ray, error 0.
    std::vector<glm::vec3> radiance, stderror;
    std::vector<uint8_t> surface;  // 1 where a surface is (the pixels every statistic counts)
    uint64_t rays = 0;             // traced now (0 on a cache hit)
    double traceSeconds = 0.0;     // the paths alone, without Vulkan start-up and G-buffer
    bool cacheHit = false;
    std::filesystem::path cacheFile;
};

// As referenceView (engine/lab/reference_view.h): the G-buffer is drawn on `ctx`,
// or on a context of its own when it is null and the cache misses; a world with
// no source file is never cached. `objects`: the world's objects at the view's
// poses, drawn, traced and glowing with the world.
LightReference lightReference(const voxel::World& world, const Camera& camera, const voxel::LightSources& lights,
                              const voxel::PathTraceSettings& settings, vk::Context* ctx = nullptr,
                              std::span<const voxel::PosedWorld> objects = {});

}  // namespace grotto
