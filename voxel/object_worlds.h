#pragma once
// The voxels of a world's objects: each a World of its own, loaded like the
// world's grid (or generated), with the world's palette and memory budget.
// OpenVDB-free interface.
#include "voxel/world.h"

#include <vector>

namespace grotto::voxel {

// One World per entry of desc.objects, in order. Throws grotto::Error (input)
// naming the world file and the object's field for a grid that cannot be read, a
// generator's bad options, a generated object past the memory budget, or an
// object with no solid voxels.
std::vector<World> loadObjectWorlds(const WorldDesc& desc);

// Refuses (as loadObjectWorlds would) a generated object whose estimated memory,
// from its kind and size alone, passes desc.memoryBudgetBytes: cheap, so
// World::load checks it before reading any grid.
void requireObjectsFit(const WorldDesc& desc);

}  // namespace grotto::voxel
