#pragma once
// A baked face cache on disk (`grotto bake`): the texels of a run of the world's
// exposed faces (all of them, or part K of N for a farm), tied to the world by a
// hash of its solid voxels and to the settings that shape the texels (AO radius
// in voxels, texels per face side, the sun). The faces themselves are not stored:
// the world lists them (exposedFaces), and the hash says it is the same world.
// Parts joined in order are byte for byte the file one bake of the whole writes.
#include "voxel/daylight.h"
#include "voxel/face_cache.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

namespace grotto::voxel {

// What a bake's texels depend on besides the voxels.
struct FaceCacheKey {
    uint64_t voxelHash = 0;      // solidVoxelHash of the world
    double radiusVoxels = 0.0;   // AO's R over the voxel size
    uint32_t texelsPerSide = 0;
    glm::dvec3 sunDirection{0.0};  // 0 with the day's sun
    double sunAngleDegrees = 0.0;
    // The day's sun: its path, whose kDaySunPositions positions each texel holds
    // a bit for (FaceTexel::daySun); none for one fixed sun.
    std::optional<SunPath> day;
    // With full light (lighting.ambient.from full): a hash of all the light
    // depends on (the sky, the sun, every material's albedo and emission); 0: none.
    uint64_t lightHash = 0;
    bool operator==(const FaceCacheKey&) const = default;
};

// A bake's header: what its texels were baked for and with, and the run of faces
// the file holds.
struct FaceCacheHeader {
    FaceCacheKey key;
    uint32_t rays = 0;         // cosine-weighted rays a texel (AO and sky)
    uint32_t sunRays = 0;      // rays a texel toward the sun (0 with the day's sun)
    uint64_t totalFaces = 0;   // exposed faces in the world
    uint64_t firstFace = 0;    // this file's run: faces [first, first + count)
    uint64_t faceCount = 0;
    uint64_t texelCount() const { return faceCount * key.texelsPerSide * key.texelsPerSide; }
};

// Does the file keep full light over the day (each face's day words, face_cache.h)?
inline bool hasDayLight(const FaceCacheHeader& h) { return h.key.day && h.key.lightHash != 0; }

struct FaceCacheFile {
    FaceCacheHeader header;
    std::vector<FaceTexel> texels; // header.texelCount(), as bakeFaces lays them out
    std::vector<glm::vec3> dayLight;  // with hasDayLight: kDayLightWords a face (voxel/light_bake.h)
};

// The key a bake of `world` with AO radius `radius` (world units) and k texels a
// side has: the world's lighting gives the sun, and whether the light is baked.
FaceCacheKey faceCacheKey(const World& world, double radius, uint32_t texelsPerSide);

// A hash of the world's solid voxels (not materials: no texel depends on them),
// the same whatever order the grid keeps its bricks in.
uint64_t solidVoxelHash(const World& world);
// The lightHash of a world whose light is baked (nonzero).
uint64_t lightHash(const World& world);

// Written atomically. Throws grotto::Error on a failed write.
void saveFaceCache(const FaceCacheFile& cache, const std::filesystem::path& path);

// Reading is in two steps, so that a header which does not match (another
// world's, a bigger world's, other settings) is refused before its texels cost
// anything. Each throws grotto::Error (input) naming the file and the field.
// The header, checked in itself and against the file's size, which must be
// exactly its texels' (so the texels it claims are there to be read).
FaceCacheHeader readFaceCacheHeader(const std::filesystem::path& path);
// The texels `header` (read from `path`) claims, read a block at a time into
// `texels` (header.texelCount() of them), each checked.
void readFaceCacheTexels(const std::filesystem::path& path, const FaceCacheHeader& header, std::span<FaceTexel> texels);
// With hasDayLight(header): each face's day words, after the texels
// (header.faceCount x kDayLightWords), each checked.
void readFaceCacheDayLight(const std::filesystem::path& path, const FaceCacheHeader& header, std::span<glm::vec3> dayLight);
// All three: the whole file.
FaceCacheFile loadFaceCache(const std::filesystem::path& path);

// Throws grotto::Error (input) naming `path` and the first field in which
// `header` differs from what `expected` and the world's face count require, or
// when it holds only a part of the bake.
void requireMatchingBake(const FaceCacheHeader& header, const FaceCacheKey& expected, uint64_t totalFaces,
                         const std::filesystem::path& path);
// The header of `path`, required to be a whole bake of `world` at AO radius
// `radius` (world units; any k) with `totalFaces` exposed faces.
FaceCacheHeader requireBakeOf(const World& world, double radius, uint64_t totalFaces, const std::filesystem::path& path);

// Parts of one bake, in any order, joined. Every part's header is read and
// compared first: they must agree in every setting they record (the part unlike
// the most others is named, with the setting) and cover every face exactly once;
// only then are the texels read, straight into the whole. Throws grotto::Error
// (input) naming the part at fault.
FaceCacheFile mergeFaceCaches(const std::vector<std::filesystem::path>& parts);

}  // namespace grotto::voxel
