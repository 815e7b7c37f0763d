#include "voxel/work_memory.h"

#include "grotto/error.h"
#include "voxel/mesh_footprint.h"
#include "voxel/solid.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace grotto::voxel {

WorkMemory estimateWorkMemory(const World& world, uint64_t stopAbove) {
    const WorldStats s = world.stats();
    const MeshFootprint mesh = countMeshFootprint(world, {.coarseLevels = kMaxCoarseLevels},
                                                  stopAbove > s.hostBytes ? stopAbove - s.hostBytes : 0);
    // countExposedFaces: the bricks listed, and a hash map of them (a node with
    // its cached hash, and a bucket, each).
    const uint64_t faceCount = heapBytes(s.bricks * sizeof(Brick)) + s.bricks * (heapBytes(40) + 8);
    WorkMemory m;
    // A .vox's voxels take 4 bytes each, as in the file, and live while the
    // file's bytes are parsed and while the material grid is built from them.
    std::error_code ec;
    const uint64_t file = std::filesystem::file_size(world.desc().gridFile, ec);
    const auto& materials = world.impl().materials;
    m.readBytes = ec ? 0 : file + std::max<uint64_t>(file, materials ? materials->memUsage() : 0);
    m.gridBytes = s.hostBytes;
    // The LiveMesh holds every chunk's boundary corners while it welds; its
    // copy outlives it; the face count reuses its memory once it is gone.
    m.meshBytes = std::max({mesh.liveBytes + std::max(mesh.cornerBytes, mesh.listBytes), mesh.listBytes + faceCount});
    m.quads = mesh.quads;
    m.complete = mesh.complete;
    return m;
}

WorkMemory requireWorkFits(const World& world) {
    const size_t budget = world.desc().memoryBudgetBytes, room = memoryRoom(budget);
    const WorkMemory estimate = estimateWorkMemory(world, room);
    if (estimate.complete && estimate.total() <= room) return estimate;
    char counted[160];
    if (estimate.complete)
        std::snprintf(counted, sizeof counted, "an estimated %.1f MiB (grids %.1f MiB, a mesh of %llu quads %.1f MiB)",
                      double(estimate.total()) / (1 << 20), double(estimate.gridBytes) / (1 << 20),
                      (unsigned long long)estimate.quads, double(estimate.meshBytes) / (1 << 20));
    else  // counting stopped there
        std::snprintf(counted, sizeof counted, "at least an estimated %.1f MiB (grids %.1f MiB, and %.1f MiB of mesh counted before it stopped)",
                      double(estimate.total()) / (1 << 20), double(estimate.gridBytes) / (1 << 20),
                      double(estimate.meshBytes) / (1 << 20));
    char figures[400];
    std::snprintf(figures, sizeof figures, "loading and meshing it needs %s, more than the %s%.1f MiB%s", counted,
                  room < budget ? "" : "memory budget of ", double(room) / (1 << 20),
                  room < budget ? " of address space this process may still map (ulimit -v)" : "");
    throw Error(world.desc().gridFile.string(), figures,
                "raise 'memory_budget_mib' in a world file naming it, or hide layers in MagicaVoxel");
}

}  // namespace grotto::voxel
