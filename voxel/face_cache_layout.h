#pragma once
// The face cache laid out as the GPU reads it (shaders/shared/face_cache.h): a
// perfect hash of the bricks with exposed faces (voxel/face_brick_table.h), a
// record of masks and counts per brick, and 3 packed bytes per texel.
#include "voxel/face_cache.h"

#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace grotto::voxel {

struct FaceCacheArrays {
    std::vector<glm::uvec4> bricks;  // the bricks' table's slots (FaceBrickTable)
    std::vector<uint32_t> records;   // the table's seeds, then GROTTO_FACE_RECORD_WORDS per brick
    std::vector<uint32_t> texels;    // 3 bytes a texel one after another, faces in record order
    std::vector<uint32_t> faceOrder; // the GPU's face i is the listed face faceOrder[i]
    uint32_t texelsPerSide = 0;
    uint32_t faceCount = 0;
    uint32_t table = 0;              // the table's shape (FaceBrickTable::shape)
    // On the GPU, with each face's level (2 bits, shaders/shared/face_trace.h).
    size_t bytes() const {
        return bricks.size() * 16 + records.size() * 4 + texels.size() * 4 + (size_t(faceCount) + 15) / 16 * 4;
    }
};

// AO, sun, horizon and zenith weights in [0, 1] as 24 bits: unorms of 8, 5, 5 and
// 6 bits from bit 0 up (shaders/shared/face_cache.h).
uint32_t packFaceTexel(const FaceTexel& t);
// The step between packed values of each part (AO, sun, horizon, zenith): what the
// GPU's read of a texel may be off by is half of it.
inline constexpr double kFaceTexelStep[4] = {1.0 / 255, 1.0 / 31, 1.0 / 31, 1.0 / 63};

// `faces` as exposedFaces lists them, `texels` k x k per face in that order.
FaceCacheArrays layFaceCache(std::span<const ExposedFace> faces, std::span<const FaceTexel> texels,
                             uint32_t texelsPerSide);

// Texel `texel`'s 24 bits in packed words laid out as FaceCacheArrays::texels.
uint32_t packedTexel(std::span<const uint32_t> words, size_t texel);
// A packed texel (packFaceTexel's bits) as sums of `rays` and `sunRays` rays: what
// the GPU's tracer left, for the host's copy.
FaceTexel unpackFaceTexel(uint32_t bits, uint32_t rays, uint32_t sunRays);

// What layFaceCache's arrays for `faces` at k texels a side take, without laying
// them out (for `info` and `bench`).
size_t faceCacheGpuBytes(std::span<const ExposedFace> faces, uint32_t texelsPerSide);
size_t faceCacheGpuBytes(const ExposedFaceCount& count, uint32_t texelsPerSide);

}  // namespace grotto::voxel
