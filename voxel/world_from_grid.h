#pragma once
// A World from an OpenVDB grid a program made itself (a game's own grid). The one
// public header that needs OpenVDB: World users who load files never include it.
#include "voxel/world.h"

#include <openvdb/Grid.h>

namespace grotto::voxel {

// The grid is copied (later changes to it do not reach the world, nor the
// world's edits the grid) and read as a file's grid would be: desc.rule picks the
// solid rule, desc.materials the palette (empty: defaultMaterials()). The world
// may be empty. Throws grotto::Error (input) for a grid a file could not hold
// either: unsupported type, non-uniform transform, ids outside the palette,
// voxels past the index limits, more than desc.memoryBudgetBytes.
World worldFromGrid(const openvdb::GridBase& grid, WorldDesc desc = {});

}  // namespace grotto::voxel
