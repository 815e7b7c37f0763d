#include "voxel/vox_world.h"

#include "common/file_kind.h"
#include "grotto/error.h"
#include "voxel/solid.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace grotto::voxel {

bool isVoxFile(const std::filesystem::path& path) {
    return lowerExtension(path) == ".vox";
}

namespace {

float linearFromSrgb(uint8_t byte) {
    const double c = byte / 255.0;
    return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

}  // namespace

std::vector<Material> voxMaterials(const VoxScene& scene) {
    int highest = 0;
    for (const VoxInstance& inst : scene.instances)
        for (const auto& v : scene.models[inst.model].voxels) highest = std::max(highest, int(v[3]));
    std::vector<Material> materials;
    for (int c = 1; c <= std::max(highest, 1); ++c) {
        const VoxColor& colour = scene.palette[size_t(c)];
        Material m;
        const std::string& type = scene.materials[size_t(c)].type;
        m.name = "colour " + std::to_string(c) + (type.empty() || type == "_diffuse" ? "" : " (" + type.substr(1) + ")");
        m.albedo = {linearFromSrgb(colour.r), linearFromSrgb(colour.g), linearFromSrgb(colour.b)};
        materials.push_back(m);
    }
    return materials;
}

openvdb::GridBase::Ptr voxGrid(const VoxScene& scene, const WorldDesc& desc) {
    const std::string file = desc.gridFile.string();
    // Bricks the voxels can touch at most: per instance, its voxels or the
    // bricks its model's box spans, whichever is fewer.
    double bricks = 0.0;
    for (const VoxInstance& inst : scene.instances) {
        const VoxModel& model = scene.models[inst.model];
        double box = 1.0;
        for (int a = 0; a < 3; ++a) box *= double(model.size[a] + 7) / 8 + 1;
        bricks += std::min(double(model.voxels.size()), box);
    }
    // Each brick touched holds an int32 leaf and a mask leaf too, as the grid is built.
    const double bytes = bricks * double(kBytesPerBrick + kValueLeafBytes + kMaskLeafBytes);
    if (bytes > double(memoryRoom(desc.memoryBudgetBytes)))
        throw Error(file, "the scene could fill " + overBudget(bricks, bytes, desc.memoryBudgetBytes),
                    "raise 'memory_budget_mib' in a world file naming it, or hide layers in MagicaVoxel");
    initializeOpenVdb();
    auto grid = openvdb::Int32Grid::create(0);
    // OpenVDB puts voxel centres at integer indices; voxel 0 spans [0, 1).
    auto xf = openvdb::math::Transform::createLinearTransform(1.0);
    xf->postTranslate(openvdb::Vec3d(0.5));
    grid->setTransform(xf);
    grid->setName("material");
    openvdb::Int32Grid::Accessor acc = grid->getAccessor();
    for (const VoxInstance& inst : scene.instances)
        for (const auto& v : scene.models[inst.model].voxels) {
            const glm::ivec3 p = placeVoxel(scene, inst, v);
            acc.setValueOn(openvdb::Coord(p.x, p.y, p.z), int(v[3]));
        }
    return grid;
}

}  // namespace grotto::voxel
