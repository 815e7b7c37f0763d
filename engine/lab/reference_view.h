#pragma once
// The reference AO of one view (docs/reference.md): the surface points of a
// G-buffer of the exact voxels (no level of detail) traced by voxel::referenceAo,
// through the on-disk cache. `grotto reference` writes it to an EXR; `grotto
// tradeoff` and the tests measure methods against it.
#include "engine/camera.h"
#include "engine/lab/surface_points.h"
#include "engine/vk/context.h"
#include "voxel/reference_ao.h"
#include "voxel/world.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace grotto {

// The surface points and normals of a view of the exact voxels (a G-buffer drawn
// on `ctx` without levels of detail), with `objects` at their poses.
SurfacePoints viewSurfacePoints(const voxel::World& world, const Camera& camera, vk::Context& ctx,
                                std::span<const voxel::PosedWorld> objects = {});

// What a view's reference depends on, as text for common/cache.h's key: the
// world's and its objects' file bytes, the camera's values (not its name), the
// size, the objects' poses and the edits applied since load, in order. A
// reference adds its own settings and version.
std::string viewCacheKey(const voxel::World& world, const Camera& camera, std::span<const voxel::PosedWorld> objects);

struct ReferenceView {
    std::vector<float> ao, stderror;  // per pixel, row 0 on top; sky: V 1, error 0
    std::vector<uint8_t> surface;     // 1 where a surface is (the pixels every statistic counts)
    uint64_t rays = 0;                // traced now (0 on a cache hit)
    double traceSeconds = 0.0;        // the rays alone, without Vulkan start-up and G-buffer
    bool cacheHit = false;
    std::filesystem::path cacheFile;
};

// R is in world units. Renders the G-buffer on `ctx`, or, when it is null and the
// cache misses, on a context of its own (a hit needs no Vulkan). A cache that
// cannot be written gives a warning on stderr, not a failure; a world with no
// source file (built in memory) is never cached.
// `objects`: the world's objects at the view's poses (object k of the surface ids
// is objects[k - 1]), drawn and traced with the world.
ReferenceView referenceView(const voxel::World& world, const Camera& camera, double radius, uint32_t spp,
                            vk::Context* ctx = nullptr, std::span<const voxel::PosedWorld> objects = {});

}  // namespace grotto
