#include "voxel/face_cache.h"

#include "shaders/shared/quad.h"
#include "voxel/brick_table.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <unordered_map>

namespace grotto::voxel {

namespace {

bool solidAt(const BrickTable& table, glm::ivec3 v) {
    const uint32_t b = table.find(v >> 3);
    return b != 0 && table.solid(b, v);
}

constexpr glm::ivec3 kStep[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

}  // namespace

std::vector<glm::dvec3> daySunDirections(const SunPath& path) {
    std::vector<glm::dvec3> out;
    for (uint32_t m = 0; m < kDaySunPositions; ++m)
        out.push_back(sunDirectionAt(path, sunPositionHour(path, int(m), int(kDaySunPositions))));
    return out;
}

DayBounceSpan dayBounceSpan(double at) {
    uint32_t b = 0;
    while (b + 2 < kDayBouncePositions && at >= double(dayBouncePosition(b + 1))) ++b;
    const double lo = dayBouncePosition(b), hi = dayBouncePosition(b + 1);
    return {b, b + 1, std::clamp((at - lo) / (hi - lo), 0.0, 1.0)};
}

std::vector<ExposedFace> exposedFaces(const World& world) { return exposedFaces(BrickTable(world), world); }

std::vector<ExposedFace> exposedFaces(const BrickTable& table, const World& world) {
    std::vector<ExposedFace> faces;
    for (const Brick& b : world.bricks())
        for (int x = 0; x < 8; ++x)
            for (int y = 0; y < 8; ++y)
                for (int z = 0; z < 8; ++z) {
                    if (!((b.occupancy[x] >> (y * 8 + z)) & 1u)) continue;
                    const glm::ivec3 cell = b.origin + glm::ivec3(x, y, z);
                    for (uint8_t d = 0; d < 6; ++d)
                        if (!solidAt(table, cell + kStep[d])) faces.push_back({cell, d});
                }
    // Bricks come in the grid's order: sort into the documented one.
    std::sort(faces.begin(), faces.end());  // bricks come in the grid's order
    return faces;
}

std::vector<ExposedFace> exposedFacesAfterEdit(const BrickTable& table, const World& world,
                                               const std::vector<ExposedFace>& before, const IndexBox& changed) {
    if (changed.empty()) return before;
    const glm::ivec3 lo = changed.min - 1, hi = changed.max + 1;
    const IndexBox near{lo, hi};
    // A box holding more cells than the world's bricks do: the world's own list.
    const glm::dvec3 extent = glm::dvec3(hi - lo) + 1.0;
    if (extent.x * extent.y * extent.z > 512.0 * double(world.bricks().size()) + 4096.0) return exposedFaces(table, world);
    std::vector<ExposedFace> fresh;  // listed in order: x, then y, then z, then direction
    for (int x = lo.x; x <= hi.x; ++x)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int z = lo.z; z <= hi.z; ++z) {
                const glm::ivec3 cell(x, y, z);
                if (!solidAt(table, cell)) continue;
                for (uint8_t d = 0; d < 6; ++d)
                    if (!solidAt(table, cell + kStep[d])) fresh.push_back({cell, d});
            }
    std::vector<ExposedFace> now;
    now.reserve(before.size() + fresh.size());
    auto kept = fresh.begin();
    for (const ExposedFace& f : before) {
        if (near.contains(f.cell)) continue;
        while (kept != fresh.end() && *kept < f) now.push_back(*kept++);
        now.push_back(f);
    }
    now.insert(now.end(), kept, fresh.end());
    return now;
}

ExposedFaceCount countExposedFaces(const World& world) {
    // A brick's word x holds its voxels (x, y, z) at bit y * 8 + z, as in the grid.
    struct KeyHash {
        size_t operator()(glm::ivec3 b) const {
            return size_t(uint32_t(b.x)) * 0x9E3779B97F4A7C15ull ^ size_t(uint32_t(b.y)) * 0xC2B2AE3D27D4EB4Full ^
                   size_t(uint32_t(b.z)) * 0x165667B19E3779F9ull;
        }
    };
    const std::vector<Brick>& bricks = world.bricks();
    std::unordered_map<glm::ivec3, const uint64_t*, KeyHash> byKey;
    byKey.reserve(bricks.size());
    for (const Brick& b : bricks) byKey[b.origin >> 3] = b.occupancy;
    static constexpr uint64_t kEmpty[8] = {};
    auto words = [&](glm::ivec3 key) {
        const auto it = byKey.find(key);
        return it == byKey.end() ? kEmpty : it->second;
    };
    constexpr uint64_t kLowZ = 0x0101010101010101ull, kHighZ = kLowZ << 7;
    ExposedFaceCount count;
    for (const Brick& b : bricks) {
        const glm::ivec3 key = b.origin >> 3;
        const uint64_t* m = b.occupancy;
        const uint64_t *px = words(key + glm::ivec3(1, 0, 0)), *nx = words(key - glm::ivec3(1, 0, 0));
        const uint64_t *py = words(key + glm::ivec3(0, 1, 0)), *ny = words(key - glm::ivec3(0, 1, 0));
        const uint64_t *pz = words(key + glm::ivec3(0, 0, 1)), *nz = words(key - glm::ivec3(0, 0, 1));
        uint64_t faces = 0;
        for (int x = 0; x < 8; ++x) {
            // Each neighbour's solidity moved onto the voxel it borders.
            const uint64_t right = x < 7 ? m[x + 1] : px[0], left = x > 0 ? m[x - 1] : nx[7];
            const uint64_t up = (m[x] >> 8) | (py[x] << 56), down = (m[x] << 8) | (ny[x] >> 56);
            const uint64_t front = ((m[x] >> 1) & ~kHighZ) | ((pz[x] & kLowZ) << 7);
            const uint64_t back = ((m[x] << 1) & ~kLowZ) | ((nz[x] & kHighZ) >> 7);
            for (uint64_t open : {right, left, up, down, front, back}) faces += uint64_t(std::popcount(m[x] & ~open));
        }
        count.faces += faces;
        count.bricks += faces > 0;
    }
    return count;
}

SkyWeights skyWeights(double up) {
    if (up < 0.0) return {0.8f, 0.0f};  // the darker horizon below it
    const double s = std::sqrt(std::min(up, 1.0));
    return {float(1.0 - s), float(s)};
}

glm::dvec3 faceNormal(uint8_t dir) { return glm::dvec3(kStep[dir]); }

glm::dvec3 texelPoint(const ExposedFace& face, uint32_t k, uint32_t i, uint32_t j) {
    const int axis = int(gpu::faceAxis(face.dir));
    glm::dvec3 p(face.cell);
    p[axis] += gpu::facePositive(face.dir) ? 1.0 : 0.0;
    p[int(gpu::faceUAxis(face.dir))] += (i + 0.5) / k;
    p[int(gpu::faceVAxis(face.dir))] += (j + 0.5) / k;
    return p;
}

}  // namespace grotto::voxel
