#include "engine/lab/light_metrics.h"

#include "engine/image_output.h"
#include "shaders/shared/tone_map.h"

#include <algorithm>
#include <cmath>

namespace grotto {

double openGroundLuminance(const voxel::LightSources& l) {
    // The sky's light on a face looking up: (1 / pi) x the integral of sky(w) cos
    // over the upper hemisphere = horizon + 0.8 (zenith - horizon) for the
    // gradient's square-root rise (docs/lighting.md, "Ambient from the sky").
    const glm::dvec3 sky = l.skyIntensity * (l.skyHorizon + 0.8 * (l.skyZenith - l.skyHorizon));
    const glm::dvec3 sun = l.sun * std::max(l.sunDirection.y, 0.0);
    return luminance(sky + sun);
}

LightError lightError(const std::vector<glm::vec3>& image, const LightReference& ref, double openGround, float exposure,
                      unsigned toneMap) {
    LightError e;
    const double threshold = 0.01 * openGround;
    double squaredDisplay = 0.0, squaredLinear = 0.0, sumReference = 0.0, sumImage = 0.0, sumRgb = 0.0;
    std::vector<double> relative;
    for (size_t i = 0; i < image.size() && i < ref.radiance.size(); ++i) {
        if (!ref.surface[i]) continue;
        ++e.pixels;
        const glm::dvec3 a(image[i]), r(ref.radiance[i]);
        for (int c = 0; c < 3; ++c) {
            // As a PNG of each holds them: tone-mapped, sRGB-encoded in 8 bits.
            const double da = toSrgb8(gpu::toneMap(float(a[c]) * exposure, toneMap)) / 255.0;
            const double dr = toSrgb8(gpu::toneMap(float(r[c]) * exposure, toneMap)) / 255.0;
            squaredDisplay += (da - dr) * (da - dr);
            squaredLinear += (a[c] - r[c]) * (a[c] - r[c]);
            sumRgb += r[c];
        }
        const double ya = luminance(a), yr = luminance(r);
        sumImage += ya, sumReference += yr;
        if (yr >= threshold && threshold > 0.0) {
            relative.push_back(std::abs(ya - yr) / yr);
            e.blackWhereLit += ya < 1e-6 * threshold;
        }
    }
    if (e.pixels == 0) return e;
    const double n = double(e.pixels);
    const double mse = squaredDisplay / (3.0 * n);
    e.psnr = mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : 99.0;
    const double meanRgb = sumRgb / (3.0 * n);
    e.relativeRmse = meanRgb > 0.0 ? std::sqrt(squaredLinear / (3.0 * n)) / meanRgb : 0.0;
    e.bias = sumReference > 0.0 ? (sumImage - sumReference) / sumReference : 0.0;
    e.dimPixels = relative.size();
    if (!relative.empty()) {
        std::sort(relative.begin(), relative.end());
        e.medianRelative = relative[relative.size() / 2];
        e.p95Relative = relative[std::min(relative.size() - 1, size_t(0.95 * double(relative.size())))];
    }
    return e;
}

}  // namespace grotto
