#pragma once
// Writes exactly the quads a renderer rasterises as a binary PLY in world units.
#include "voxel/mesh.h"

#include <filesystem>

namespace grotto::voxel {

// Atomic write; throws grotto::Error (input) when the output cannot be written.
void writePly(const Mesh& mesh, const std::filesystem::path& path);

}  // namespace grotto::voxel
