#include "engine/frame/history_boxes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grotto {
namespace {

voxel::WorldBox unionOf(const voxel::WorldBox& a, const voxel::WorldBox& b) {
    return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

double volume(const voxel::WorldBox& b) {
    const glm::dvec3 d = b.max - b.min;
    return d.x * d.y * d.z;
}

}  // namespace

double aoReach(const AoOptions& ao) {
    const double r = ao.estimator.radius;
    switch (ao.method) {
    case AoMethod::Ssao: return 1.25 * r;
    case AoMethod::Hbao: return r;
    default: return r * std::max(1.0, double(ao.estimator.radiusMultiplier));
    }
}

void HistoryBoxes::add(const voxel::WorldBox& box) {
    if (box.empty()) return;
    boxes_.push_back(box);
    if (boxes_.size() <= GROTTO_TEMPORAL_MAX_BOXES) return;
    size_t bestI = 0, bestJ = 1;
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < boxes_.size(); ++i)
        for (size_t j = i + 1; j < boxes_.size(); ++j) {
            const double added = volume(unionOf(boxes_[i], boxes_[j])) - volume(boxes_[i]) - volume(boxes_[j]);
            if (added < best) best = added, bestI = i, bestJ = j;
        }
    boxes_[bestI] = unionOf(boxes_[bestI], boxes_[bestJ]);
    boxes_.erase(boxes_.begin() + std::ptrdiff_t(bestJ));
}

void HistoryBoxes::write(const glm::dvec3& camera, double margin, gpu::TemporalConstants& t) const {
    t.boxCount = uint32_t(boxes_.size());
    for (size_t i = 0; i < boxes_.size(); ++i) {
        const voxel::WorldBox g = boxes_[i].grown(margin);
        // Rounded outwards to float: never a point of the box left out.
        const glm::dvec3 lo = g.min - camera, hi = g.max - camera;
        for (int k = 0; k < 3; ++k) {
            t.boxMin[i][k] = std::nextafter(float(lo[k]), -std::numeric_limits<float>::infinity());
            t.boxMax[i][k] = std::nextafter(float(hi[k]), std::numeric_limits<float>::infinity());
        }
    }
}

}  // namespace grotto
