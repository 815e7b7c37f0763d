#include "voxel/object_worlds.h"

#include "common/error.h"
#include "voxel/generators.h"
#include "voxel/solid.h"

namespace grotto::voxel {
namespace {

// A solid box of `size` voxels from index 0, every voxel `material` (an int32 grid).
openvdb::GridBase::Ptr boxGrid(glm::ivec3 size, int material, double voxelSize) {
    auto grid = openvdb::Int32Grid::create(0);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxelSize));
    grid->tree().denseFill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(size.x - 1, size.y - 1, size.z - 1)),
                           material, true);
    grid->setName("material");
    return grid;
}

World loadObject(const WorldDesc& world, const ObjectDesc& o, const std::string& field) {
    WorldDesc d;
    d.source = o.gridFile.empty() ? world.source : o.gridFile;
    d.gridFile = o.gridFile;
    d.gridName = o.gridName;
    d.rule = o.rule;
    d.threshold = o.threshold;
    d.material = o.material;
    d.materials = world.materials;
    d.lighting = world.lighting;
    d.memoryBudgetBytes = world.memoryBudgetBytes;
    openvdb::GridBase::Ptr grid;
    if (!o.gridFile.empty()) {
        grid = loadGrid(d);
    } else {
        try {
            grid = o.generator == "box" ? boxGrid(o.boxSize, o.material, o.generatorOptions.voxelSize)
                                        : generateWorld(o.generator, o.generatorOptions);
        } catch (const Error& e) {  // name the world file and the object, not mkworld's flags
            throw Error(world.source.string(), "field '" + field + ".generator': " + e.problem(), e.hint());
        }
    }
    World w = makeWorld(grid, std::move(d));
    if (w.bounds().empty())
        throw Error(world.source.string(), "field '" + field + "': object '" + o.name + "' has no solid voxels",
                    "check its grid, rule and threshold");
    return w;
}

}  // namespace

std::vector<World> loadObjectWorlds(const WorldDesc& desc) {
    std::vector<World> out;
    out.reserve(desc.objects.size());
    for (size_t i = 0; i < desc.objects.size(); ++i)
        out.push_back(loadObject(desc, desc.objects[i], "objects[" + std::to_string(i) + "]"));
    return out;
}

}  // namespace grotto::voxel
