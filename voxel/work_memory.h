#pragma once
// What a world's everyday work takes in memory at its peak, estimated before it is
// done: the world as loaded, meshed as a renderer uploads it (every level of
// detail: voxel::LiveMesh and the copy of its chunks `info` counts from; a
// renderer's scene is uploaded from the chunks themselves, engine/scene/scene_memory.h),
// and the exposed-face count `info` and `bake` make beside it. `grotto info`
// does exactly this work; a render adds its GPU scene (docs/formats.md).
#include "voxel/world.h"

#include <algorithm>
#include <cstdint>
#include <string>

namespace grotto::voxel {

struct WorkMemory {
    uint64_t readBytes = 0;  // reading the file: its bytes and the voxels parsed from them, then the grid built
    uint64_t gridBytes = 0;  // the solid and material grids
    uint64_t meshBytes = 0;  // beside them, the mesh at its peak: while welded, copied, or faces counted
    uint64_t quads = 0;      // every level's
    bool complete = true;    // false: counting stopped past stopAbove; total() is a lower bound
    uint64_t total() const { return std::max(readBytes, gridBytes + meshBytes); }
};

// Meshes every chunk once more to count it (memory bounded by a chunk per
// thread), stopping once the estimate passes `stopAbove`.
WorkMemory estimateWorkMemory(const World& world, uint64_t stopAbove = UINT64_MAX);

// The estimate, when it is within the world's memory budget (or the address
// space left); else throws grotto::Error (input) naming the world's grid file:
// before the work, not after.
WorkMemory requireWorkFits(const World& world);

// The world's memory budget, or the address space this process may still map if less.
uint64_t budgetRoom(const World& world);
// The budget's refusal: grotto::Error (input) naming the world's grid file, saying
// "<needs>, more than the memory budget of B MiB" (or the address space left).
[[noreturn]] void refuseOverBudget(const World& world, const std::string& needs);
std::string mibText(uint64_t bytes);  // "12.3 MiB"

}  // namespace grotto::voxel
