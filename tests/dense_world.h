#pragma once
// A world made voxel by voxel, for tests that need exact geometry: `size` voxels
// of 1 world unit from the origin, `fill(x, y, z)` giving each one's material id.
#include "voxel/world.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace grotto::voxel::test {

// `desc`: the rest of the world file (its lighting, say), with these materials.
template <class Fill>
World denseWorld(glm::ivec3 size, std::vector<Material> materials, Fill fill, WorldDesc desc = {}) {
    std::vector<uint8_t> ids(size_t(size.x) * size.y * size.z);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) ids[(size_t(z) * size.y + y) * size.x + x] = uint8_t(fill(x, y, z));
    desc.materials = std::move(materials);
    return World::fromDense(size, ids.data(), 1.0, glm::dvec3(0.0), desc);
}

}  // namespace grotto::voxel::test
