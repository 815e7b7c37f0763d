#pragma once
// Edits on a live world (the types are public: grotto/edit.h). World::apply runs
// them on the OpenVDB grid (the one source of truth) and returns what changed, so everything
// downstream (meshes, GPU buffers, the reference's bricks, temporal history)
// redoes only that box. OpenVDB-free: paths and the engine API carry these.
#include "grotto/edit.h"

#include <string>

namespace grotto::voxel {

using grotto::Edit;
using grotto::EditResult;
using grotto::IndexBox;
using grotto::WorldBox;

// One line naming the edit, for logs and errors ("carve sphere at (1, 2, 3) r 4").
std::string describe(const Edit& edit);

}  // namespace grotto::voxel
