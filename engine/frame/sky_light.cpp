#include "engine/frame/sky_light.h"

#include <cmath>
#include <optional>
#include <utility>

namespace grotto {

glm::vec3 skyLight(double up, glm::vec3 zenith, glm::vec3 horizon) {
    // Midpoint rule over the sphere in polar angle from straight up (an even
    // count, so the horizon's step in the gradient falls between cells) and
    // azimuth, weighted by the cosine to the surface direction where positive.
    constexpr int kPolar = 64, kAzimuth = 128;
    const double pi = 3.14159265358979323846, side = std::sqrt(std::max(0.0, 1.0 - up * up));
    glm::dvec3 sum(0.0);
    for (int i = 0; i < kPolar; ++i) {
        const double theta = (i + 0.5) * pi / kPolar, y = std::cos(theta), r = std::sin(theta);
        const glm::dvec3 radiance(gpu::skyRadiance(float(y), zenith, horizon));
        for (int j = 0; j < kAzimuth; ++j) {
            const double phi = (j + 0.5) * 2.0 * pi / kAzimuth;
            const double cosine = r * std::cos(phi) * side + y * up;
            if (cosine > 0.0) sum += radiance * (cosine * r);
        }
    }
    return glm::vec3(sum * (pi / kPolar) * (2.0 * pi / kAzimuth) / pi);
}

std::array<glm::vec3, GROTTO_SKY_LIGHT_ROWS> skyLightTable(glm::vec3 zenith, glm::vec3 horizon) {
    // Every frame asks, and the sky rarely changes: the last sky's rows are kept
    // (per thread, so renderers on several threads need no lock).
    thread_local std::optional<std::pair<glm::vec3, glm::vec3>> lastSky;
    thread_local std::array<glm::vec3, GROTTO_SKY_LIGHT_ROWS> rows;
    if (lastSky == std::pair(zenith, horizon)) return rows;
    for (int k = 0; k < GROTTO_SKY_LIGHT_ROWS; ++k)
        rows[k] = skyLight(-1.0 + 2.0 * k / (GROTTO_SKY_LIGHT_ROWS - 1), zenith, horizon);
    lastSky = std::pair(zenith, horizon);
    return rows;
}

}  // namespace grotto
