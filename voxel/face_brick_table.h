#pragma once
// The face cache's table of bricks as the GPU reads it (shaders/shared/face_cache.h):
// a perfect hash, so a lookup is two loads whatever it finds. Each bucket of about
// four bricks gets the first seed that sends all of them to free slots, the
// largest buckets first while most slots are free.
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace grotto::voxel {

struct FaceBrickTable {
    std::vector<glm::uvec4> slots;  // (brick x, y, z, its index + 1); 0 = free
    std::vector<uint32_t> seeds;    // per bucket
    uint32_t shape = 0;             // slots << 5 | log2(buckets): faceCacheTable()
};

// bricks[i]'s slot holds (brick, i + 1). The bricks must be distinct.
FaceBrickTable layFaceBrickTable(std::span<const glm::ivec3> bricks);

// The bytes layFaceBrickTable's slots and seeds take for `bricks` bricks.
size_t faceBrickTableBytes(size_t bricks);

}  // namespace grotto::voxel
