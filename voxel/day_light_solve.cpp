#include "voxel/day_light_solve.h"

#include "voxel/luminance.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

namespace grotto::voxel {

void mergeByFace(FaceRow& row) {
    std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    size_t kept = 0;
    for (size_t i = 0; i < row.size(); ++i) {
        if (kept > 0 && row[kept - 1].first == row[i].first) row[kept - 1].second += row[i].second;
        else row[kept++] = row[i];
    }
    row.resize(kept);
    row.shrink_to_fit();
}

DaySources daySources(std::span<const ExposedFace> faces, uint32_t k, std::span<const FaceTexel> texels,
                      const SunPath& path, const std::function<glm::vec3(size_t face)>& albedo) {
    constexpr uint32_t W = kDayLightWords;
    const size_t perFace = size_t(k) * k;
    const std::vector<glm::dvec3> toSun = daySunDirections(path);
    DaySources s;
    s.albedo.resize(faces.size());
    s.direct.assign(faces.size() * W, 0.0f);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, faces.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t f = r.begin(); f < r.end(); ++f) {
            s.albedo[f] = albedo(f);
            float* d = &s.direct[f * W];
            const glm::dvec3 n = faceNormal(faces[f].dir);
            for (size_t t = f * perFace; t < (f + 1) * perFace; ++t) {
                const FaceTexel& x = texels[t];
                const float samples = float(std::max(x.samples, 1u));
                d[0] += x.skyZenith / samples / float(perFace), d[1] += x.skyHorizon / samples / float(perFace);
                for (uint32_t b = 0; b < kDayBouncePositions; ++b) {
                    const uint32_t position = dayBouncePosition(b);
                    if ((x.daySun >> position) & 1u)
                        d[2 + b] += float(std::max(glm::dot(n, toSun[position]), 0.0)) / float(perFace);
                }
            }
        }
    });
    return s;
}

uint32_t solveDayLight(std::span<const uint32_t> relit, std::span<const FaceRow> rows, const DaySources& sources,
                       double tolerance, uint32_t maxPasses, std::span<glm::vec3> dayLight) {
    constexpr uint32_t W = kDayLightWords;
    const size_t faces = sources.albedo.size();
    std::vector<glm::vec3> sent(faces * W), next(relit.size() * W);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, faces, 1024), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t f = r.begin(); f < r.end(); ++f)
            for (uint32_t w = 0; w < W; ++w) sent[f * W + w] = daySent(sources, dayLight, f, w);
    });
    // A word's change counts against itself, down to a floor far below what its
    // source sends on average: dim faces converge too.
    std::array<double, W> floors{};
    for (size_t f = 0; f < faces; ++f)
        for (uint32_t w = 0; w < W; ++w)
            floors[w] += luminance(glm::dvec3(sources.albedo[f])) * sources.direct[f * W + w] / double(faces);
    for (double& f : floors) f = std::max(f, 1e-30) * 1e-4;
    uint32_t passes = 0;
    for (; passes < maxPasses; ++passes) {
        const double change = tbb::parallel_reduce(
            tbb::blocked_range<size_t>(0, relit.size(), 256), 0.0,
            [&](const tbb::blocked_range<size_t>& r, double worst) {
                for (size_t n = r.begin(); n < r.end(); ++n) {
                    std::array<glm::vec3, W> sum{};
                    for (const auto& [face, weight] : rows[n]) {
                        const glm::vec3* from = &sent[size_t(face) * W];
                        for (uint32_t w = 0; w < W; ++w) sum[w] += weight * from[w];
                    }
                    const glm::vec3* was = &dayLight[size_t(relit[n]) * W];
                    for (uint32_t w = 0; w < W; ++w) {
                        next[n * W + w] = sum[w];
                        const double grown = std::abs(luminance(glm::dvec3(sum[w] - was[w])));
                        worst = std::max(worst, grown / std::max(luminance(glm::dvec3(sum[w])), floors[w]));
                    }
                }
                return worst;
            },
            [](double a, double b) { return std::max(a, b); });
        tbb::parallel_for(tbb::blocked_range<size_t>(0, relit.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t n = r.begin(); n < r.end(); ++n)
                for (uint32_t w = 0; w < W; ++w) {
                    const size_t f = relit[n];
                    dayLight[f * W + w] = next[n * W + w];
                    sent[f * W + w] = daySent(sources, dayLight, f, w);
                }
        });
        if (change < tolerance) return passes + 1;
    }
    return passes;
}

}  // namespace grotto::voxel
