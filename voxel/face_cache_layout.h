#pragma once
// The face cache laid out as the GPU reads it (shaders/shared/face_cache.h): a
// perfect hash of the bricks with exposed faces (voxel/face_brick_table.h), a
// record of masks and counts per brick, and 6 packed bytes per texel.
#include "voxel/face_cache.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace grotto::voxel {

struct FaceCacheArrays {
    std::vector<glm::uvec4> bricks;  // the bricks' table's slots (FaceBrickTable)
    std::vector<uint32_t> records;   // the table's seeds, then GROTTO_FACE_RECORD_WORDS per brick
    std::vector<uint32_t> texels;    // 6 bytes a texel in pairs of 3 words, faces in record order
    bool fullLight = false;          // light words hold the full light, not the sky's weights
    std::vector<uint32_t> faceOrder; // the GPU's face i is the listed face faceOrder[i]
    uint32_t texelsPerSide = 0;
    uint32_t faceCount = 0;
    uint32_t table = 0;              // the table's shape (FaceBrickTable::shape)
    // Where `texels` goes on past the texels with each face's material id, a byte
    // a face in the GPU's order, four a word (appendFaceMaterials): what a ray that
    // meets a face needs to know the light the face sends. 0: not there.
    uint32_t materialsFirst = 0;
    // Where `texels` goes on with each texel's day's sun bits (FaceTexel::daySun),
    // a word a texel in the texels' order (appendDaySun). 0: not there.
    uint32_t daySunFirst = 0;
    // Full light over the day (appendDayLight): where `texels` goes on with each
    // texel's sky weights (two halfs a word, in the texels' order), and then
    // with each face's kDayLightWords day words (RGB9E5, faces in record
    // order). 0: not there; the light words then hold the glowing faces' light alone.
    uint32_t dayLightFirst = 0, dayFacesFirst = 0;
    // On the GPU, with each face's level (2 bits, shaders/shared/face_trace.h).
    size_t bytes() const {
        return bricks.size() * 16 + records.size() * 4 + texels.size() * 4 + (size_t(faceCount) + 15) / 16 * 4;
    }
};

// A texel as the GPU keeps it (shaders/shared/face_cache.h): x AO and sun as 8-bit
// unorms, y the light word, the horizon and zenith weights per ray as halfs or,
// with `fullLight`, the light as RGB9E5.
glm::uvec2 packFaceTexel(const FaceTexel& t, bool fullLight = false);
// What the GPU's read of each part (AO, sun, horizon, zenith) may be off by, at
// most: half the step of AO and sun; a half's rounding of a weight up to 1.
inline constexpr double kFaceTexelStep[4] = {1.0 / 255, 1.0 / 255, 1.0 / 2048, 1.0 / 2048};
// The relative error of an RGB9E5 light channel against the largest channel.
inline constexpr double kFaceLightStep = 1.0 / 512;

// `faces` as exposedFaces lists them, `texels` k x k per face in that order.
// `storage`: memory the texel words may take (a live cache's last layout's): a
// fresh array of tens of megabytes costs an edit more than filling it.
FaceCacheArrays layFaceCache(std::span<const ExposedFace> faces, std::span<const FaceTexel> texels,
                             uint32_t texelsPerSide, bool fullLight = false, std::vector<uint32_t> storage = {});

// Texel `texel`'s bits in packed words laid out as FaceCacheArrays::texels.
glm::uvec2 packedTexel(std::span<const uint32_t> words, size_t texel);
// A packed texel (packFaceTexel's bits) as sums of `rays` and `sunRays` rays: what
// the GPU's tracer left, for the host's copy.
FaceTexel unpackFaceTexel(glm::uvec2 bits, uint32_t rays, uint32_t sunRays, bool fullLight = false);

// Appends each face's material id in `world` to a.texels (a.materialsFirst).
void appendFaceMaterials(FaceCacheArrays& a, std::span<const ExposedFace> faces, const World& world);
// Appends each texel's day's sun bits, `texels` as layFaceCache took them, to
// a.texels (a.daySunFirst): 4 bytes a texel.
void appendDaySun(FaceCacheArrays& a, std::span<const FaceTexel> texels);
// Appends each texel's sky weights, then each face's day words (`dayLight`,
// kDayLightWords a face in `faces`' order) to a.texels (a.dayLightFirst,
// a.dayFacesFirst): 4 bytes a texel and 72 a face.
void appendDayLight(FaceCacheArrays& a, std::span<const FaceTexel> texels, std::span<const glm::vec3> dayLight);

// What layFaceCache's arrays for `faces` at k texels a side take, without laying
// them out (for `info` and `bench`); with `daySun`, appendDaySun's words too,
// with `dayLight` appendDayLight's.
size_t faceCacheGpuBytes(std::span<const ExposedFace> faces, uint32_t texelsPerSide, bool daySun = false,
                         bool dayLight = false);
size_t faceCacheGpuBytes(const ExposedFaceCount& count, uint32_t texelsPerSide, bool daySun = false, bool dayLight = false);

}  // namespace grotto::voxel
