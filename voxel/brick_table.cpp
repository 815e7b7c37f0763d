#include "voxel/brick_table.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grotto::voxel {

namespace {
// Above this many bricks in the bounding range the table is a hash map: a sparse
// world spread over a huge box would otherwise cost 4 bytes per empty brick.
constexpr size_t kDenseLimit = size_t(1) << 25;
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

BrickTable::BrickTable(const World& world) {
    masks_.assign(8, 0);
    const IndexBox box = world.bounds();
    if (box.empty()) return;
    lo_ = box.min >> 3;  // arithmetic shift: floor division for negative indices too
    dims_ = (box.max >> 3) - lo_ + 1;
    // In double: the product of the extents can exceed 64 bits.
    const double range = double(dims_.x) * double(dims_.y) * double(dims_.z);
    if (range <= double(kDenseLimit)) dense_.assign(size_t(range), 0);
    for (const Brick& b : world.bricks()) {
        bool any = false;
        for (uint64_t w : b.occupancy) any = any || w != 0;
        if (!any) continue;
        const glm::ivec3 r = (b.origin >> 3) - lo_;
        const uint32_t index = uint32_t(masks_.size() / 8);
        masks_.insert(masks_.end(), b.occupancy, b.occupancy + 8);
        if (dense()) dense_[denseIndex(r)] = index;
        else sparse_[r] = index;
    }
}

// Amanatides & Woo per voxel inside occupied bricks; an empty brick is crossed in
// one step by advancing every axis's crossing count to where the ray leaves it.
bool BrickTable::hitWithin(glm::dvec3 p, glm::dvec3 d, double tMax) const {
    glm::ivec3 cell(std::floor(p.x), std::floor(p.y), std::floor(p.z)), step;
    glm::dvec3 tNext, tDelta;
    for (int i = 0; i < 3; ++i) {
        if (d[i] > 0) {
            step[i] = 1, tDelta[i] = 1.0 / d[i], tNext[i] = (cell[i] + 1 - p[i]) * tDelta[i];
        } else if (d[i] < 0) {
            step[i] = -1, tDelta[i] = -1.0 / d[i], tNext[i] = (p[i] - cell[i]) * tDelta[i];
        } else {
            step[i] = 0, tDelta[i] = kInf, tNext[i] = kInf;
        }
    }
    glm::ivec3 brick = cell >> 3;
    uint32_t b = find(brick);
    bool first = true;
    while (true) {
        if (b == 0) {
            // An empty brick: move every axis to where the ray leaves it, at once.
            glm::ivec3 steps;
            glm::dvec3 tLeave;
            for (int i = 0; i < 3; ++i) {
                steps[i] = step[i] > 0 ? brick[i] * 8 + 8 - cell[i] : cell[i] - brick[i] * 8 + 1;
                tLeave[i] = step[i] == 0 ? kInf : tNext[i] + (steps[i] - 1) * tDelta[i];
            }
            const int e = tLeave.x < tLeave.y ? (tLeave.x < tLeave.z ? 0 : 2) : (tLeave.y < tLeave.z ? 1 : 2);
            const double tE = tLeave[e];
            if (tE > tMax) return false;
            for (int i = 0; i < 3; ++i) {
                if (i == e || step[i] == 0 || tNext[i] >= tE) continue;
                // Crossings of axis i strictly before tE, staying inside this brick.
                const double k = std::clamp(std::ceil((tE - tNext[i]) / tDelta[i]), 0.0, double(steps[i] - 1));
                cell[i] += step[i] * int(k);
                tNext[i] += k * tDelta[i];
            }
            cell[e] += step[e] * steps[e];
            tNext[e] = tE + tDelta[e];
            brick[e] += step[e];
            b = find(brick);
            first = false;
            continue;
        }
        if (!first && solid(b, cell)) return true;
        first = false;
        const int a = tNext.x < tNext.y ? (tNext.x < tNext.z ? 0 : 2) : (tNext.y < tNext.z ? 1 : 2);
        if (tNext[a] > tMax) return false;
        cell[a] += step[a];
        tNext[a] += tDelta[a];
        if ((cell[a] & 7) == (step[a] > 0 ? 0 : 7)) {
            brick[a] += step[a];
            b = find(brick);
        }
    }
}

}  // namespace grotto::voxel
