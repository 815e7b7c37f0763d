#include "app/viewer/settings_patch.h"

namespace grotto::viewer {

AoOptions applyViewerPatch(voxel::WorldDesc& desc, const nlohmann::ordered_json& patch, double voxelSize,
                           const std::filesystem::path& file, const std::string& field) {
    voxel::WorldDesc d = desc;
    voxel::applySettingsPatch(d, patch, file, field);
    AoOptions ao = aoOptionsFor(d.ao, voxelSize, file.string());
    desc = std::move(d);
    return ao;
}

}  // namespace grotto::viewer
