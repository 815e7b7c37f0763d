#pragma once
// Reads a camera path's "edits" track (docs/paths.md). Internal to voxel/: it
// reads through the strict JSON reader.
#include "voxel/camera_path_desc.h"
#include "voxel/json_reader.h"

#include <vector>

namespace grotto::voxel {

// The edits array at `key` of a path object; `field` names the path in errors.
std::vector<TimedEdit> parseEditTrack(Reader& path, const std::string& key, const std::string& field);

}  // namespace grotto::voxel
