#include "engine/lab/light_reference.h"

#include "common/cache.h"
#include "engine/lab/reference_view.h"
#include "engine/lab/surface_points.h"
#include "grotto/error.h"
#include "shaders/shared/sky.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

namespace grotto {
namespace {

// The path tracer's version: bumped when what it computes changes, so caches go stale.
constexpr int kPathTraceVersion = 1;

std::string lightCacheKey(const voxel::World& world, const Camera& camera, const voxel::LightSources& l,
                          const voxel::PathTraceSettings& s, std::span<const voxel::PosedWorld> objects) {
    char text[768];
    std::snprintf(text, sizeof text,
                  "light v%d spp %u bounces %u seed %llu eps %.17g sky %.9g %.9g %.9g %.9g %.9g %.9g x %.9g "
                  "sun %.17g %.17g %.17g %.9g %.9g %.9g angle %.9g ",
                  kPathTraceVersion, s.spp, s.maxBounces, (unsigned long long)s.seed, s.epsilon, l.skyZenith.r,
                  l.skyZenith.g, l.skyZenith.b, l.skyHorizon.r, l.skyHorizon.g, l.skyHorizon.b, l.skyIntensity,
                  l.sunDirection.x, l.sunDirection.y, l.sunDirection.z, l.sun.r, l.sun.g, l.sun.b,
                  l.sunAngleDegrees);
    // The materials' light: the world file's bytes hold them, but a world's
    // materials may also come from elsewhere (a .vox palette).
    std::string materials;
    for (const Material& m : world.desc().materials) {
        char entry[160];
        std::snprintf(entry, sizeof entry, "m %.9g %.9g %.9g %.9g %.9g %.9g %.9g ", m.albedo.r, m.albedo.g,
                      m.albedo.b, m.emissionColor.r, m.emissionColor.g, m.emissionColor.b, m.emissionIntensity);
        materials += entry;
    }
    return text + materials + viewCacheKey(world, camera, objects);
}

// Channels in the cache: radiance r, g, b, errors r, g, b, surface.
constexpr size_t kCachedArrays = 7;

}  // namespace

LightReference lightReference(const voxel::World& world, const Camera& camera, const voxel::LightSources& lights,
                              const voxel::PathTraceSettings& settings, vk::Context* ctx,
                              std::span<const voxel::PosedWorld> objects) {
    const size_t n = size_t(camera.width) * camera.height;
    LightReference r{std::vector<glm::vec3>(n), std::vector<glm::vec3>(n, glm::vec3(0.0f)), std::vector<uint8_t>(n, 0)};
    std::error_code ec;
    const bool cacheable = std::filesystem::is_regular_file(world.desc().source, ec);
    const std::string key = cacheable ? lightCacheKey(world, camera, lights, settings, objects) : std::string();
    if (cacheable) r.cacheFile = cachePath("light", key);
    if (auto cached = cacheable ? loadCached("light", key) : std::nullopt;
        cached && cached->size() == kCachedArrays && std::ranges::all_of(*cached, [n](auto& a) { return a.size() == n; })) {
        const auto& c = *cached;
        for (size_t i = 0; i < n; ++i) {
            r.radiance[i] = {c[0][i], c[1][i], c[2][i]};
            r.stderror[i] = {c[3][i], c[4][i], c[5][i]};
            r.surface[i] = c[6][i] != 0.0f;
        }
        r.cacheHit = true;
        return r;
    }
    // The sky along each pixel's centre ray; surface pixels are overwritten below.
    for (uint32_t y = 0; y < camera.height; ++y)
        for (uint32_t x = 0; x < camera.width; ++x) {
            const glm::dvec3 d = camera.rayDirection(x + 0.5, y + 0.5);
            r.radiance[size_t(y) * camera.width + x] =
                gpu::skyRadiance(float(d.y), glm::vec3(lights.skyZenith), glm::vec3(lights.skyHorizon)) *
                float(lights.skyIntensity);
        }
    std::unique_ptr<vk::Context> own;
    if (!ctx) own = std::make_unique<vk::Context>(), ctx = own.get();
    const SurfacePoints sp = viewSurfacePoints(world, camera, *ctx, objects);
    if (own && own->validationMessages() > 0)
        throw Error::internal("vulkan", std::to_string(own->validationMessages()) +
                                            " validation message(s) reported (printed above)");
    const auto start = std::chrono::steady_clock::now();
    const voxel::PathTraced traced = voxel::pathTrace(world, objects, sp.points, sp.normals, sp.owners, lights, settings);
    r.traceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.rays = traced.rays;
    for (size_t k = 0; k < sp.pixels.size(); ++k) {
        r.radiance[sp.pixels[k]] = traced.radiance[k];
        r.stderror[sp.pixels[k]] = traced.stderror[k];
        r.surface[sp.pixels[k]] = 1;
    }
    if (!cacheable) return r;
    CachedArrays arrays(kCachedArrays, std::vector<float>(n));
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            arrays[size_t(c)][i] = r.radiance[i][c];
            arrays[3 + size_t(c)][i] = r.stderror[i][c];
        }
        arrays[6][i] = r.surface[i];
    }
    try {
        storeCached("light", key, arrays);
    } catch (const Error& e) {
        std::fprintf(stderr, "grotto: warning: result not cached: %s\n", e.what());
    }
    return r;
}

}  // namespace grotto
