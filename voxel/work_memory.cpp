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

std::string mibText(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / (1 << 20));
    return text;
}

uint64_t budgetRoom(const World& world) { return memoryRoom(world.desc().memoryBudgetBytes); }

void refuseOverBudget(const World& world, const std::string& needs) {
    const size_t budget = world.desc().memoryBudgetBytes, room = memoryRoom(budget);
    throw Error(world.desc().gridFile.string(),
                needs + ", more than the " + (room < budget ? "" : "memory budget of ") + mibText(room) +
                    (room < budget ? " of address space this process may still map (ulimit -v)" : ""),
                "raise 'memory_budget_mib' in a world file naming it, or hide layers in MagicaVoxel");
}

WorkMemory requireWorkFits(const World& world) {
    const uint64_t room = budgetRoom(world);
    const WorkMemory estimate = estimateWorkMemory(world, room);
    if (estimate.complete && estimate.total() <= room) return estimate;
    const std::string grids = "(grids " + mibText(estimate.gridBytes);
    refuseOverBudget(world, estimate.complete ? "loading and meshing it needs an estimated " + mibText(estimate.total()) + " " +
                                                    grids + ", a mesh of " + std::to_string(estimate.quads) + " quads " +
                                                    mibText(estimate.meshBytes) + ")"
                                              // counting stopped there
                                              : "loading and meshing it needs at least an estimated " + mibText(estimate.total()) +
                                                    " " + grids + ", and " + mibText(estimate.meshBytes) +
                                                    " of mesh counted before it stopped)");
}

}  // namespace grotto::voxel
