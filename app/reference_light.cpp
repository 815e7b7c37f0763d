#include "app/reference_light.h"

#include "engine/image_output.h"
#include "engine/lab/light_reference.h"
#include "grotto/error.h"
#include "shaders/shared/tone_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace grotto::app {

void writeLightReference(const std::filesystem::path& out, const voxel::World& world, const Camera& camera,
                         const voxel::PathTraceSettings& settings, std::span<const voxel::PosedWorld> objects,
                         std::optional<double> requireRelative) {
    const voxel::LightSources lights = voxel::lightSources(world.desc().lighting);
    const LightReference t = lightReference(world, camera, lights, settings, nullptr, objects);
    if (t.cacheHit) std::printf("cache hit: %s (nothing traced)\n", t.cacheFile.c_str());
    const size_t n = t.radiance.size();
    if (imageFormatFor(out) == ImageFormat::Png) {
        // As a frame's PNG shows light: times the exposure, tone-mapped, sRGB.
        const voxel::Lighting& l = world.desc().lighting;
        const unsigned curve = l.toneMap == ToneMap::Filmic ? GROTTO_TONE_MAP_FILMIC : GROTTO_TONE_MAP_CLAMP;
        std::vector<float> display(4 * n, 1.0f);
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) display[4 * i + size_t(c)] = gpu::toneMap(t.radiance[i][c] * l.exposure, curve);
        writeSrgb8(out, camera.width, camera.height, encodeSrgb8(display), &camera);
    } else {
        std::vector<std::vector<float>> planes(6, std::vector<float>(n));
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) planes[size_t(c)][i] = t.radiance[i][c], planes[3 + size_t(c)][i] = t.stderror[i][c];
        writeChannels(out, camera.width, camera.height,
                      std::vector<Channel>{{"R", &planes[0]}, {"G", &planes[1]}, {"B", &planes[2]},
                                           {"R_stderr", &planes[3]}, {"G_stderr", &planes[4]}, {"B_stderr", &planes[5]}},
                      camera);
    }

    // The estimate's own error, relative to the light where the light is: the
    // luminance's standard error over its mean, per surface pixel.
    std::vector<double> relative;
    double sum = 0.0;
    size_t black = 0;
    for (size_t i = 0; i < n; ++i) {
        if (!t.surface[i]) continue;
        const glm::vec3 w(0.2126f, 0.7152f, 0.0722f);
        const double y = glm::dot(t.radiance[i], w), e = glm::dot(t.stderror[i], w);
        sum += y;
        if (y > 0.0) relative.push_back(e / y);
        else ++black;
    }
    std::sort(relative.begin(), relative.end());
    const size_t surface = relative.size() + black;
    double relativeSum = 0.0;
    for (double r : relative) relativeSum += r;
    const double mean = relative.empty() ? 0.0 : relativeSum / double(relative.size());
    const double p95 = relative.empty() ? 0.0 : relative[std::min(relative.size() - 1, size_t(0.95 * relative.size()))];
    const std::string bounces = settings.maxBounces == UINT32_MAX
                                    ? std::string("every bounce")
                                    : std::to_string(settings.maxBounces) + " bounces at most";
    std::printf("wrote %s (%ux%u, full light, %u paths a pixel, %s)\n", out.c_str(), camera.width, camera.height,
                settings.spp, bounces.c_str());
    std::printf("pixels %zu (%zu sky, %zu black)", surface, n - surface, black);
    if (t.rays > 0)
        std::printf(", rays %llu traced in %.2f s, %.2f M rays/s", (unsigned long long)t.rays, t.traceSeconds,
                    t.rays / t.traceSeconds * 1e-6);
    std::printf(", mean luminance %.5g\n", surface ? sum / surface : 0.0);
    std::printf("relative standard error of the luminance: mean %.4f, 95th percentile %.4f\n", mean, p95);
    if (requireRelative && mean > *requireRelative)
        throw Error::regression("--require-stderr",
                                "mean relative standard error " + std::to_string(mean) + " is above " +
                                    std::to_string(*requireRelative),
                                "the EXR is written: " + out.string());
}

}  // namespace grotto::app
