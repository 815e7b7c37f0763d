// Writes small baked face caches for fuzz_face_cache: a few worlds of each kind at
// the smallest size, baked with few rays, whole and as a part.
//   fuzz_face_cache_seeds DIR
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/face_cache_file.h"
#include "voxel/mkworld.h"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) return std::fprintf(stderr, "usage: fuzz_face_cache_seeds DIR\n"), 2;
    const std::filesystem::path dir = argv[1];
    for (const std::string kind : {"rooms", "caves", "thin"}) {
        const std::filesystem::path grid = dir / (kind + "-4.vdb");
        grotto::voxel::makeWorldFile(kind, {.size = 4}, grid);
        const grotto::voxel::World world = grotto::voxel::World::load(grid);
        std::filesystem::remove(grid);
        const grotto::voxel::BrickTable table(world);
        const auto faces = grotto::voxel::exposedFaces(table, world);
        for (uint32_t k : {1u, 2u}) {
            grotto::voxel::FaceCacheFile cache{.header = {.key = grotto::voxel::faceCacheKey(world, 4.0, k), .rays = 4,
                                                          .sunRays = 1, .totalFaces = faces.size(), .faceCount = faces.size()}};
            cache.texels.resize(cache.header.texelCount());
            grotto::voxel::bakeFaces(table, world, faces, {.texelsPerSide = k, .rays = 4, .sunRays = 1}, cache.texels);
            grotto::voxel::saveFaceCache(cache, dir / (kind + "-k" + std::to_string(k) + ".gfc"));
        }
    }
    return 0;
}
