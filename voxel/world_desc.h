#pragma once
// What a world file says, as plain data: which grid, how it becomes solid, the
// material palette, the light and the named cameras. OpenVDB-free.
#include "grotto/settings.h"
#include "voxel/camera_path_desc.h"
#include "voxel/object_desc.h"

#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace grotto::voxel {

// How grid values become solid voxels; chosen from the grid class/type by default.
enum class SolidRule {
    Auto,      // from the grid: level set, fog volume, bool/mask or int32
    LevelSet,  // solid where value < 0, interior tiles included
    Fog,       // solid where density >= threshold
    Mask,      // solid where active (bool and mask grids)
    Int32,     // solid where active and value != 0; the value is the material id
};
const char* solidRuleName(SolidRule rule);

using grotto::AmbientSource;
using grotto::AoDesc;
using grotto::CameraDesc;
using grotto::Lighting;
using grotto::Material;
using grotto::SunSource;
using grotto::ToneMap;

// How much of the world the G-buffer draws: levels of detail and occlusion culling.
struct Detail {
    // The largest size, in pixels, a coarse cell (2, 4 or 8 voxels as one) may
    // project to where far chunks are drawn coarser; 0 = the exact voxels everywhere.
    double lodBias = 1.0;
    bool occlusionCulling = true;  // skip chunk clusters hidden behind nearer geometry
};

struct WorldDesc {
    std::filesystem::path source;      // the .json or .vdb the user named
    std::filesystem::path gridFile;    // resolved .vdb path
    std::string gridName;              // empty = the file's first grid
    SolidRule rule = SolidRule::Auto;
    double threshold = 0.5;            // fog volumes only
    int material = 1;                  // material id of every voxel for non-int32 grids
    std::vector<Material> materials;   // id k uses materials[k - 1]
    Lighting lighting;
    AoDesc ao;
    Detail detail;
    std::map<std::string, CameraDesc> cameras;
    std::string defaultCamera;         // empty = framed from the world's bounds
    std::map<std::string, CameraPathDesc> paths;  // inline or read from files beside the world
    std::vector<ObjectDesc> objects;   // voxel models placed with a transform over time
    size_t memoryBudgetBytes = size_t(8) << 30;  // grids estimated above this are refused
};

// Changes a loaded world's lighting, AO and detail: `patch` holds "lighting", "ao"
// and "detail" blocks as a world file writes them (each optional; keys left out keep their
// values), checked as a world file is, errors naming `file` and `field`. The
// viewer's panel and scripts change settings through it.
// A patch that names "ao.quality" replaces the preset's slices, steps and rays,
// as --quality does.
void applySettingsPatch(WorldDesc& desc, const nlohmann::ordered_json& patch, const std::filesystem::path& file,
                        const std::string& field);

// One setting, by its dotted key ("lighting.sun.angle", as viewer scripts name
// it), as the patch applySettingsPatch takes: {"lighting": {"sun": {"angle": v}}}.
nlohmann::ordered_json settingPatch(const std::string& key, const nlohmann::json& value);

// Reads a world .json, or describes a bare .vdb with defaults. Throws grotto::Error
// (input) naming the file and field for anything malformed or unknown.
WorldDesc loadWorldDesc(const std::filesystem::path& path);

// The palette used when a world names none: stone, grass, wood, brick, ...
std::vector<Material> defaultMaterials();
// A material's emission intensity at most: radiance in the sun's and sky's scale
// (the default sun lights a face turned to it as a surface glowing at 1 would),
// far past any lamp and still in a float's range after any sum of them.
inline constexpr double kMaxEmissionIntensity = 1e5;

}  // namespace grotto::voxel
