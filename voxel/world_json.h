#pragma once
// A WorldDesc written as the world file (docs/worlds.md) that loadWorldDesc reads
// back as the same description: grid block, palette, lighting, AO, detail,
// cameras, paths (inline, with their edits) and objects. World::save writes it
// beside the saved .vdb; the viewer writes the paths it records.
#include "voxel/json_reader.h"
#include "voxel/world_desc.h"

#include <filesystem>

namespace grotto::voxel {

// Files the description names (its grid, objects' grids, meshes) are written
// relative to `dir`, the directory the world file goes to, where they can be.
json worldFileJson(const WorldDesc& desc, const std::filesystem::path& dir);

// A camera path as a path file (or a world file's "paths" entry) reads it back.
json cameraPathJson(const CameraPathDesc& path);

}  // namespace grotto::voxel
