#pragma once
// What a panel change or a script's "set" does to the viewer's settings, without
// a window: the patch of world-file keys checked as a world file's blocks are
// (voxel::applySettingsPatch), then the AO it resolves to. The viewer applies
// the result to its renderer; tests call it directly.
#include "engine/ao_settings.h"
#include "voxel/world_desc.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace grotto::viewer {

// `desc` with `patch` applied and the AO in effect after it; `desc` is left as it
// was when anything is refused. Throws grotto::Error (input) naming `file` and `field`.
AoOptions applyViewerPatch(voxel::WorldDesc& desc, const nlohmann::ordered_json& patch, double voxelSize,
                           const std::filesystem::path& file, const std::string& field);

}  // namespace grotto::viewer
