#pragma once
// A baked face cache on disk (`grotto bake`): the texels of a run of the world's
// exposed faces (all of them, or part K of N for a farm), tied to the world by a
// hash of its solid voxels and to the settings that shape the texels (AO radius
// in voxels, texels per face side, the sun). The faces themselves are not stored:
// the world lists them (exposedFaces), and the hash says it is the same world.
// Parts joined in order are byte for byte the file one bake of the whole writes.
#include "voxel/face_cache.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace grotto::voxel {

// What a bake's texels depend on besides the voxels.
struct FaceCacheKey {
    uint64_t voxelHash = 0;      // solidVoxelHash of the world
    double radiusVoxels = 0.0;   // AO's R over the voxel size
    uint32_t texelsPerSide = 0;
    glm::dvec3 sunDirection{0.0};
    double sunAngleDegrees = 0.0;
    bool operator==(const FaceCacheKey&) const = default;
};

struct FaceCacheFile {
    FaceCacheKey key;
    uint64_t totalFaces = 0;       // exposed faces in the world
    uint64_t firstFace = 0;        // this file's run: faces [first, first + count)
    std::vector<FaceTexel> texels; // count x k x k, as bakeFaces lays them out
    uint64_t faceCount() const { return texels.size() / (uint64_t(key.texelsPerSide) * key.texelsPerSide); }
};

// The key a bake of `world` with AO radius `radius` (world units) and k texels a
// side has: the world's lighting gives the sun.
FaceCacheKey faceCacheKey(const World& world, double radius, uint32_t texelsPerSide);

// A hash of the world's solid voxels (not materials: no texel depends on them),
// the same whatever order the grid keeps its bricks in.
uint64_t solidVoxelHash(const World& world);

// Written atomically. Throws grotto::Error on a failed write.
void saveFaceCache(const FaceCacheFile& cache, const std::filesystem::path& path);
// Throws grotto::Error (input) naming the file and field for anything malformed:
// sizes are checked against the file's before anything is allocated.
FaceCacheFile loadFaceCache(const std::filesystem::path& path);
// Throws grotto::Error (input) naming `path` and the first field in which `cache`
// differs from what `expected` and the world's face count require.
void requireMatchingBake(const FaceCacheFile& cache, const FaceCacheKey& expected, uint64_t totalFaces,
                         const std::filesystem::path& path);
// Parts of one bake, in any order, joined: they must share the key and cover
// every face exactly once. Throws grotto::Error (input) naming the part at fault.
FaceCacheFile mergeFaceCaches(std::vector<FaceCacheFile> parts, const std::vector<std::filesystem::path>& paths);

}  // namespace grotto::voxel
