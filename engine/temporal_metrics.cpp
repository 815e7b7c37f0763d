#include "engine/temporal_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grotto {

AoFrame aoFrame(const FrameImages& f, const Camera& camera, uint32_t scale) {
    AoFrame a;
    a.scale = scale;
    a.width = (f.width + scale - 1) / scale;
    a.height = (f.height + scale - 1) / scale;
    const size_t n = size_t(a.width) * a.height;
    a.world.resize(n);
    a.surface.assign(n, 0);
    a.raw.resize(n), a.spatial.resize(n), a.temporal.resize(n);
    const glm::dvec3 forward = -camera.basis[2];
    for (uint32_t y = 0; y < a.height; ++y)
        for (uint32_t x = 0; x < a.width; ++x) {
            const size_t i = size_t(y) * a.width + x, full = size_t(scale * y) * f.width + scale * x;
            a.raw[i] = f.aoRaw[full];
            a.spatial[i] = f.aoSpatial[full];
            a.temporal[i] = f.aoTemporal[full];
            const double depth = f.depth[full];
            if (!std::isfinite(depth)) continue;
            const glm::dvec3 dir = camera.rayDirection(scale * x + 0.5, scale * y + 0.5);
            a.world[i] = camera.position + dir * (depth / glm::dot(dir, forward));
            a.surface[i] = 1;
        }
    return a;
}

std::vector<int32_t> reproject(const AoFrame& now, const AoFrame& before, const Camera& beforeCamera,
                               double tolerance) {
    std::vector<int32_t> match(now.world.size(), -1);
    // Relative to the camera, so positions far from the origin keep their precision.
    const glm::dmat4 clipFromView = beforeCamera.projection();
    const glm::dmat3 viewFromWorld = glm::transpose(beforeCamera.basis);
    for (size_t i = 0; i < now.world.size(); ++i) {
        if (!now.surface[i]) continue;
        const glm::dvec3 view = viewFromWorld * (now.world[i] - beforeCamera.position);
        if (view.z >= 0.0) continue;  // behind the previous camera
        const glm::dvec4 clip = clipFromView * glm::dvec4(view, 1.0);
        const double px = (clip.x / clip.w * 0.5 + 0.5) * beforeCamera.width;
        const double py = (clip.y / clip.w * 0.5 + 0.5) * beforeCamera.height;
        // The AO pixel whose full-res pixel (scale x, scale y) is nearest.
        const double qx = std::floor(px / before.scale), qy = std::floor(py / before.scale);
        if (!(qx >= 0 && qy >= 0 && qx < before.width && qy < before.height)) continue;
        const size_t j = size_t(qy) * before.width + size_t(qx);
        if (before.surface[j] && glm::length(before.world[j] - now.world[i]) <= tolerance) match[i] = int32_t(j);
    }
    return match;
}

double flicker(const std::vector<float>& now, const std::vector<float>& before, const std::vector<int32_t>& match) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < match.size(); ++i)
        if (match[i] >= 0) sum += std::abs(double(now[i]) - before[size_t(match[i])]), ++n;
    return n ? sum / double(n) : 0.0;
}

std::vector<uint16_t> disocclusionAge(const std::vector<int32_t>& match, const std::vector<uint16_t>& previous,
                                      size_t pixels) {
    std::vector<uint16_t> age(pixels, 0);
    for (size_t i = 0; i < pixels; ++i)
        if (match[i] >= 0)
            age[i] = uint16_t(std::min<int>(previous[size_t(match[i])] + 1, std::numeric_limits<uint16_t>::max()));
    return age;
}

}  // namespace grotto
