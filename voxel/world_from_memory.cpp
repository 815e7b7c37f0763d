// Worlds made in memory: from a dense array of material ids, or from a grid.
#include "grotto/error.h"
#include "common/number_text.h"
#include "voxel/solid.h"
#include "voxel/world_from_grid.h"

#include <glm/common.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

namespace grotto::voxel {
namespace {

void requirePlacement(glm::ivec3 size, const uint8_t* materials, double voxelSize, glm::dvec3 origin) {
    const std::string where = "World::fromDense";
    double voxels = 1.0;
    for (int a = 0; a < 3; ++a) {
        if (size[a] < 1 || size[a] > kMaxVoxelIndex)
            throw Error(where, std::string("size ") + std::to_string(size[a]) + " on " + "xyz"[a] + " is out of range",
                        "accepted: 1 to 2^30 voxels on every axis");
        voxels *= double(size[a]);
    }
    if (voxels > double(std::numeric_limits<ptrdiff_t>::max()))
        throw Error(where, "size " + numberText(voxels) + " voxels is more than an array in memory can hold");
    if (!materials) throw Error(where, "has no material array", "pass size.x * size.y * size.z material ids");
    if (!(voxelSize >= kMinVoxelSize && voxelSize <= kMaxVoxelSize))
        throw Error(where, "voxel size " + numberText(voxelSize) + " is out of range",
                    "accepted: " + numberText(kMinVoxelSize) + " to " + numberText(kMaxVoxelSize) + " world units");
    for (int a = 0; a < 3; ++a)
        if (!(std::abs(origin[a]) <= kMaxWorldOffset))
            throw Error(where, std::string("origin ") + numberText(origin[a]) + " on " + "xyz"[a] + " is out of range",
                        "accepted: within +-" + numberText(kMaxWorldOffset) + " world units");
}

WorldDesc withPalette(WorldDesc desc) {
    if (desc.materials.empty()) desc.materials = defaultMaterials();
    return desc;
}

}  // namespace

World World::fromDense(glm::ivec3 size, const uint8_t* materials, double voxelSize, glm::dvec3 origin, WorldDesc desc) {
    requirePlacement(size, materials, voxelSize, origin);
    desc = withPalette(std::move(desc));
    desc.rule = SolidRule::Int32;
    const int palette = int(desc.materials.size());
    initializeOpenVdb();
    auto grid = openvdb::Int32Grid::create(0);
    // OpenVDB puts voxel centres at integer indices; our voxel 0 spans [origin, origin + voxelSize).
    auto xf = openvdb::math::Transform::createLinearTransform(voxelSize);
    xf->postTranslate(openvdb::Vec3d(origin.x, origin.y, origin.z) + 0.5 * voxelSize);
    grid->setTransform(xf);
    grid->setName("material");
    openvdb::Int32Grid::Accessor acc = grid->getAccessor();
    const uint8_t* id = materials;
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x, ++id) {
                if (*id == 0) continue;
                if (*id > palette)
                    throw Error("World::fromDense", "material id " + std::to_string(*id) + " at index (" + std::to_string(x) +
                                                        ", " + std::to_string(y) + ", " + std::to_string(z) +
                                                        ") is not in the palette",
                                "accepted: 0 (empty) or 1.." + std::to_string(palette));
                acc.setValueOn(openvdb::Coord(x, y, z), *id);
            }
    return makeWorld(grid, std::move(desc));
}

World worldFromGrid(const openvdb::GridBase& grid, WorldDesc desc) {
    return makeWorld(grid.deepCopyGrid(), withPalette(std::move(desc)));
}

}  // namespace grotto::voxel
