#pragma once
// Worlds and bakes for the face cache's CPU tests: voxel by voxel, at random, and
// every texel of a list of faces baked.
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/world.h"

#include <glm/vec3.hpp>

#include <functional>
#include <random>
#include <span>
#include <vector>

namespace grotto::test {
using namespace voxel;

// `size` voxels of 1 world unit from the origin, solid where `solid` says.
inline World solidWorld(glm::ivec3 size, const std::function<bool(glm::ivec3)>& solid) {
    std::vector<uint8_t> m(size_t(size.x) * size.y * size.z, 0);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                if (solid({x, y, z})) m[(size_t(z) * size.y + y) * size.x + x] = 1;
    return World::fromDense(size, m.data(), 1.0, glm::dvec3(0.0));
}

// A cube of `side` voxels, each solid with probability `density`, drawn from `rng`.
inline World randomWorld(int side, double density, std::mt19937& rng) {
    std::bernoulli_distribution fill(density);
    std::vector<bool> cells(size_t(side) * side * side);
    for (size_t k = 0; k < cells.size(); ++k) cells[k] = fill(rng);
    return solidWorld({side, side, side}, [&](glm::ivec3 v) { return cells[(size_t(v.z) * side + v.y) * side + v.x]; });
}

// Every texel of `faces` baked with `s`.
inline std::vector<FaceTexel> bakeAll(const World& w, std::span<const ExposedFace> faces, const FaceBakeSettings& s) {
    std::vector<FaceTexel> t(faces.size() * s.texelsPerSide * s.texelsPerSide);
    bakeFaces(BrickTable(w), w, faces, s, t);
    return t;
}

}  // namespace grotto::test
