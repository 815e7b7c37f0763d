#include "voxel/brick_table.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace grotto::voxel {

namespace {
// Above this many bricks in the bounding range the table is a hash map: a sparse
// world spread over a huge box would otherwise cost 4 bytes per empty brick.
constexpr size_t kDenseLimit = size_t(1) << 25;
constexpr double kInf = std::numeric_limits<double>::infinity();

double volume(glm::ivec3 dims) { return double(dims.x) * double(dims.y) * double(dims.z); }
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
    for (const Brick& b : world.bricks()) {  // those with solid voxels only
        const glm::ivec3 r = (b.origin >> 3) - lo_;
        const uint32_t index = uint32_t(masks_.size() / 8);
        masks_.insert(masks_.end(), b.occupancy, b.occupancy + 8);
        if (dense()) dense_[denseIndex(r)] = index;
        else sparse_[r] = index;
    }
}

void BrickTable::update(const World& world, const IndexBox& changed) {
    if (changed.empty()) return;
    const IndexBox box = world.bounds();
    if (box.empty()) {  // nothing solid is left
        *this = BrickTable(world);
        return;
    }
    // Solid bricks beyond the range: grow it, with room for a quarter more on
    // each side so a world built up edit by edit re-lays the index rarely.
    const glm::ivec3 solidLo = box.min >> 3, solidHi = box.max >> 3;
    if (dims_.x == 0 || glm::any(glm::lessThan(solidLo, lo_)) || glm::any(glm::greaterThanEqual(solidHi, lo_ + dims_))) {
        const glm::ivec3 wantLo = glm::min(solidLo, dims_.x == 0 ? solidLo : lo_);
        const glm::ivec3 wantHi = glm::max(solidHi, dims_.x == 0 ? solidHi : lo_ + dims_ - 1);
        const glm::ivec3 room = (wantHi - wantLo + 1) / 4;
        // Within the index limits, and no slack that would turn a dense table sparse.
        glm::ivec3 roomLo = glm::max(wantLo - room, glm::ivec3(-kMaxVoxelIndex >> 3));
        glm::ivec3 roomHi = glm::min(wantHi + room, glm::ivec3((kMaxVoxelIndex >> 3) - 1));
        if (volume(roomHi - roomLo + 1) > double(kDenseLimit) && volume(wantHi - wantLo + 1) <= double(kDenseLimit))
            roomLo = wantLo, roomHi = wantHi;
        reshape(roomLo, roomHi - roomLo + 1);
    }
    // The changed box's bricks: cleared, then written from the world's.
    const glm::ivec3 lo = glm::max(changed.min >> 3, lo_), hi = glm::min(changed.max >> 3, lo_ + dims_ - 1);
    std::vector<glm::ivec3> stale;
    if (dense() || volume(hi - lo + 1) <= double(sparse_.size())) {
        for (int x = lo.x; x <= hi.x; ++x)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int z = lo.z; z <= hi.z; ++z)
                    if (find({x, y, z}) != 0) stale.push_back({x, y, z});
    } else {
        for (const auto& [r, index] : sparse_) {
            const glm::ivec3 brick = lo_ + r;
            if (glm::all(glm::greaterThanEqual(brick, lo)) && glm::all(glm::lessThanEqual(brick, hi))) stale.push_back(brick);
        }
    }
    for (glm::ivec3 brick : stale) {
        freeSlots_.push_back(find(brick));
        setIndex(brick, 0);
    }
    for (const Brick& b : world.bricks(changed)) {
        const uint32_t index = newSlot();
        setIndex(b.origin >> 3, index);
        std::copy(b.occupancy, b.occupancy + 8, masks_.begin() + ptrdiff_t(index) * 8);
    }
}

void BrickTable::reshape(glm::ivec3 lo, glm::ivec3 dims) {
    // Every non-empty brick with its slot, in absolute brick coordinates.
    std::vector<std::pair<glm::ivec3, uint32_t>> entries;
    if (dense()) {
        for (int x = 0; x < dims_.x; ++x)
            for (int y = 0; y < dims_.y; ++y)
                for (int z = 0; z < dims_.z; ++z)
                    if (const uint32_t i = dense_[denseIndex({x, y, z})]) entries.push_back({lo_ + glm::ivec3(x, y, z), i});
    } else {
        for (const auto& [r, i] : sparse_) entries.push_back({lo_ + r, i});
    }
    lo_ = lo, dims_ = dims;
    dense_.clear();
    sparse_.clear();
    if (volume(dims) <= double(kDenseLimit)) dense_.assign(size_t(volume(dims)), 0);
    for (const auto& [brick, i] : entries) setIndex(brick, i);
}

void BrickTable::setIndex(glm::ivec3 brick, uint32_t index) {
    const glm::ivec3 r = brick - lo_;
    if (dense()) dense_[denseIndex(r)] = index;
    else if (index != 0) sparse_[r] = index;
    else sparse_.erase(r);
}

uint32_t BrickTable::newSlot() {
    if (!freeSlots_.empty()) {
        const uint32_t i = freeSlots_.back();
        freeSlots_.pop_back();
        return i;
    }
    masks_.resize(masks_.size() + 8);
    return uint32_t(masks_.size() / 8 - 1);
}

double BrickTable::leaveRange(glm::dvec3 p, glm::dvec3 d) const {
    if (dims_.x == 0) return -1.0;
    const glm::dvec3 lo = glm::dvec3(lo_) * 8.0, hi = glm::dvec3(lo_ + dims_) * 8.0;
    double enter = 0.0, leave = kInf;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (p[i] < lo[i] || p[i] >= hi[i]) return -1.0;  // beside the range, running along it
            continue;
        }
        double t0 = (lo[i] - p[i]) / d[i], t1 = (hi[i] - p[i]) / d[i];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
    }
    if (enter > leave) return -1.0;
    // A margin wider than the walk's own rounding (its crossings are sums), so a
    // ray that hits within the range hits at the same t as without the clip.
    return leave + 2.0 + 1e-6 * leave;
}

// Amanatides & Woo per voxel inside occupied bricks; an empty brick is crossed in
// one step by advancing every axis's crossing count to where the ray leaves it.
// With `hit`, the voxel entered, the distance and the axis crossed into it are
// kept (only a caller that needs them pays for tracking them).
template <bool kRecord>
bool BrickTable::walk(glm::dvec3 p, glm::dvec3 d, double tMax, BrickHit* hit) const {
    // Past the table's range nothing is solid: the walk ends where the ray leaves
    // it, so a radius of any length costs the world's size at most.
    tMax = std::min(tMax, leaveRange(p, d));
    if (!(tMax >= 0.0)) return false;
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
    [[maybe_unused]] double tEnter = 0.0;
    [[maybe_unused]] int axis = 0;
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
            if constexpr (kRecord) tEnter = tE, axis = e;
            continue;
        }
        if (!first && solid(b, cell)) {
            if constexpr (kRecord) *hit = {tEnter, cell, axis * 2 + (step[axis] > 0 ? 1 : 0)};
            return true;
        }
        first = false;
        const int a = tNext.x < tNext.y ? (tNext.x < tNext.z ? 0 : 2) : (tNext.y < tNext.z ? 1 : 2);
        if (tNext[a] > tMax) return false;
        if constexpr (kRecord) tEnter = tNext[a], axis = a;
        cell[a] += step[a];
        tNext[a] += tDelta[a];
        if ((cell[a] & 7) == (step[a] > 0 ? 0 : 7)) {
            brick[a] += step[a];
            b = find(brick);
        }
    }
}

bool BrickTable::hitWithin(glm::dvec3 p, glm::dvec3 d, double tMax) const {
    return walk<false>(p, d, tMax, nullptr);
}

std::optional<BrickHit> BrickTable::firstHit(glm::dvec3 p, glm::dvec3 d, double tMax) const {
    BrickHit hit;
    if (!walk<true>(p, d, tMax, &hit)) return std::nullopt;
    return hit;
}

}  // namespace grotto::voxel
