#include "voxel/face_cache.h"

#include "shaders/shared/quad.h"
#include "voxel/brick_table.h"

#include <algorithm>
#include <cmath>

namespace grotto::voxel {

namespace {

bool solidAt(const BrickTable& table, glm::ivec3 v) {
    const uint32_t b = table.find(v >> 3);
    return b != 0 && table.solid(b, v);
}

constexpr glm::ivec3 kStep[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

}  // namespace

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
