#include "voxel/vox_world.h"

#include "common/file_kind.h"
#include "grotto/error.h"
#include "voxel/solid.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace grotto::voxel {

bool isVoxFile(const std::filesystem::path& path) {
    return lowerExtension(path) == ".vox";
}

namespace {

struct BrickKeyHash {
    size_t operator()(glm::ivec3 b) const {
        return size_t(uint32_t(b.x)) * 0x9E3779B97F4A7C15ull ^ size_t(uint32_t(b.y)) * 0xC2B2AE3D27D4EB4Full ^
               size_t(uint32_t(b.z)) * 0x165667B19E3779F9ull;
    }
};

float linearFromSrgb(uint8_t byte) {
    const double c = byte / 255.0;
    return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

// MagicaVoxel's emitters glow in their palette colour. It publishes no scale for
// its sliders, so ours: radiance = colour x _emit x 2^_flux (Power 0 to 4: 1x to
// 16x). _ldr tints only MagicaVoxel's own image of the glow and lights nothing,
// so it is not read.
void setVoxEmission(const VoxMaterial& vox, Material& m) {
    if (vox.type != "_emit" || !(vox.emit > 0.0f)) return;
    const double flux = std::clamp(double(vox.flux), 0.0, 16.0);
    m.emissionColor = m.albedo;
    m.emissionIntensity = float(std::min(double(vox.emit) * std::exp2(flux), kMaxEmissionIntensity));
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
        setVoxEmission(scene.materials[size_t(c)], m);
        materials.push_back(m);
    }
    return materials;
}

openvdb::GridBase::Ptr voxGrid(const VoxScene& scene, const WorldDesc& desc) {
    const std::string file = desc.gridFile.string();
    // The bricks the placed voxels touch, each once (a model's voxels mostly
    // come brick by brick: the last one is not looked up again).
    std::unordered_set<glm::ivec3, BrickKeyHash> touched;
    glm::ivec3 last(std::numeric_limits<int>::min());
    for (const VoxInstance& inst : scene.instances)
        for (const auto& v : scene.models[inst.model].voxels)
            if (const glm::ivec3 brick = placeVoxel(scene, inst, v) >> 3; brick != last) touched.insert(last = brick);
    const double bricks = double(touched.size());
    // Each brick becomes an int32 leaf and a mask leaf, beside the voxels as parsed
    // (the whole work, its mesh included, is estimated once the grid is built).
    double voxels = 0.0;
    for (const VoxModel& model : scene.models) voxels += double(model.voxels.size());
    const double bytes = bricks * double(kValueLeafBytes + kMaskLeafBytes) + voxels * 4.0;  // x, y, z, colour
    if (bytes > double(memoryRoom(desc.memoryBudgetBytes)))
        throw Error(file, "the scene fills " + overBudget(bricks, bytes, desc.memoryBudgetBytes),
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
